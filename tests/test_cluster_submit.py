"""The submit tool (drivers/mlgshimmy/shared/jobs/submit.py) without a scheduler: the
submission directory and its job files, the lines made self-sufficient, the sbatch
commands of a staged pipeline (--dry-run), stages from a command, and its refusals."""
import json
import os
import re
import stat
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WRAPPER = os.path.join(ROOT, "mk", "cluster", "array-task.sh")


def submit(args, cwd, env=None, stdin=None):
    environment = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "drivers"))
    for variable in ("AUTO_DIR", "MLG_RUN_ROOT", "MLG_AUTO_THREADS"):
        environment.pop(variable, None)
    environment.update(env or {})
    return subprocess.run([sys.executable, "-m", "mlgshimmy.shared.jobs.submit"]
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
    script = tmp_path / "jobs.sh"   # like `fig11.py jobs --stage K`: empty past the last
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
