"""The submit tool with GNU parallel: two stages and an assembly run in order with
--joblog and --halt soon,fail=1; a failing line stops the pipeline, `status` names it
(stage, index, line, command) from the job log, and `resume` (--resume-failed) reruns
only it, then the later stages and the assembly."""
import json
import os
import shutil
import subprocess
import sys

import pytest

import helpers

ROOT = helpers.ROOT
SCRIPT = os.path.join(ROOT, "mk", "cluster", "slurm-single-node.sh")


@pytest.fixture(scope="module")
def gnu_parallel():
    if shutil.which("parallel") is None:
        # the same script installs slurm-wlm munge parallel; 77: cannot be installed
        result = subprocess.run([SCRIPT, "install"], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
        if result.returncode == 77:
            pytest.skip(f"GNU parallel is not installed and cannot be: {result.stdout.strip()}")
        assert result.returncode == 0, result.stdout
    assert shutil.which("parallel")


def tool(args, cwd):
    environment = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "drivers"))
    return subprocess.run([sys.executable, "-m", "mlgshimmy.shared.cluster"]
                          + [str(a) for a in args], cwd=cwd, env=environment,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=120)


def runs(path):
    return len(path.read_text().split()) if path.exists() else 0


def test_stages_failure_status_and_resume(tmp_path, gnu_parallel):
    out = tmp_path / "out"
    work = tmp_path / "work"
    work.mkdir()
    one = tmp_path / "one.txt"
    one.write_text("".join(f"echo x >> runs1_{n}; {body}\n" for n, body in (
        (1, "sleep 0.3; echo done > a1"),
        (2, "test -e flag || exit 4; echo done > a2"),
        (3, "sleep 0.3; echo done > a3"))))
    two = tmp_path / "two.txt"
    two.write_text("echo x >> runs2_1; cat a1 a2 a3 > b1\necho x >> runs2_2\n")
    args = ["submit", "--name", "par", "--scheduler", "parallel", "--jobs", 2,
            "--stage", one, "--stage", two, "--assemble", "echo x >> assembled",
            "--out", out]
    first = tool(args, cwd=work)
    assert first.returncode != 0, first.stdout + first.stderr
    directory = first.stdout.split("submission: ")[1].split()[0]
    assert os.path.exists(os.path.join(directory, "stage1.log"))
    assert not os.path.exists(os.path.join(directory, "stage2.log"))   # stopped there
    assert runs(work / "runs1_2") == 1 and not (work / "b1").exists()

    status = tool(["status", directory], cwd=tmp_path)
    assert status.returncode == 1, status.stdout
    assert "FAILED     stage 1, index 2, line 2, exit 4" in status.stdout
    assert "test -e flag || exit 4" in status.stdout
    assert "NOT RUN    stage 2, index 1, line 1" in status.stdout
    assert "NOT RUN    assembly" in status.stdout
    report = json.loads(tool(["status", directory, "--json"], cwd=tmp_path).stdout)
    assert [e["state"] for e in report["steps"][0]["entries"]][1] == "FAILED"

    (work / "flag").touch()
    again = tool(["resume", directory], cwd=tmp_path)
    assert again.returncode == 0, again.stdout + again.stderr
    assert "--resume-failed" in again.stderr
    assert "everything completed" in again.stdout
    assert [runs(work / f"runs1_{n}") for n in (1, 2, 3)] == [1, 2, 1]
    assert [runs(work / f"runs2_{n}") for n in (1, 2)] == [1, 1]
    assert runs(work / "assembled") == 1
    assert (work / "b1").read_text() == "done\n" * 3
    assert tool(["status", directory], cwd=tmp_path).returncode == 0
    nothing = tool(["resume", directory], cwd=tmp_path)
    assert nothing.returncode == 0 and "nothing to resume" in nothing.stdout
    assert runs(work / "assembled") == 1
