"""The AUTO plugin (models/mlg.c) at the edge of the model's domain, compiled
into a small harness (no AUTO run): a step that leaves the domain gets a
huge residual, so that AUTO's Newton iteration fails and the step is halved,
and a non-finite solution (where that iteration overflowed instead, which
AUTO's convergence test passes) stops the run at once with one line naming
where; the drivers read that line as a run that did not converge
(runerror.RunError.kind), which the retry ladder retries.

Run: /usr/bin/python3 -m pytest -q tests/model/test_plugin_domain.py
"""
import os
import subprocess

import pytest

from mlgshimmy.shared import autosession, paths, runerror

HARNESS = r"""
#include "mlg.c"
static double getp_value;
doublereal getp(const char *code, integer ic, const doublereal *u) { return getp_value; }
int main(void)
{
    doublereal u[MLG_NX], f[MLG_NX], dfdu[MLG_NX * MLG_NX], dfdp[MLG_NX * MLG_NPAR];
    doublereal par[36] = {0};
    integer icp[1] = {1};
    stpnt(MLG_NX, 0.0, u, par);
    func(MLG_NX, u, icp, par, 2, f, dfdu, dfdp);       /* the start: inside the domain */
    par[MLG_PAR_V] = -0.4;                               /* a step to V < 0 */
    func(MLG_NX, u, icp, par, 2, f, dfdu, dfdp);
    for (int i = 0; i < MLG_NX; i++) printf("f %.17g\n", f[i]);
    fflush(stdout);
    getp_value = NAN;                                    /* AUTO accepted a NaN solution */
    pvls(MLG_NX, u, par);
    printf("pvls returned\n");
    return 0;
}
"""


@pytest.fixture(scope="module")
def harness(tmp_path_factory):
    """(exit status, stdout lines, stderr) of the harness."""
    where = tmp_path_factory.mktemp("plugin")
    source = where / "harness.c"
    source.write_text(HARNESS)
    exe = str(where / "harness")
    subprocess.run(["gcc", "-I", os.path.join(autosession.auto_dir(), "include"),
                    "-I", os.path.join(paths.ROOT, "c"), "-I", os.path.join(paths.ROOT, "models"),
                    str(source), os.path.join(paths.BUILD, "lib", "libmlg.a"), "-lm", "-o", exe],
                   check=True)
    done = subprocess.run([exe], capture_output=True, text=True)
    return done.returncode, done.stdout.splitlines(), done.stderr


def test_a_step_outside_the_domain_gets_a_huge_residual(harness):
    _, lines, _ = harness
    f = [float(line.split()[1]) for line in lines if line.startswith("f ")]
    assert len(f) > 0 and all(value == 1e30 for value in f)


def test_a_non_finite_solution_stops_the_run_naming_where(harness, tmp_path):
    status, lines, stderr = harness
    assert status == 3 and "pvls returned" not in lines
    line, = stderr.splitlines()
    assert line.startswith(runerror.NON_FINITE_LINE) and "V = -0.4 m/s, F* = 1" in line
    log = tmp_path / "run.log"
    log.write_text("Starting mlg ...\n" + stderr)
    assert runerror.non_finite_stop(str(log)) == line
