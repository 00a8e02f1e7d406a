"""mk/cluster/array-task.sh, the job-array task wrapper, run directly (no scheduler):
it runs its line(s), propagates their exit status, and fails when there is nothing to
run (list too short, a relative or unreadable job file, a bad task id, a rewritten
list)."""
import os
import subprocess

import helpers

ROOT = helpers.ROOT
WRAPPER = os.path.join(ROOT, "mk", "cluster", "array-task.sh")


def run(args, cwd, env=None):
    environment = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    environment.update(env or {})
    return subprocess.run([WRAPPER] + [str(a) for a in args], cwd=cwd, env=environment,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=60)


def job_file(tmp_path, lines):
    path = tmp_path / "jobs.txt"
    path.write_text("".join(f"{line}\n" for line in lines))
    return path


def test_runs_the_task_line_and_propagates_its_status(tmp_path):
    jobs = job_file(tmp_path, [f"echo one > {tmp_path}/1", "exit 7", "echo three"])
    ok = run([jobs, 1], cwd="/")
    assert ok.returncode == 0, ok.stderr
    assert (tmp_path / "1").read_text() == "one\n"
    failed = run([jobs, 2], cwd="/")
    assert failed.returncode == 7
    assert "line 2" in failed.stderr and "status 7" in failed.stderr
    # the id from Slurm's environment
    third = run([jobs], cwd="/", env={"SLURM_ARRAY_TASK_ID": "3"})
    assert third.returncode == 0 and third.stdout == "three\n"


def test_fails_when_the_list_is_too_short(tmp_path):
    jobs = job_file(tmp_path, ["true", "true", "true"])
    result = run([jobs, 4], cwd="/")
    assert result.returncode != 0
    assert "needs line 4" in result.stderr and "only 3 lines" in result.stderr
    # the count it was submitted with: a shortened list fails every task
    result = run(["-n", 4, jobs, 1], cwd="/")
    assert result.returncode != 0 and "not the 4" in result.stderr


def test_fails_on_a_relative_or_unreadable_job_file(tmp_path):
    job_file(tmp_path, ["true"])
    other = tmp_path / "elsewhere"
    other.mkdir()
    # readable from tmp_path, but a task may start anywhere: refused even there
    for cwd in (tmp_path, other):
        result = run(["jobs.txt", 1], cwd=cwd)
        assert result.returncode != 0
        assert "not an absolute path" in result.stderr
    result = run([tmp_path / "missing.txt", 1], cwd="/")
    assert result.returncode != 0 and "cannot read" in result.stderr


def test_fails_without_a_task_id(tmp_path):
    jobs = job_file(tmp_path, ["true"])
    for args in ([jobs], [jobs, 0], [jobs, "1;true"], [jobs, "x"]):
        result = run(args, cwd="/")
        assert result.returncode != 0, args
        assert "task id" in result.stderr
    result = run(["-k", "0", jobs, 1], cwd="/")
    assert result.returncode != 0


def test_fails_on_an_empty_line(tmp_path):
    jobs = tmp_path / "jobs.txt"
    jobs.write_text("true\n   \ntrue\n")
    result = run([jobs, 2], cwd="/")
    assert result.returncode != 0 and "empty" in result.stderr


def test_k_lines_per_task(tmp_path):
    lines = [f"echo {n} >> {tmp_path}/out" for n in range(1, 6)]
    jobs = job_file(tmp_path, lines)
    for task in (1, 2, 3):
        result = run(["-k", 2, "-n", 5, jobs, task], cwd="/")
        assert result.returncode == 0, result.stderr
    assert (tmp_path / "out").read_text().split() == ["1", "2", "3", "4", "5"]
    assert run(["-k", 2, jobs, 4], cwd="/").returncode != 0   # line 7 of 5
    # a failing line: the task's other lines still run, the task fails with its status
    jobs = job_file(tmp_path, [f"echo a >> {tmp_path}/k", "exit 5", f"echo c >> {tmp_path}/k"])
    result = run(["-k", 3, jobs, 1], cwd="/")
    assert result.returncode == 5
    assert (tmp_path / "k").read_text() == "a\nc\n"


def test_marks_and_redo_skip_the_lines_done(tmp_path):
    marks = tmp_path / "marks"
    flag = tmp_path / "flag"
    lines = [f"echo x >> {tmp_path}/first", f"test -e {flag}", f"echo x >> {tmp_path}/third"]
    jobs = job_file(tmp_path, lines)
    assert run(["-k", 3, "-m", marks, jobs, 1], cwd="/").returncode == 1
    assert [(marks / str(n)).read_text().split()[0] for n in (1, 2, 3)] == ["0", "1", "0"]
    flag.touch()
    result = run(["-k", 3, "-m", marks, "-r", jobs, 1], cwd="/")
    assert result.returncode == 0, result.stderr
    assert (marks / "2").read_text().split()[0] == "0"
    # lines 1 and 3 ran once
    assert (tmp_path / "first").read_text() == "x\n"
    assert (tmp_path / "third").read_text() == "x\n"
    assert run(["-m", "relative", jobs, 1], cwd="/").returncode != 0


def test_runs_with_an_empty_environment(tmp_path):
    """sbatch --export=NONE: no PATH, no HOME; the line carries what it needs."""
    jobs = job_file(tmp_path, [f"export X=1; cd {tmp_path} && echo $X > here"])
    result = subprocess.run(["/bin/bash", WRAPPER, str(jobs), "1"], env={}, cwd="/",
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "here").read_text() == "1\n"
