"""The cluster path on a real Slurm: a private single-node cluster started by
mk/cluster/slurm-single-node.sh for this module (its own state directory and ports) and
stopped at the end, by pid, even when a test fails.  Checks, with synthetic job lists:
two stages and a dependent assembly run in order; a failed task cancels the later stages
and the assembly (--kill-on-invalid-dep), `status` names it, and `resume` recomputes
only it; K lines per task; --export=NONE; the wrapper fails its task on a list that is
too short or a relative path; and `make submit-sweep SCHEDULER=slurm` on 2 points gives
what `make sweep` gives, and run again after a result was lost, submits only that point
(`jobs --missing`) and the summary.  Skipped only where the packages cannot be
installed."""
import json
import os
import shutil
import socket
import stat
import subprocess
import sys
import tempfile
import time

import pytest

import helpers

ROOT = helpers.ROOT
SCRIPT = os.path.join(ROOT, "mk", "cluster", "slurm-single-node.sh")
WRAPPER = os.path.join(ROOT, "mk", "cluster", "array-task.sh")
DAEMONS = (("slurmd.pid", "slurmd"), ("slurmctld.pid", "slurmctld"),
           ("munge/munged.pid", "munged"))


def free_ports(count):
    sockets = [socket.socket() for _ in range(count)]
    for s in sockets:
        s.bind(("127.0.0.1", 0))
    ports = [s.getsockname()[1] for s in sockets]
    for s in sockets:
        s.close()
    return ports


def running(pid, name):
    try:
        with open(f"/proc/{pid}/comm") as handle:
            return handle.read().strip() == name
    except OSError:
        return False


def state_directory():
    """build/test-slurm-<pid>, or a new directory under /var/tmp where a directory above
    build/ is not searchable by every user (munge's socket needs that)."""
    build = os.path.join(ROOT, "build")
    os.makedirs(build, exist_ok=True)
    path = build
    while path != os.path.dirname(path):
        if not os.stat(path).st_mode & stat.S_IXOTH:
            state = tempfile.mkdtemp(prefix="mlg-test-slurm-", dir="/var/tmp")
            os.chmod(state, 0o755)
            return state
        path = os.path.dirname(path)
    return os.path.join(build, f"test-slurm-{os.getpid()}")


@pytest.fixture(scope="module")
def slurm():
    state = state_directory()
    ctld, slurmd = free_ports(2)
    environment = dict(os.environ, SLURM_STATE_DIR=state, SLURMCTLD_PORT=str(ctld),
                       SLURMD_PORT=str(slurmd))
    started = time.monotonic()
    start = subprocess.run([SCRIPT, "start"], env=environment, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=600)
    if start.returncode == 77:
        pytest.skip("no Slurm here: slurm-wlm/munge are not installed and cannot be "
                    f"({start.stdout.strip()})")
    pids = {}
    try:
        assert start.returncode == 0, start.stdout
        for file, name in DAEMONS:
            with open(os.path.join(state, file)) as handle:
                pids[name] = int(handle.read())
            assert running(pids[name], name)
        print(f"slurm started in {time.monotonic() - started:.1f} s: {pids}")
        yield {"SLURM_CONF": os.path.join(state, "slurm.conf")}
    finally:
        stop = subprocess.run([SCRIPT, "stop"], env=environment, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=120)
        left = [f"{name} {pid}" for name, pid in pids.items() if running(pid, name)]
        if not left:
            shutil.rmtree(state, ignore_errors=True)
        assert stop.returncode == 0, stop.stdout
        assert not left, f"daemons still running after stop: {left}"


def tool(args, cwd, slurm, env=None, stdin=None):
    environment = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "drivers"), **slurm)
    environment.update(env or {})
    return subprocess.run([sys.executable, "-m", "mlgshimmy.shared.cluster"]
                          + [str(a) for a in args], cwd=cwd, env=environment, input=stdin,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=150)


def submitted(result):
    assert result.returncode == 0, result.stdout + result.stderr
    return result.stdout.split("submission: ")[1].split()[0]


def wait(directory, slurm):
    """status --wait: the exit status (0 all completed, 1 not) and the text."""
    result = tool(["status", directory, "--wait", "--timeout", 100], ROOT, slurm)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    return result.returncode, result.stdout


def marks(directory, stage):
    folder = os.path.join(directory, "marks", stage)
    return {int(n): open(os.path.join(folder, n)).read().split() for n in os.listdir(folder)
            if n.isdigit()}


def count(path):
    return len(path.read_text().split()) if path.exists() else 0


def scheduler(command, slurm):
    result = subprocess.run(command, env=dict(os.environ, **slurm), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_two_stages_and_an_assembly_run_in_order(tmp_path, slurm):
    work = tmp_path / "work"
    work.mkdir()
    one = tmp_path / "one.txt"
    one.write_text("".join(f"sleep 1; echo {n} > s1_{n}\n" for n in (1, 2, 3)))
    two = tmp_path / "two.txt"
    two.write_text("cat s1_1 s1_2 s1_3 > s2_1\ncat s1_3 > s2_2\n")
    directory = submitted(tool(
        ["submit", "--name", "order", "--scheduler", "slurm", "--stage", one, "--stage", two,
         "--assemble", "cat s2_1 s2_2 > assembled", "--out", tmp_path / "out"], work, slurm))
    code, text = wait(directory, slurm)
    assert code == 0, text
    assert (work / "assembled").read_text() == "1\n2\n3\n3\n"
    first, second, last = (marks(directory, s) for s in ("stage1", "stage2", "assemble"))
    assert sorted(first) == [1, 2, 3] and sorted(second) == [1, 2] and sorted(last) == [1]
    assert all(m[0] == "0" for m in (*first.values(), *second.values(), *last.values()))
    # each stage started after the one before ended: fields rc start end host job
    assert min(int(m[1]) for m in second.values()) >= max(int(m[2]) for m in first.values())
    assert int(last[1][1]) >= max(int(m[2]) for m in second.values())
    manifest = json.load(open(os.path.join(directory, "manifest.json")))
    jobs = manifest["attempts"][0]
    logs = os.listdir(tmp_path / "out" / "logs")
    assert f"order-s1_{jobs['stages']['1']['job']}_3.out" in logs
    assert f"order-assemble_{jobs['assemble']['job']}.out" in logs


def test_a_failed_task_cancels_the_rest_and_resume_redoes_only_it(tmp_path, slurm):
    work = tmp_path / "work"
    work.mkdir()
    one = tmp_path / "one.txt"
    one.write_text("".join(f"echo x >> runs1_{n}; {body}\n" for n, body in (
        (1, "sleep 1"), (2, "test -e flag || exit 3"), (3, "sleep 1"))))
    two = tmp_path / "two.txt"
    two.write_text("echo x >> runs2_1\necho x >> runs2_2\n")
    directory = submitted(tool(
        ["submit", "--name", "fail", "--scheduler", "slurm", "--stage", one, "--stage", two,
         "--assemble", "echo x >> assembled", "--out", tmp_path / "out"], work, slurm))
    code, text = wait(directory, slurm)
    assert code == 1, text
    print(text)
    assert "FAILED     stage 1, index 2, line 2, exit 3" in text
    assert "test -e flag || exit 3" in text
    assert text.count("CANCELLED  stage 2") == 2 and "CANCELLED  assembly" in text
    assert "DependencyNeverSatisfied" in text
    assert [count(work / f"runs1_{n}") for n in (1, 2, 3)] == [1, 1, 1]
    assert count(work / "runs2_1") == 0 and count(work / "assembled") == 0
    # what sacct -c (jobcomp/filetxt) recorded: the failed task, the cancelled jobs
    attempt = json.load(open(os.path.join(directory, "manifest.json")))["attempts"][0]
    later = [attempt["stages"]["2"]["job"], attempt["assemble"]["job"]]
    rows = scheduler(["sacct", "-c", "-n", "-P", "-j", ",".join(later),
                      "--format=JobID,JobName,State"], slurm).split()
    assert sorted(rows) == sorted([f"{later[0]}|fail-s2|CANCELLED",
                                   f"{later[1]}|fail-assemble|CANCELLED"]), rows
    rows = scheduler(["sacct", "-c", "-n", "-P", "--format=JobName,State,ExitCode"], slurm)
    assert "fail-s1|FAILED|3:0" in rows.split()

    (work / "flag").touch()
    again = tool(["resume", directory], ROOT, slurm)
    assert again.returncode == 0, again.stdout + again.stderr
    assert "stage 1: resubmitting array indices 2" in again.stderr
    code, text = wait(directory, slurm)
    assert code == 0, text
    assert [count(work / f"runs1_{n}") for n in (1, 2, 3)] == [1, 2, 1]
    assert [count(work / f"runs2_{n}") for n in (1, 2)] == [1, 1]
    assert count(work / "assembled") == 1
    nothing = tool(["resume", directory], ROOT, slurm)
    assert nothing.returncode == 0 and "nothing to resume" in nothing.stdout


def test_k_lines_per_task_with_export_none_time_and_memory(tmp_path, slurm):
    work = tmp_path / "work"
    work.mkdir()
    lines = tmp_path / "lines.txt"
    lines.write_text("".join(
        f'echo "$MLG_RUN_ROOT $MLG_AUTO_THREADS $SLURM_ARRAY_TASK_ID '
        f'${{NOT_CARRIED-absent}}" > line_{n}\n' for n in range(1, 6)))
    directory = submitted(tool(
        ["submit", "--name", "bundle", "--scheduler", "slurm", "--stage", lines,
         "--per-task", 2, "--env", f"MLG_RUN_ROOT={tmp_path}/runs", "--env",
         "MLG_AUTO_THREADS=3", "--out", tmp_path / "out", "--", "--export=NONE",
         "--mem=100M", "--time=0:05:00"],
        work, slurm, env={"NOT_CARRIED": "here"}))
    code, text = wait(directory, slurm)
    assert code == 0, text
    manifest = json.load(open(os.path.join(directory, "manifest.json")))
    assert manifest["stages"][0]["tasks"] == 3
    job = manifest["attempts"][0]["stages"]["1"]["job"]
    tasks = scheduler(["squeue", "-h", "-r", "-t", "all", "-j", job, "-o", "%i|%T"], slurm)
    assert sorted(tasks.split()) == [f"{job}_{i}|COMPLETED" for i in (1, 2, 3)]
    seen = [(work / f"line_{n}").read_text().split() for n in range(1, 6)]
    assert [s[2] for s in seen] == ["1", "1", "2", "2", "3"]
    assert all(s[:2] == [f"{tmp_path}/runs", "3"] and s[3] == "absent" for s in seen), seen


def test_the_wrapper_fails_its_task_in_slurm(tmp_path, slurm):
    jobs = tmp_path / "jobs.txt"
    jobs.write_text("true\ntrue\ntrue\n")
    other = tmp_path / "other"
    other.mkdir()
    short = scheduler(["sbatch", "--parsable", "-o", "/dev/null", "--array=1-4", WRAPPER,
                       str(jobs)], slurm).strip()
    relative = subprocess.run(["sbatch", "--parsable", "-o", "/dev/null", "--array=1",
                               WRAPPER, "../jobs.txt"], cwd=other,
                              env=dict(os.environ, **slurm), stdout=subprocess.PIPE,
                              text=True, check=True).stdout.strip()
    deadline = time.monotonic() + 60
    while True:
        rows = scheduler(["squeue", "-h", "-r", "-t", "all", "-j", f"{short},{relative}",
                          "-o", "%i|%T"], slurm).split()
        if not any(r.endswith(("|PENDING", "|RUNNING", "|COMPLETING")) for r in rows):
            break
        assert time.monotonic() < deadline, rows
        time.sleep(1)
    assert sorted(rows) == sorted([f"{short}_1|COMPLETED", f"{short}_2|COMPLETED",
                                   f"{short}_3|COMPLETED", f"{short}_4|FAILED",
                                   f"{relative}_1|FAILED"]), rows


def make_environment(**extra):
    environment = {k: v for k, v in os.environ.items()
                   if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    environment.update(extra)
    return environment


def submit_target(target, slurm, *settings):
    """`make <target> SCHEDULER=slurm settings...`: its submission directory."""
    made = subprocess.run(["make", "--no-print-directory", target, "SCHEDULER=slurm",
                           *settings], cwd=ROOT, env=make_environment(**slurm),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=300)
    assert made.returncode == 0, made.stdout[-3000:]
    return submitted(made), made.stdout


def test_make_submit_sweep_matches_make_sweep_and_resubmits_only_the_missing(tmp_path,
                                                                             slurm):
    """`make submit-sweep SCHEDULER=slurm` on 2 points gives what `make sweep` gives; run
    again after a point's result was lost (with --export=NONE), it submits that point
    only, then the summary."""
    build = subprocess.run(["make", "-s", "setup", "build/models/mlg.exe",
                            "build/lib/libmlg.so", "build/bin/mlg_simulate"], cwd=ROOT,
                           env=make_environment(), stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=900)
    assert build.returncode == 0, build.stdout[-3000:]
    by_make, by_slurm = tmp_path / "make", tmp_path / "slurm"
    grid = ["SWEEP_RHO=0,10", "SWEEP_MU=0"]
    made = subprocess.run(["make", "sweep", *grid], cwd=ROOT,
                          env=make_environment(MLG_RUN_ROOT=str(by_make)),
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=300)
    assert made.returncode == 0, made.stdout[-3000:]
    settings = [*grid, f"MLG_RUN_ROOT={by_slurm}", f"SUBMIT_ARGS=--out {tmp_path}/out"]
    directory, output = submit_target("submit-sweep", slurm, *settings)
    assert "sweep: 2 of 2 points without a valid result" in output, output
    code, text = wait(directory, slurm)
    assert code == 0, text
    results = {}
    for point in ("rho0_mu0", "rho10_mu0"):
        a, b = by_make / "sweep" / point, by_slurm / "sweep" / point
        for name in ("b.hb1", "s.hb1"):
            assert (a / name).read_bytes() == (b / name).read_bytes(), (point, name)
        ra, rb = (json.loads((d / "result.json").read_text()) for d in (a, b))
        for record in (ra, rb):
            record.pop("seconds"), record["provenance"].pop("written")
        assert ra == rb and ra["critical_V"] is not None, (ra, rb)
        results[point] = (b / "result.json").read_bytes()
    log = [os.path.join(tmp_path, "out", "logs", f) for f in
           os.listdir(tmp_path / "out" / "logs") if f.startswith("sweep-assemble_")]
    summary = [l for l in open(log[0]).read().splitlines() if "critical speed" in l]
    assert summary == [l for l in made.stdout.splitlines()
                       if l.startswith("sweep: rho =") and "critical speed" in l]
    assert len(summary) == 2

    os.remove(by_slurm / "sweep" / "rho10_mu0" / "result.json")
    again, output = submit_target("submit-sweep", slurm, *settings,
                                  "SUBMIT_OPTIONS=--export=NONE")
    assert "sweep: 1 of 2 points without a valid result" in output, output
    lines = open(os.path.join(again, "stage1.txt")).read().splitlines()
    assert len(lines) == 1 and lines[0].endswith(" point rho10_mu0"), lines
    code, text = wait(again, slurm)
    assert code == 0, text
    assert (by_slurm / "sweep" / "rho0_mu0" / "result.json").read_bytes() == \
        results["rho0_mu0"]
    back = json.loads((by_slurm / "sweep" / "rho10_mu0" / "result.json").read_text())
    assert back["critical_V"] == json.loads(results["rho10_mu0"])["critical_V"]
    logs = sorted(f for f in os.listdir(tmp_path / "out" / "logs")
                  if f.startswith("sweep-assemble_"))
    assert len(logs) == 2
