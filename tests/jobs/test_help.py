"""make help (mk/help.mk), also plain make: every figure target of the
makefiles is listed, every listed target exists, and each line has a
typical time.

Run: /usr/bin/python3 -m pytest -q tests/jobs/test_help.py
"""
import os
import pathlib
import re
import subprocess

import helpers

ROOT = pathlib.Path(helpers.ROOT)


def make(*args):
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES")}
    proc = subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return proc.stdout


def variable(name):
    """A variable of the makefiles as make sees it."""
    out = make(f"--eval=print-var-{name}: ; @echo '$({name})'", f"print-var-{name}")
    return out.strip().splitlines()[-1].split()


def listed():
    """(target, time, description) of each target line of make help."""
    rows = []
    for line in make("help").splitlines():
        m = re.match(r"^  (\S.*?)\s{2,}(\S.*?)?\s{2,}(\S.*)$", line) or \
            re.match(r"^  (\S+(?: \S+=\S+)*)\s+(\d.*? (?:s|min))\s+(.*)$", line)
        if m:
            rows.append((m.group(1).strip(), (m.group(2) or "").strip(), m.group(3)))
    return rows


def header_version():
    text = (ROOT / "c" / "mlg_version.h").read_text()
    return ".".join(re.search(rf"^#define MLG_VERSION_{p} +(\d+)", text, re.M).group(1)
                    for p in ("MAJOR", "MINOR", "PATCH"))


def test_plain_make_prints_help():
    out = make()
    assert out == make("help")
    assert out.startswith(f"mlg-shimmy {header_version()}: ")
    assert "test" in out and "figures" in out


def test_every_figure_is_listed_with_a_time():
    rows = {target.split()[0]: time for target, time, _ in listed() if target}
    figures = variable("FIGURES")
    assert len(figures) >= 16, figures
    for fig in figures:
        assert fig in rows, f"{fig} (FIGURES) is not in make help"
        assert re.match(r"^(\+ |> )?\d+(\.\d+)? (s|min)$", rows[fig]), (fig, rows[fig])


def test_every_line_has_a_typical_time():
    for target, time, _ in listed():
        if not target.startswith("refs"):
            assert re.match(r"^(\+ |> )?\d+(\.\d+)? (s|min)$", time), (target, time)


def test_every_listed_target_exists():
    database = make("-p", "-n", "help")
    targets = set(re.findall(r"^([^\s#%:=][^\s:=]*):(?!=)", database, re.M))
    names = []
    for target, _, _ in listed():
        for name in re.split(r",\s*", target):
            name = name.split()[0] if name else name
            if name and "<" not in name:
                names.append(name)
    assert len(names) >= 40, names
    missing = [n for n in names if n not in targets]
    assert not missing, f"make help lists targets that do not exist: {missing}"
    # the pattern rules behind regress-<fig> and refs-<fig>
    assert re.search(r"^regress-%:", database, re.M) and re.search(r"^refs-%:", database, re.M)


def test_every_submit_target_is_listed():
    """make submit-fig10 said "No rule to make target" and help listed no
    submit target; every one is listed now (submit-<fig> for the figures)."""
    names = {name for target, _, _ in listed() for name in re.split(r",\s*", target)}
    figures = set(variable("FIGURES"))
    submit = variable("SUBMIT_TARGETS")
    assert {"submit-fig10", "submit-fig11", "submit-sweep", "submit-robustness"} <= set(submit)
    assert "submit-<fig>" in names
    unlisted = [t for t in submit if t not in names and t[len("submit-"):] not in figures]
    assert not unlisted, f"make help does not list {unlisted}"
