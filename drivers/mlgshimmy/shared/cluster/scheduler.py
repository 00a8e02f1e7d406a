"""What Slurm says of a submission's jobs: squeue, sacct, or the jobcomp log."""
from __future__ import annotations

import os
import re
import subprocess
from typing import Any, Dict, Optional, Sequence, Tuple

from mlgshimmy.shared.cluster.arrays import expand, parse_job_id

DONE = "COMPLETED"
QUEUED = {"PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "REQUEUED", "RESIZING",
          "SUSPENDED", "REQUEUE_HOLD", "REQUEUE_FED", "SIGNALING", "STAGE_OUT"}


def query(command: Sequence[str]) -> Tuple[Optional[int], str]:
    """(exit status, standard output) of a scheduler command; (None, "") where it is not
    installed (status then relies on the marks alone)."""
    try:
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, timeout=120)
    except (FileNotFoundError, subprocess.TimeoutExpired):
        return None, ""
    return run.returncode, run.stdout


def scheduler_states(ids: Sequence[str]) -> Dict[Tuple[str, Optional[int]], Dict[str, Any]]:
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
