"""Submit staged job lists to Slurm or GNU parallel, follow them, resume them.

A job list is one shell command per line (a sweep point, an atlas cell, a part of a
staged figure).  A submission is a pipeline: stage 1's lines, then stage 2's (which may
read stage 1's results), ..., then one assembly command (`make fig11`, `python3 -m
mlgshimmy.studies.sweep summary`).  Usage (PYTHONPATH=drivers):

  python3 -m mlgshimmy.shared.jobs.submit submit --name NAME --scheduler slurm|parallel
          (--stage FILE [--stage FILE ...] | --stages-from 'CMD ... {k}' [--stages N])
          [--allow-empty] [--assemble 'CMD'] [--per-task K] [--throttle M] [--jobs J]
          [--env VAR=VALUE ...] [--carry VAR ...] [--out DIR] [--assemble-opt=OPT ...]
          [--dry-run] [-- SBATCH OR PARALLEL OPTIONS ...]
  python3 -m mlgshimmy.shared.jobs.submit status DIR [--json] [--wait [--timeout S]]
  python3 -m mlgshimmy.shared.jobs.submit resume DIR [--dry-run] [-- EXTRA OPTIONS ...]

submit writes a new directory <out>/submit/<name>-<date>-<time>-<random>/ (out: the
repository's build/ by default) with one job file per stage (stage1.txt, ...; read-only,
never rewritten), assemble.txt, and manifest.json (job ids per stage and attempt).  Each
line there is the input line made self-sufficient: unless the line sets them itself, it
is prefixed with `export AUTO_DIR=... MLG_RUN_ROOT=... MLG_AUTO_THREADS=...
MPLBACKEND=Agg SOURCE_DATE_EPOCH=0;` (values from --env, else the submitting shell,
else the repository's defaults; paths made absolute; MLG_CPU_GUARD_SCALE too where the
submitting shell sets it), and with `cd <the submitting
directory> &&` unless it starts with an absolute cd.  So the tasks need nothing from
the environment they start in (sbatch --export=NONE works).  With --allow-empty, a
stage without lines (a `jobs --missing` list with nothing left) is kept and submits
nothing; when no stage has a line, only the assembly is submitted (none: nothing is).

slurm: stage k is one job array `sbatch --parsable -J <name>-s<k> --array=1-T[%M]
  -o <out>/logs/%x_%A_%a.out` of T = ceil(lines / K) tasks running mk/cluster/array-task.sh
  (K lines per task, --per-task), stage k + 1 depends on it with
  --dependency=afterok:<id> --kill-on-invalid-dep=yes, and the assembly
  (-J <name>-assemble, log %x_%j.out) on the last stage.  A failed task therefore
  cancels every later stage and the assembly instead of leaving them pending.  The
  options after `--` go to every sbatch (partition, account, --time, --mem, --export);
  --assemble-opt ones to the assembly's only, after them.
parallel: runs here, in the foreground, stage after stage: `parallel --joblog
  DIR/stage<k>.log --halt soon,fail=1 -j J [options after --] < DIR/stage<k>.txt`,
  then the assembly likewise (DIR/assemble.log); stops at the first failing stage.

status: every line of every stage and the assembly with its state: from the task's
  marks (array-task.sh writes DIR/marks/stage<k>/<line>: exit status, start, end, host,
  job id), squeue (-t all), and sacct, or, without accounting, the jobcomp/filetxt log;
  for parallel, from the job logs.  Counts per stage, then every line that failed, was
  cancelled or killed, never ran, or is running, with its stage, array index, line
  number, state, exit status, reason, job id, log and command (--all: pending and
  completed lines too; --json: all of it).  Exit status 0 when everything completed,
  3 while tasks are pending or running, 1 otherwise.
resume: slurm: resubmits, in the same directory and from the same job files, only the
  array indices that hold lines which did not complete (each such task skips its lines
  marked done), every later stage's incomplete lines, and the assembly; parallel: runs
  the pipeline again with --resume-failed (the job logs say what is done).  Refused
  while tasks of the submission are pending or running.

Standard library only; nothing else of the project is imported.
"""
import argparse
import datetime
import json
import math
import os
import re
import secrets
import shlex
import shutil
import subprocess
import sys
import time

TOOL = "submit"
WRAPPER = os.path.join("mk", "cluster", "array-task.sh")
# What every job line must carry (the Makefile exports the same)
CARRY = ("AUTO_DIR", "MLG_RUN_ROOT", "MLG_AUTO_THREADS", "MPLBACKEND", "SOURCE_DATE_EPOCH")
# ... and these where the submitting shell sets them (the CPU guards' factor)
CARRY_IF_SET = ("MLG_CPU_GUARD_SCALE",)
PATH_VARIABLES = ("AUTO_DIR", "MLG_RUN_ROOT")
NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.+-]*$")
ABSOLUTE_CD = re.compile(r"""^\s*cd\s+(['"]?)/""")
MAX_STAGES = 50
DONE = "COMPLETED"
QUEUED = {"PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "REQUEUED", "RESIZING",
          "SUSPENDED", "REQUEUE_HOLD", "REQUEUE_FED", "SIGNALING", "STAGE_OUT"}


class Refused(Exception):
    """A request that cannot be carried out, with the reason."""


class NothingToDo(Exception):
    """--allow-empty: no stage has a line and there is no assembly."""


def say(message):
    print(f"{TOOL}: {message}", file=sys.stderr)


def repository():
    """The repository this file is in (the directory holding mk/cluster/array-task.sh)."""
    here = os.path.dirname(os.path.abspath(__file__))
    while True:
        if os.path.isfile(os.path.join(here, WRAPPER)):
            return here
        parent = os.path.dirname(here)
        if parent == here:
            return None
        here = parent


def defaults(root):
    return {"AUTO_DIR": os.path.join(root, "build", "auto", "07p"),
            "MLG_RUN_ROOT": os.path.join(root, "build"),
            "MLG_AUTO_THREADS": "1", "MPLBACKEND": "Agg", "SOURCE_DATE_EPOCH": "0"}


def carried_environment(root, overrides, extra, environ=os.environ):
    """{variable: value} that every line carries: --env, else the environment, else the
    repository's default; AUTO_DIR and MLG_RUN_ROOT as absolute paths."""
    values = {}
    base = defaults(root)
    optional = [v for v in CARRY_IF_SET
                if (environ.get(v) or v in overrides) and v not in extra]
    for variable in list(CARRY) + optional + [v for v in extra if v not in CARRY]:
        if variable in overrides:
            value = overrides[variable]
        elif variable in environ:
            value = environ[variable]
        elif variable in base:
            value = base[variable]
        else:
            raise Refused(f"--carry {variable}: {variable} is not set here; give "
                          f"--env {variable}=VALUE")
        if variable in PATH_VARIABLES:
            value = os.path.abspath(value)
        values[variable] = value
    for variable in overrides:
        if variable not in values:
            values[variable] = overrides[variable]
    threads = values.get("MLG_AUTO_THREADS", "1")
    if not re.fullmatch(r"[1-9][0-9]*", threads):
        raise Refused(f"MLG_AUTO_THREADS={threads!r} must be a whole number >= 1")
    return values


def export_prefix(line, environment):
    """`export A=... B=...; ` for the variables the line does not set itself."""
    missing = [f"{variable}={shlex.quote(value)}" for variable, value in environment.items()
               if not re.search(rf"(^|[\s;&|(]){re.escape(variable)}=", line)]
    return f"export {' '.join(missing)}; " if missing else ""


def self_sufficient(line, environment, cwd):
    """The line with what it needs to run anywhere: the environment and an absolute cd."""
    body = line if ABSOLUTE_CD.match(line) else f"cd {shlex.quote(cwd)} || exit 1; {line}"
    return export_prefix(line, environment) + body


def read_lines(text):
    """The commands of a job list: its lines without blank ones and # comments."""
    lines = []
    for raw in text.splitlines():
        line = raw.rstrip("\r").strip()
        if line and not line.startswith("#"):
            lines.append(line)
    return lines


def stages_from_files(files, allow_empty=False):
    stages = []
    for file in files:
        try:
            if file == "-":
                lines = read_lines(sys.stdin.read())
            else:
                with open(file) as handle:
                    lines = read_lines(handle.read())
        except OSError as exc:
            raise Refused(f"--stage {file}: {exc.strerror}") from None
        if not lines and not allow_empty:
            raise Refused(f"--stage {file}: no command in it (--allow-empty: a stage with "
                          "nothing left to do is skipped)")
        stages.append(lines)
    return stages


def stages_from_command(command, count, cwd, allow_empty=False):
    """Stage k's lines from `command` with {k} replaced by k, k = 1, 2, ...: `count`
    stages, or, without a count, up to the first stage that prints nothing.  With
    allow_empty (and a count), a stage may print nothing (`jobs --missing` of a stage
    whose parts are all done)."""
    if "{k}" not in command:
        raise Refused(f"--stages-from {command!r}: put {{k}} where the stage number goes")
    if allow_empty and not count:
        raise Refused("--allow-empty with --stages-from needs --stages N: without it an "
                      "empty stage ends the list")
    stages = []
    for k in range(1, (count or MAX_STAGES) + 1):
        run = subprocess.run(["bash", "-c", command.replace("{k}", str(k))], cwd=cwd,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if run.returncode != 0:
            raise Refused(f"--stages-from: stage {k}: {command.replace('{k}', str(k))!r} "
                          f"failed (exit {run.returncode}): {run.stderr.strip()[-500:]}")
        sys.stderr.write(run.stderr)   # what the command says (`jobs --missing`: counts)
        lines = read_lines(run.stdout)
        if not lines and not allow_empty:
            if count:
                raise Refused(f"--stages-from: stage {k} of --stages {count} has no job "
                              "(--allow-empty: a stage with nothing left to do is skipped)")
            break
        stages.append(lines)
    else:
        if not count:
            raise Refused(f"--stages-from: still printing jobs at stage {MAX_STAGES}; "
                          "give --stages N")
    if not stages:
        raise Refused(f"--stages-from: stage 1 ({command.replace('{k}', '1')!r}) "
                      "printed no job")
    return stages


def write_new(path, text, mode=0o444):
    with open(path, "x") as out:
        out.write(text)
    os.chmod(path, mode)


def write_manifest(directory, manifest):
    target = os.path.join(directory, "manifest.json")
    temporary = f"{target}.{os.getpid()}.part"
    with open(temporary, "w") as out:
        json.dump(manifest, out, indent=1)
        out.write("\n")
    os.replace(temporary, target)


def read_manifest(directory):
    try:
        with open(os.path.join(directory, "manifest.json")) as handle:
            manifest = json.load(handle)
    except OSError as exc:
        raise Refused(f"{directory}: no manifest.json ({exc.strerror}); not a submission "
                      "directory") from None
    manifest["dir"] = os.path.abspath(directory)
    return manifest


def now():
    return datetime.datetime.now().astimezone().isoformat(timespec="seconds")


def compress(indices):
    """[1, 2, 3, 7, 9, 10] -> '1-3,7,9-10'."""
    parts, indices = [], sorted(indices)
    start = previous = indices[0]
    for index in indices[1:] + [None]:
        if index is not None and index == previous + 1:
            previous = index
            continue
        parts.append(str(start) if start == previous else f"{start}-{previous}")
        if index is not None:
            start = previous = index
    return ",".join(parts)


def expand(text):
    """'[1-3,5%2]' or '4' -> [1, 2, 3, 5] / [4]."""
    text = text.strip("[]").split("%")[0]
    indices = []
    for part in filter(None, text.split(",")):
        if "-" in part:
            low, high = part.split("-")
            indices.extend(range(int(low), int(high) + 1))
        else:
            indices.append(int(part))
    return indices


# ---------------------------------------------------------------- submission

def create(args, options):
    root = repository()
    if root is None:
        raise Refused(f"cannot find {WRAPPER} above {__file__}")
    if not NAME.match(args.name):
        raise Refused(f"--name {args.name!r}: use letters, digits and _ . + - only")
    if args.per_task < 1:
        raise Refused(f"--per-task {args.per_task}: lines per task must be >= 1")
    if args.throttle is not None and args.throttle < 1:
        raise Refused(f"--throttle {args.throttle}: must be >= 1")
    if args.scheduler == "parallel" and (args.throttle or args.per_task != 1
                                         or args.assemble_opt):
        raise Refused("--throttle, --per-task and --assemble-opt are for --scheduler slurm; "
                      "with GNU parallel, --jobs J sets how many lines run at once")
    if args.scheduler == "slurm" and args.jobs is not None:
        raise Refused("--jobs is for --scheduler parallel; with Slurm, --throttle M limits "
                      "the running tasks of a stage")
    cwd = os.getcwd()
    overrides = {}
    for item in args.env:
        variable, equals, value = item.partition("=")
        if not equals or not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", variable):
            raise Refused(f"--env {item!r}: give VARIABLE=VALUE")
        overrides[variable] = value
    environment = carried_environment(root, overrides, args.carry)
    if args.stage and args.stages_from:
        raise Refused("give --stage FILE ... or --stages-from CMD, not both")
    if args.stage:
        if args.stages:
            raise Refused("--stages N goes with --stages-from")
        stages = stages_from_files(args.stage, args.allow_empty)
    elif args.stages_from:
        stages = stages_from_command(args.stages_from, args.stages, cwd, args.allow_empty)
    else:
        raise Refused("no jobs: give --stage FILE (one per stage, in order) or "
                      "--stages-from 'CMD ... {k}'")
    for k, lines in enumerate(stages, start=1):
        if not lines:
            say(f"stage {k}: no line (nothing left to do there), skipped")
    if not any(stages):
        if not args.assemble:
            raise NothingToDo("no stage has a line left and there is no assembly: "
                              "nothing to submit")
        say("no stage has a line left: only the assembly is submitted")

    out = os.path.abspath(args.out or os.path.join(root, "build"))
    stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S")
    parent = os.path.join(out, "submit")
    os.makedirs(parent, exist_ok=True)
    directory = os.path.join(parent, f"{args.name}-{stamp}-{secrets.token_hex(3)}")
    os.mkdir(directory)   # new: an existing one is never reused
    manifest = {
        "name": args.name, "scheduler": args.scheduler, "created": now(), "cwd": cwd,
        "repository": root, "wrapper": os.path.join(root, WRAPPER),
        "logs": os.path.join(out, "logs"), "environment": environment,
        "per_task": args.per_task if args.scheduler == "slurm" else 1,
        "throttle": args.throttle, "jobs": args.jobs,
        "options": options, "assemble_options": args.assemble_opt,
        "stages": [], "assemble": None, "attempts": []}
    for k, lines in enumerate(stages, start=1):
        file = f"stage{k}.txt"
        prepared = [self_sufficient(line, environment, cwd) for line in lines]
        write_new(os.path.join(directory, file), "".join(f"{line}\n" for line in prepared))
        manifest["stages"].append({
            "file": file, "lines": len(prepared),
            "tasks": math.ceil(len(prepared) / manifest["per_task"])})
    if args.assemble:
        write_new(os.path.join(directory, "assemble.txt"),
                  self_sufficient(args.assemble.strip(), environment, cwd) + "\n")
        manifest["assemble"] = "assemble.txt"
    manifest["dir"] = directory
    write_manifest(directory, manifest)
    return manifest


def sbatch(arguments, dry_run, placeholder):
    command = ["sbatch", "--parsable"] + arguments
    if dry_run:
        print(shlex.join(command))
        return placeholder
    try:
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)
    except FileNotFoundError:
        raise Refused("sbatch is not installed here (or not on PATH)") from None
    job = run.stdout.strip().split(";")[0]
    if run.returncode != 0 or not job.isdigit():
        raise Refused(f"sbatch failed (exit {run.returncode}): "
                      f"{(run.stderr or run.stdout).strip()}\n  command: {shlex.join(command)}")
    return job


def submit_slurm(manifest, plan, extra, dry_run):
    """Submit the stages' tasks in plan ({k: [array indices]}, all stages if None) and the
    assembly; record the attempt.  Cancels what it submitted if an sbatch fails."""
    directory, logs = manifest["dir"], manifest["logs"]
    os.makedirs(logs, exist_ok=True)   # Slurm does not create the log directory
    options = manifest["options"] + extra
    resume = plan is not None
    attempt = {"time": now(), "kind": "resume" if resume else "submit", "extra_options": extra,
               "stages": {}, "assemble": None}
    previous = None
    submitted = []
    try:
        for k, stage in enumerate(manifest["stages"], start=1):
            indices = list(range(1, stage["tasks"] + 1)) if plan is None else plan.get(k, [])
            if not indices:
                continue
            array = compress(indices)
            if manifest["throttle"]:
                array += f"%{manifest['throttle']}"
            arguments = ["-J", f"{manifest['name']}-s{k}", f"--array={array}",
                         "-o", os.path.join(logs, "%x_%A_%a.out")]
            if previous:
                arguments += [f"--dependency=afterok:{previous}", "--kill-on-invalid-dep=yes"]
            arguments += options + [manifest["wrapper"], "-n", str(stage["lines"]),
                                    "-k", str(manifest["per_task"]),
                                    "-m", os.path.join(directory, "marks", f"stage{k}")]
            arguments += (["-r"] if resume else []) + [os.path.join(directory, stage["file"])]
            previous = sbatch(arguments, dry_run, f"<stage{k}>")
            submitted.append(previous)
            attempt["stages"][str(k)] = {"job": previous, "indices": indices}
        if manifest["assemble"] and (previous or not resume or
                                     plan.get("assemble")):
            arguments = ["-J", f"{manifest['name']}-assemble",
                         "-o", os.path.join(logs, "%x_%j.out")]
            if previous:
                arguments += [f"--dependency=afterok:{previous}", "--kill-on-invalid-dep=yes"]
            arguments += options + manifest["assemble_options"] + [
                manifest["wrapper"], "-n", "1",
                "-m", os.path.join(directory, "marks", "assemble"),
                os.path.join(directory, manifest["assemble"]), "1"]
            job = sbatch(arguments, dry_run, "<assemble>")
            submitted.append(job)
            attempt["assemble"] = {"job": job}
    except Refused:
        if submitted and not dry_run:
            subprocess.run(["scancel"] + submitted)
            say(f"cancelled the jobs this attempt had submitted: {' '.join(submitted)}")
        raise
    if dry_run:
        return attempt
    manifest["attempts"].append(attempt)
    write_manifest(directory, manifest)
    for k, job in attempt["stages"].items():
        stage = manifest["stages"][int(k) - 1]
        print(f"stage {k}: job {job['job']}, array {compress(job['indices'])} "
              f"({stage['lines']} lines, {manifest['per_task']} per task)")
    if attempt["assemble"]:
        print(f"assembly: job {attempt['assemble']['job']}")
    print(f"logs: {logs}/{manifest['name']}-s<k>_<job>_<index>.out")
    print(f"follow: PYTHONPATH=drivers python3 -m mlgshimmy.shared.jobs.submit status {directory}")
    return attempt


def run_parallel(manifest, extra, resume):
    """Run the stages and the assembly here with GNU parallel; the exit status of the
    first stage that fails, else 0."""
    if shutil.which("parallel") is None:
        raise Refused("GNU parallel is not installed here (apt-get install parallel)")
    directory = manifest["dir"]
    environment = dict(os.environ, PARALLEL_SHELL="/bin/bash")
    manifest["attempts"].append({"time": now(), "kind": "resume" if resume else "submit",
                                 "extra_options": extra, "runner": os.getpid()})
    write_manifest(directory, manifest)
    steps = [(f"stage {k}", stage["file"], f"stage{k}.log")
             for k, stage in enumerate(manifest["stages"], start=1) if stage["lines"]]
    if manifest["assemble"]:
        steps.append(("assembly", manifest["assemble"], "assemble.log"))
    for label, file, log in steps:
        command = ["parallel", "--joblog", os.path.join(directory, log),
                   "--halt", "soon,fail=1"]
        if manifest["jobs"]:
            command += ["-j", str(manifest["jobs"])]
        if resume:
            command.append("--resume-failed")
        command += manifest["options"] + extra
        say(f"{label}: {shlex.join(command)} < {os.path.join(directory, file)}")
        with open(os.path.join(directory, file)) as stdin:
            rc = subprocess.run(command, stdin=stdin, env=environment).returncode
        if rc != 0:
            say(f"{label} failed (parallel exit {rc}); the later steps did not run")
            return rc
    return 0


# ---------------------------------------------------------------- status

def jobs_of(manifest):
    ids = []
    for attempt in manifest["attempts"]:
        ids += [stage["job"] for stage in attempt.get("stages", {}).values()]
        if attempt.get("assemble"):
            ids.append(attempt["assemble"]["job"])
    return ids


def parse_job_id(text):
    """'12_3' -> (12, [3]); '12_[1-4]' -> (12, [1, 2, 3, 4]); '12' -> (12, None)."""
    job, _, indices = text.strip().partition("_")
    if not job.isdigit():
        return None, None
    return job, (expand(indices) if indices else None)


def query(command):
    """(exit status, standard output) of a scheduler command; (None, "") where it is not
    installed (status then relies on the marks alone)."""
    try:
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, timeout=120)
    except (FileNotFoundError, subprocess.TimeoutExpired):
        return None, ""
    return run.returncode, run.stdout


def scheduler_states(ids):
    """{(job, index or None): {"state": ..., "exit": ..., "reason": ...}} from squeue -t all,
    sacct, or the jobcomp/filetxt log; the first source that knows a task wins."""
    states = {}

    def put(job, indices, state, **more):
        for index in indices or [None]:
            states.setdefault((job, index), dict(state=state.split()[0], **more))

    if not ids:
        return states
    listing = ",".join(ids)
    _, output = query(["squeue", "-h", "-r", "-t", "all", "-j", listing, "-o", "%i|%T|%r"])
    for row in output.splitlines():
        fields = row.split("|")
        if len(fields) == 3:
            job, indices = parse_job_id(fields[0])
            if job:
                put(job, indices, fields[1], reason=fields[2], source="squeue")
    code, output = query(["sacct", "-n", "-P", "-X", "-j", listing,
                          "--format=JobID,State,ExitCode,Elapsed"])
    if code == 0:
        for row in output.splitlines():
            fields = row.split("|")
            if len(fields) == 4:
                job, indices = parse_job_id(fields[0])
                if job:
                    put(job, indices, fields[1], exit=fields[2], elapsed=fields[3],
                        source="sacct")
        return states
    # no accounting database: the jobcomp/filetxt log, if this host can read it
    # (sacct -c reads it too, but Slurm 22.05's sacct -c drops the array indices)
    _, config = query(["scontrol", "show", "config"])
    settings = dict(re.findall(r"^(\w+)\s*=\s*(.*?)\s*$", config, re.M))
    location = settings.get("JobCompLoc", "")
    if settings.get("JobCompType") != "jobcomp/filetxt" or not os.path.isfile(location):
        return states
    wanted = set(ids)
    found = {}
    with open(location, errors="replace") as handle:
        for row in handle:
            record = dict(re.findall(r"(\w+)=(\S*)", row))
            array = record.get("ArrayJobId")
            if array in wanted:
                for index in expand(record.get("ArrayTaskId", "")):
                    found[(array, index)] = record
            elif record.get("JobId") in wanted:
                found[(record["JobId"], None)] = record   # a job, or an array never split
    for (job, index), record in found.items():
        put(job, [index] if index is not None else None, record.get("JobState", "UNKNOWN"),
            exit=record.get("ExitCode", ""), source="jobcomp")
    return states


def read_mark(path):
    try:
        with open(path) as handle:
            fields = handle.read().split()
    except OSError:
        return None
    if not fields:
        return None
    if fields[0] == "running":
        return {"running": True, "start": fields[1], "host": fields[3], "job": fields[4]}
    return {"rc": int(fields[0]), "start": int(fields[1]), "end": int(fields[2]),
            "host": fields[3], "job": fields[4]}


def strip_prefix(line, manifest):
    prefix = export_prefix("", manifest["environment"])
    return line[len(prefix):] if prefix and line.startswith(prefix) else line


def file_lines(manifest, file):
    with open(os.path.join(manifest["dir"], file)) as handle:
        return handle.read().splitlines()


def slurm_status(manifest):
    states = scheduler_states(jobs_of(manifest))
    per_task = manifest["per_task"]
    steps = [(k, stage) for k, stage in enumerate(manifest["stages"], start=1)]
    if manifest["assemble"]:
        steps.append(("assemble", {"file": manifest["assemble"], "lines": 1, "tasks": 1}))
    report = []
    for k, stage in steps:
        key = str(k)
        # the latest attempt that submitted each array index
        latest = {}
        for attempt in manifest["attempts"]:
            if key == "assemble":
                if attempt.get("assemble"):
                    latest[1] = attempt["assemble"]["job"]
            elif key in attempt.get("stages", {}):
                for index in attempt["stages"][key]["indices"]:
                    latest[index] = attempt["stages"][key]["job"]
        marks = os.path.join(manifest["dir"], "marks", f"stage{k}" if key != "assemble"
                             else "assemble")
        lines = file_lines(manifest, stage["file"])
        entries = []
        for number, line in enumerate(lines, start=1):
            index = (number - 1) // per_task + 1 if key != "assemble" else 1
            job = latest.get(index)
            task = None
            if job is not None:
                task = states.get((job, index if key != "assemble" else None)) \
                    or states.get((job, None)) or states.get((job, index))
            mark = read_mark(os.path.join(marks, str(number)))
            entry = {"line": number, "index": index, "command": strip_prefix(line, manifest),
                     "job": f"{job}_{index}" if job and key != "assemble" else job}
            if job and key != "assemble":
                entry["log"] = os.path.join(manifest["logs"],
                                            f"{manifest['name']}-s{k}_{job}_{index}.out")
            elif job:
                entry["log"] = os.path.join(manifest["logs"],
                                            f"{manifest['name']}-assemble_{job}.out")
            scheduler = task["state"] if task else None
            if mark and not mark.get("running") and (scheduler not in QUEUED
                                                     or mark["rc"] == 0):
                entry["state"] = DONE if mark["rc"] == 0 else "FAILED"
                entry["exit"] = mark["rc"]
                entry["seconds"] = mark["end"] - mark["start"]
            elif scheduler in QUEUED:
                entry["state"] = scheduler
            elif mark and mark.get("running"):
                # started, never ended: killed (time limit, memory, node failure, scancel)
                entry["state"] = scheduler or "KILLED"
            elif scheduler:
                entry["state"] = "NO MARK" if scheduler == DONE else scheduler
            else:
                entry["state"] = "NOT SUBMITTED" if job is None else "UNKNOWN"
            if task and task.get("reason") not in (None, "None", ""):
                entry["reason"] = task["reason"]
            if task and task.get("exit"):
                entry["scheduler_exit"] = task["exit"]
            entries.append(entry)
        report.append({"stage": k, "file": stage["file"], "entries": entries,
                       "jobs": sorted(set(latest.values()), key=int)})
    return report


def parallel_status(manifest):
    report = []
    steps = [(k, stage["file"], f"stage{k}.log")
             for k, stage in enumerate(manifest["stages"], start=1)]
    if manifest["assemble"]:
        steps.append(("assemble", manifest["assemble"], "assemble.log"))
    runner = manifest["attempts"][-1].get("runner") if manifest["attempts"] else None
    running = runner is not None and runner != os.getpid() and alive(runner)
    for k, file, log in steps:
        records = {}
        try:
            with open(os.path.join(manifest["dir"], log)) as handle:
                for row in handle.read().splitlines()[1:]:
                    fields = row.split("\t")
                    if len(fields) >= 9 and fields[0].isdigit():
                        records[int(fields[0])] = fields   # the latest run of each line
        except OSError:
            pass
        entries = []
        for number, line in enumerate(file_lines(manifest, file), start=1):
            entry = {"line": number, "index": number, "command": strip_prefix(line, manifest)}
            fields = records.get(number)
            if fields:
                exitval, signal = int(fields[6]), int(fields[7])
                entry["state"] = DONE if exitval == 0 and signal == 0 else "FAILED"
                entry["exit"] = exitval
                if signal:
                    entry["signal"] = signal
                entry["seconds"] = round(float(fields[3]), 1)
            else:
                entry["state"] = "RUNNING" if running else "NOT RUN"
            entries.append(entry)
        report.append({"stage": k, "file": file, "entries": entries,
                       "log": os.path.join(manifest["dir"], log)})
    return report


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def status(manifest):
    report = (slurm_status if manifest["scheduler"] == "slurm" else parallel_status)(manifest)
    states = [entry["state"] for step in report for entry in step["entries"]]
    if any(state in QUEUED for state in states):
        code = 3
    elif all(state == DONE for state in states):
        code = 0
    else:
        code = 1
    return report, code


def print_status(manifest, report, code, every=False):
    counts = sum(len(step["entries"]) for step in report if step["stage"] != "assemble")
    print(f"{manifest['dir']}: {manifest['scheduler']}, {manifest['name']}, "
          f"{len(manifest['stages'])} stage(s), {counts} lines"
          + (", an assembly" if manifest["assemble"] else "")
          + f", {len(manifest['attempts'])} attempt(s)")
    for step in report:
        tally = {}
        for entry in step["entries"]:
            tally[entry["state"]] = tally.get(entry["state"], 0) + 1
        label = "assembly" if step["stage"] == "assemble" else f"stage {step['stage']}"
        if not step["entries"]:
            print(f"{label}: no lines (nothing was left to do there)")
            continue
        jobs = f" (job {', '.join(step['jobs'])})" if step.get("jobs") else ""
        seconds = [entry["seconds"] for entry in step["entries"] if "seconds" in entry]
        longest = f"; longest line {max(seconds):g} s" if seconds else ""
        print(f"{label}{jobs}: " + ", ".join(f"{n} {state}" for state, n in tally.items())
              + longest)
        for entry in step["entries"]:
            if not every and entry["state"] in (DONE, "PENDING"):
                continue
            detail = [f"index {entry['index']}", f"line {entry['line']}"]
            if "exit" in entry:
                detail.append(f"exit {entry['exit']}")
            if entry.get("reason"):
                detail.append(entry["reason"])
            if entry.get("job"):
                detail.append(f"job {entry['job']}")
            print(f"  {entry['state']:<10} {label}, {', '.join(detail)}: {entry['command']}")
            if entry.get("log") and os.path.exists(entry["log"]):
                print(f"             log {entry['log']}")
    if code == 0:
        print("everything completed")
    elif code == 3:
        print("in progress: tasks are pending or running")
    else:
        print("incomplete: `submit resume "
              f"{manifest['dir']}` reruns only what did not complete")


# ---------------------------------------------------------------- resume

def resume(manifest, extra, dry_run):
    report, code = status(manifest)
    if code == 3:
        raise Refused("tasks of this submission are still pending or running: wait "
                      f"(status --wait) or scancel them: {' '.join(jobs_of(manifest))}")
    if code == 0:
        print("nothing to resume: every line and the assembly completed")
        return 0
    if manifest["scheduler"] == "parallel":
        return run_parallel(manifest, extra, resume=True)
    plan = {}
    for step in report:
        todo = sorted({entry["index"] for entry in step["entries"] if entry["state"] != DONE})
        if step["stage"] == "assemble":
            plan["assemble"] = bool(todo)
        elif todo:
            plan[step["stage"]] = todo
    for k in sorted(key for key in plan if key != "assemble"):
        say(f"stage {k}: resubmitting array indices {compress(plan[k])}")
    submit_slurm(manifest, plan, extra, dry_run)
    return 0


# ---------------------------------------------------------------- command line

def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    options = []
    if "--" in argv:
        cut = argv.index("--")
        argv, options = argv[:cut], argv[cut + 1:]
    parser = argparse.ArgumentParser(
        prog="python3 -m mlgshimmy.shared.jobs.submit",
        description="Submit staged job lists to Slurm or GNU parallel; status; resume. "
                    "Options after -- go to sbatch or parallel.",
        epilog="docs/cluster.md walks through it.")
    commands = parser.add_subparsers(dest="command", required=True)
    new = commands.add_parser("submit", help="write the job files and submit or run them")
    new.add_argument("--name", required=True, help="job name prefix (<name>-s<k>, "
                     "<name>-assemble) and directory name")
    new.add_argument("--scheduler", required=True, choices=["slurm", "parallel"])
    new.add_argument("--stage", action="append", default=[], metavar="FILE",
                     help="a stage's job list, one shell command per line (repeat, in order; "
                          "- reads standard input)")
    new.add_argument("--stages-from", metavar="CMD",
                     help="a command printing stage {k}'s lines, run for k = 1, 2, ... "
                          "until one prints nothing (or --stages N)")
    new.add_argument("--stages", type=int, help="the number of stages of --stages-from")
    new.add_argument("--allow-empty", action="store_true",
                     help="a stage without lines is skipped, not refused (job lists printed by "
                          "`jobs --missing`); with --stages-from it needs --stages N")
    new.add_argument("--assemble", metavar="CMD",
                     help="run after every stage completed (e.g. 'make fig11')")
    new.add_argument("--per-task", type=int, default=1, metavar="K",
                     help="slurm: K lines per array task (default 1)")
    new.add_argument("--throttle", type=int, metavar="M",
                     help="slurm: at most M tasks of a stage at once (--array=...%%M)")
    new.add_argument("--jobs", type=int, metavar="J", help="parallel: -j J")
    new.add_argument("--env", action="append", default=[], metavar="VAR=VALUE",
                     help="a value for a variable the lines carry (AUTO_DIR, MLG_RUN_ROOT, "
                          "MLG_AUTO_THREADS, MPLBACKEND, SOURCE_DATE_EPOCH) or another one")
    new.add_argument("--carry", action="append", default=[], metavar="VAR",
                     help="also carry this variable's value from here")
    new.add_argument("--out", metavar="DIR",
                     help="where submit/ and logs/ go (default: the repository's build/)")
    new.add_argument("--assemble-opt", action="append", default=[], metavar="OPT",
                     help="an sbatch option for the assembly job only (--assemble-opt=--mem=4G)")
    new.add_argument("--dry-run", action="store_true",
                     help="write the directory, print the sbatch commands, submit nothing")
    look = commands.add_parser("status", help="the state of every line of a submission")
    look.add_argument("dir")
    look.add_argument("--json", action="store_true", help="the report as JSON")
    look.add_argument("--all", action="store_true",
                      help="list pending and completed lines too (default: the others)")
    look.add_argument("--wait", action="store_true",
                      help="poll until no task is pending or running")
    look.add_argument("--timeout", type=float, default=3600, help="seconds for --wait")
    again = commands.add_parser("resume", help="rerun only what did not complete")
    again.add_argument("dir")
    again.add_argument("--dry-run", action="store_true")
    commands.add_parser("resubmit", help="the same as resume").add_argument("dir")
    args = parser.parse_args(argv)
    try:
        if args.command == "submit":
            manifest = create(args, options)
            print(f"submission: {manifest['dir']}")
            if args.scheduler == "slurm":
                submit_slurm(manifest, None, [], args.dry_run)
                return 0
            if args.dry_run:
                print("dry run: GNU parallel not started")
                return 0
            rc = run_parallel(manifest, [], resume=False)
            report, code = status(manifest)
            print_status(manifest, report, code)
            return rc or code
        manifest = read_manifest(args.dir)
        if options and args.command == "status":
            raise Refused("status takes no scheduler options")
        if args.command == "status":
            deadline = time.monotonic() + args.timeout
            while True:
                report, code = status(manifest)
                if code != 3 or not args.wait or time.monotonic() > deadline:
                    break
                time.sleep(2)
            if args.json:
                print(json.dumps({"dir": manifest["dir"], "code": code, "steps": report},
                                 indent=1))
            else:
                print_status(manifest, report, code, every=args.all)
            return code
        rc = resume(manifest, options, getattr(args, "dry_run", False))
        if manifest["scheduler"] == "parallel":
            report, code = status(manifest)
            print_status(manifest, report, code)
            return rc or code
        return rc
    except NothingToDo as exc:
        say(str(exc))
        return 0
    except Refused as exc:
        say(str(exc))
        return 2


if __name__ == "__main__":
    sys.exit(main())
