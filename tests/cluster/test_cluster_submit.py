"""The submit tool (drivers/mlgshimmy/shared/cluster/) without a scheduler: the
submission directory and its job files, the lines made self-sufficient, the sbatch
commands of a staged pipeline (--dry-run), stages from a command, and its refusals."""
import json
import os
import re
import shutil
import stat
import subprocess
import sys

import pytest

import helpers

ROOT = helpers.ROOT
WRAPPER = os.path.join(ROOT, "mk", "cluster", "array-task.sh")


def submit(args, cwd, env=None, stdin=None):
    environment = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "drivers"))
    for variable in ("AUTO_DIR", "MLG_RUN_ROOT", "MLG_AUTO_THREADS"):
        environment.pop(variable, None)
    environment.update(env or {})
    return subprocess.run([sys.executable, "-m", "mlgshimmy.shared.cluster"]
                          + [str(a) for a in args], cwd=cwd, env=environment, input=stdin,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=60)


def submission(result):
    match = re.search(r"^submission: (\S+)$", result.stdout, re.M)
    assert match, result.stdout + result.stderr
    return match.group(1)


def stage_files(tmp_path):
    one = tmp_path / "one.txt"
    one.write_text("echo a\n\n# a comment\ncd /tmp && echo b\n"
                   "AUTO_DIR=/opt/auto MLG_RUN_ROOT=/r echo c\n")
    two = tmp_path / "two.txt"
    two.write_text("echo d\n")
    return one, two


def test_dry_run_writes_the_job_files_and_prints_the_pipeline(tmp_path):
    one, two = stage_files(tmp_path)
    out = tmp_path / "out"
    result = submit(["submit", "--name", "demo", "--scheduler", "slurm", "--stage", one,
                     "--stage", two, "--assemble", "make fig11", "--per-task", 2,
                     "--throttle", 3, "--out", out, "--assemble-opt=--mem=2G",
                     "--dry-run", "--env", "AUTO_DIR=auto07p",
                     "--", "--partition=short", "--time=0:10:00"],
                    cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    directory = submission(result)
    assert os.path.dirname(directory) == str(out / "submit")
    assert re.fullmatch(r"demo-\d{8}-\d{6}-[0-9a-f]{6}", os.path.basename(directory))
    commands = [line for line in result.stdout.splitlines() if line.startswith("sbatch ")]
    assert len(commands) == 3
    s1, s2, assemble = commands
    assert "-J demo-s1 --array=1-2%3 -o " + str(out / "logs") + "/%x_%A_%a.out" in s1
    assert "dependency" not in s1
    assert "-J demo-s2 --array=1%3" in s2
    assert "'--dependency=afterok:<stage1>' --kill-on-invalid-dep=yes" in s2
    assert "-J demo-assemble -o " + str(out / "logs") + "/%x_%j.out" in assemble
    assert "'--dependency=afterok:<stage2>' --kill-on-invalid-dep=yes" in assemble
    for command in commands:
        assert command.startswith("sbatch --parsable ")
    for command in (s1, s2):
        assert "--partition=short --time=0:10:00 " + WRAPPER in command
    # the assembly's own options come after the common ones (the last one wins)
    assert "--partition=short --time=0:10:00 --mem=2G " + WRAPPER in assemble
    assert "--mem=2G" not in s1
    assert f"-n 3 -k 2 -m {directory}/marks/stage1 {directory}/stage1.txt" in s1
    assert f"{directory}/assemble.txt 1" in assemble

    lines = (out / "submit" / os.path.basename(directory) / "stage1.txt").read_text()
    lines = lines.splitlines()
    auto = os.path.join(str(tmp_path), "auto07p")   # made absolute, from the cwd
    build = os.path.join(ROOT, "build")
    assert lines[0] == (f"export AUTO_DIR={auto} MLG_RUN_ROOT={build} MLG_AUTO_THREADS=1 "
                        f"MPLBACKEND=Agg SOURCE_DATE_EPOCH=0; cd {tmp_path} || exit 1; echo a")
    # an absolute cd is kept; variables a line sets itself are not prefixed
    assert lines[1].endswith("; cd /tmp && echo b") and "|| exit 1" not in lines[1]
    assert lines[2] == (f"export MLG_AUTO_THREADS=1 MPLBACKEND=Agg SOURCE_DATE_EPOCH=0; "
                        f"cd {tmp_path} || exit 1; AUTO_DIR=/opt/auto MLG_RUN_ROOT=/r echo c")
    assert len(lines) == 3   # the blank line and the comment are not jobs
    assert open(os.path.join(directory, "assemble.txt")).read().endswith(
        f"cd {tmp_path} || exit 1; make fig11\n")
    for name in ("stage1.txt", "stage2.txt", "assemble.txt"):   # never rewritten
        mode = os.stat(os.path.join(directory, name)).st_mode
        assert not mode & (stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH)
    manifest = json.load(open(os.path.join(directory, "manifest.json")))
    assert [s["lines"] for s in manifest["stages"]] == [3, 1]
    assert [s["tasks"] for s in manifest["stages"]] == [2, 1]
    assert manifest["options"] == ["--partition=short", "--time=0:10:00"]
    assert manifest["attempts"] == []   # a dry run submits nothing


def test_every_submission_gets_a_new_directory(tmp_path):
    one, _ = stage_files(tmp_path)
    args = ["submit", "--name", "x", "--scheduler", "slurm", "--stage", one,
            "--out", tmp_path / "out", "--dry-run"]
    first = submission(submit(args, cwd=tmp_path))
    second = submission(submit(args, cwd=tmp_path))
    assert first != second
    assert open(os.path.join(first, "stage1.txt")).read() == \
        open(os.path.join(second, "stage1.txt")).read()


def test_the_environment_of_the_submitting_shell_is_carried(tmp_path):
    one, _ = stage_files(tmp_path)
    result = submit(["submit", "--name", "x", "--scheduler", "slurm", "--stage", one,
                     "--out", tmp_path / "out", "--dry-run", "--carry", "EXTRA_SETTING"],
                    cwd=tmp_path, env={"MLG_RUN_ROOT": "runs", "MLG_AUTO_THREADS": "2",
                                       "EXTRA_SETTING": "a b"})
    assert result.returncode == 0, result.stderr
    first = open(os.path.join(submission(result), "stage1.txt")).readline()
    assert f"MLG_RUN_ROOT={tmp_path}/runs MLG_AUTO_THREADS=2 " in first
    assert "EXTRA_SETTING='a b'; " in first


def test_stages_from_a_command(tmp_path):
    script = tmp_path / "jobs.sh"   # like `mlgshimmy.figures.fig11 jobs --stage K`: empty past the last
    script.write_text('case $1 in 1) echo "echo a"; echo "echo b";; 2) echo "echo c";; esac\n')
    result = submit(["submit", "--name", "f", "--scheduler", "slurm", "--stages-from",
                     f"bash {script} {{k}}", "--out", tmp_path / "out", "--dry-run"],
                    cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    directory = submission(result)
    manifest = json.load(open(os.path.join(directory, "manifest.json")))
    assert [s["lines"] for s in manifest["stages"]] == [2, 1]
    assert not os.path.exists(os.path.join(directory, "stage3.txt"))
    # a stated number of stages must all have jobs
    result = submit(["submit", "--name", "f", "--scheduler", "slurm", "--stages-from",
                     f"bash {script} {{k}}", "--stages", 3, "--out", tmp_path / "out",
                     "--dry-run"], cwd=tmp_path)
    assert result.returncode != 0 and "stage 3 of --stages 3 has no job" in result.stderr
    # from standard input
    result = submit(["submit", "--name", "s", "--scheduler", "slurm", "--stage", "-",
                     "--out", tmp_path / "out", "--dry-run"], cwd=tmp_path,
                    stdin="echo x\necho y\n")
    assert result.returncode == 0, result.stderr
    assert "--array=1-2 " in result.stdout


def test_refusals(tmp_path):
    one, _ = stage_files(tmp_path)
    empty = tmp_path / "empty.txt"
    empty.write_text("\n")
    base = ["submit", "--scheduler", "slurm", "--out", tmp_path / "out", "--dry-run"]
    cases = [
        (["--name", "a b", "--stage", one], "--name"),
        (["--name", "a", "--stage", empty], "no command"),
        (["--name", "a", "--stage", tmp_path / "none.txt"], "none.txt"),
        (["--name", "a"], "no jobs"),
        (["--name", "a", "--stages-from", "echo true"], "{k}"),
        (["--name", "a", "--stages-from", "exit 4 {k}"], "exit 4"),
        (["--name", "a", "--stage", one, "--per-task", 0], "--per-task"),
        (["--name", "a", "--stage", one, "--env", "MLG_AUTO_THREADS=0"], "MLG_AUTO_THREADS"),
        (["--name", "a", "--stage", one, "--carry", "NOT_SET_ANYWHERE"], "NOT_SET_ANYWHERE"),
    ]
    for extra, message in cases:
        result = submit(base + extra, cwd=tmp_path)
        assert result.returncode == 2, (extra, result.stdout, result.stderr)
        assert message in result.stderr, (extra, result.stderr)
    result = submit(["submit", "--name", "a", "--scheduler", "parallel", "--stage", one,
                     "--per-task", 2, "--out", tmp_path / "out"], cwd=tmp_path)
    assert result.returncode == 2 and "--per-task" in result.stderr
    result = submit(["status", tmp_path], cwd=tmp_path)
    assert result.returncode == 2 and "not a submission directory" in result.stderr


def test_allow_empty_skips_stages_with_nothing_left(tmp_path):
    """`jobs --missing` lists: a stage left empty submits nothing (the next does not
    depend on it); no line at all: only the assembly, or nothing."""
    script = tmp_path / "jobs.sh"   # stage 1 done already, stage 2 has one line left
    script.write_text('case $1 in 1) ;; 2) echo "echo c";; *) exit 1;; esac\n')
    base = ["submit", "--name", "f", "--scheduler", "slurm", "--out", tmp_path / "out",
            "--dry-run", "--stages-from", f"bash {script} {{k}}", "--stages", 2]
    refused = submit(base, cwd=tmp_path)
    assert refused.returncode == 2 and "stage 1 of --stages 2 has no job" in refused.stderr
    assert "--allow-empty" in refused.stderr
    result = submit(base + ["--allow-empty", "--assemble", "make fig11"], cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "stage 1: no line (nothing left to do there), skipped" in result.stderr
    commands = [line for line in result.stdout.splitlines() if line.startswith("sbatch ")]
    assert len(commands) == 2 and "-J f-s2 --array=1 " in commands[0], commands
    assert "dependency" not in commands[0] and "afterok:<stage2>" in commands[1]
    manifest = json.load(open(os.path.join(submission(result), "manifest.json")))
    assert [s["lines"] for s in manifest["stages"]] == [0, 1]
    # without --stages an empty stage ends the list, so --allow-empty needs it
    result = submit(base[:-2] + ["--allow-empty"], cwd=tmp_path)
    assert result.returncode == 2 and "needs --stages N" in result.stderr, result.stderr

    empty = tmp_path / "empty.txt"
    empty.write_text("")
    only = submit(["submit", "--name", "g", "--scheduler", "slurm", "--out", tmp_path / "out",
                   "--dry-run", "--stage", empty, "--allow-empty", "--assemble", "echo done"],
                  cwd=tmp_path)
    assert only.returncode == 0, only.stderr
    assert "only the assembly is submitted" in only.stderr
    commands = [line for line in only.stdout.splitlines() if line.startswith("sbatch ")]
    assert len(commands) == 1 and "-J g-assemble" in commands[0] \
        and "dependency" not in commands[0], commands
    nothing = submit(["submit", "--name", "h", "--scheduler", "slurm", "--out",
                      tmp_path / "out", "--dry-run", "--stage", empty, "--allow-empty"],
                     cwd=tmp_path)
    assert nothing.returncode == 0 and "nothing to submit" in nothing.stderr
    assert "submission:" not in nothing.stdout
    assert not [d for d in os.listdir(tmp_path / "out" / "submit") if d.startswith("h-")]


def test_the_cpu_guard_scale_is_carried_where_it_is_set(tmp_path):
    one, _ = stage_files(tmp_path)
    args = ["submit", "--name", "x", "--scheduler", "slurm", "--stage", one,
            "--out", tmp_path / "out", "--dry-run"]
    unset = submit(args, cwd=tmp_path, env={"MLG_CPU_GUARD_SCALE": ""})
    first = open(os.path.join(submission(unset), "stage1.txt")).readline()
    assert unset.returncode == 0 and "MLG_CPU_GUARD_SCALE" not in first, first
    scaled = submit(args, cwd=tmp_path, env={"MLG_CPU_GUARD_SCALE": "2"})
    first = open(os.path.join(submission(scaled), "stage1.txt")).readline()
    assert " MLG_CPU_GUARD_SCALE=2; " in first, first


def make_dry_run(*args):
    environment = {k: v for k, v in os.environ.items()
                   if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    return subprocess.run(["make", "-n", *args], cwd=ROOT, env=environment,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=120)


def test_the_submit_targets_run_the_package_with_every_value_quoted():
    sweep = make_dry_run("submit-sweep", "SWEEP_RHO=0,10", "SWEEP_MU=0",
                         "SUBMIT_ARGS=--per-task 2", "SUBMIT_OPTIONS=--time=0:05:00 --mem=1G")
    assert sweep.returncode == 0, sweep.stderr
    text = sweep.stdout
    assert "-m mlgshimmy.studies.sweep check --rho='0,10' --mu='0'" in text, text
    assert "-m mlgshimmy.studies.sweep jobs --missing --rho='0,10' --mu='0' | " in text
    assert "--allow-empty '--per-task' '2'" in text
    assert "-- '--time=0:05:00' '--mem=1G'" in text
    assert ("--assemble 'PYTHONPATH='\\''" + ROOT + "/drivers'\\'' ") in text, text
    assert "drivers/sweep.py" not in text and "drivers/atlas.py" not in text
    every = make_dry_run("submit-sweep", "SWEEP_RHO=0,10", "SWEEP_MU=0", "SUBMIT_ALL=1")
    assert every.returncode == 0 and "--missing" not in every.stdout \
        and "--allow-empty" not in every.stdout
    atlas = make_dry_run("submit-atlas", "ATLAS_V=100,300", "ATLAS_FSTAR=1")
    assert "-m mlgshimmy.studies.atlas jobs --missing --V='100,300' --Fstar='1' | " \
        in atlas.stdout, atlas.stdout + atlas.stderr
    design = make_dry_run("submit-design-map", "DESIGN_RHO=-20:20:2", "DESIGN_MU=-20:20:2")
    assert "-m mlgshimmy.studies.design_map jobs --missing --rho='-20:20:2' --mu='-20:20:2' | " \
        in design.stdout and "--name design_map --stage -" in design.stdout, \
        design.stdout + design.stderr
    figure = make_dry_run("submit-fig11", "AUTO_THREADS=2")
    assert "set -e; stages=$(/" in figure.stdout and "-m mlgshimmy.figures.fig11 stages)" \
        in figure.stdout, figure.stdout
    assert "--stages \"$stages\"" in figure.stdout
    assert "--stages-from '" in figure.stdout and \
        "-m mlgshimmy.figures.fig11 jobs --stage {k} --missing'" in figure.stdout
    assert "--assemble 'make --no-print-directory AUTO_THREADS=2 fig11'" in figure.stdout
    bad = make_dry_run("submit-fig11", "SCHEDULER=pbs")
    assert bad.returncode != 0 and "SCHEDULER=pbs must be slurm or parallel" in bad.stderr
    # a bad SCHEDULER in the environment does not stop other targets
    assert make_dry_run("help", "SCHEDULER=pbs").returncode == 0


def test_a_21_by_21_design_map_is_441_job_lines(tmp_path):
    """The cluster-sized design map: one job line per geometry, each naming its point."""
    listed = subprocess.run([sys.executable, "-m", "mlgshimmy.studies.design_map", "jobs",
                             "--rho=-20:20:2", "--mu=-20:20:2"], cwd=ROOT, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120,
                            env={**os.environ, "MLG_RUN_ROOT": str(tmp_path)})
    lines = listed.stdout.splitlines()
    assert listed.returncode == 0 and len(lines) == 441, listed.stderr
    assert len(set(lines)) == 441 and all("design_map" in line for line in lines), lines[:2]


def test_a_figure_without_parts_is_submitted_as_one_job(tmp_path):
    """make submit-fig10 said only "No rule to make target": a figure without
    parts is one job, `make <fig>`, with the gear as make read it."""
    plain = make_dry_run("submit-fig10")
    assert plain.returncode == 0, plain.stderr
    assert "set -eo pipefail; printf '%s\\n' 'make --no-print-directory AUTO_THREADS=1 fig10 ' | " \
        in plain.stdout, plain.stdout
    assert "--name fig10 --stage -" in plain.stdout
    gear = make_dry_run("submit-fig10", "SET=k_tlk=3.51e7")
    assert "fig10 RHO='\\''0'\\'' MU='\\''0'\\'' EOM='\\''0'\\'' SET='\\''k_tlk=3.51e7'\\'''" \
        in gear.stdout, gear.stdout
    other = subprocess.run(["make", "--no-print-directory", "submit-fig99"], cwd=ROOT,
                           capture_output=True, text=True, timeout=120,
                           env={k: v for k, v in os.environ.items() if k not in
                                ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")})
    assert other.returncode != 0
    assert other.stderr.startswith("submit-fig99: nothing of that name can be submitted; the "
                                   "submit targets are submit-fig11 "), other.stderr
    assert "submit-fig10" in other.stderr and "submit-sweep" in other.stderr


def test_a_figure_without_parts_runs_as_one_job_under_parallel(tmp_path):
    if shutil.which("parallel") is None:
        pytest.skip("GNU parallel is not installed (tests/cluster/test_cluster_parallel.py installs it)")
    environment = {k: v for k, v in os.environ.items()
                   if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    proc = subprocess.run(["make", "--no-print-directory", "submit-fig06", "SCHEDULER=parallel",
                           f"MLG_RUN_ROOT={tmp_path}", f"SUBMIT_ARGS=--out {tmp_path}/out"],
                          cwd=ROOT, env=environment, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    assert "stage 1: 1 COMPLETED" in proc.stdout and "everything completed" in proc.stdout
    assert (tmp_path / "figures" / "fig06.png").stat().st_size > 10000
