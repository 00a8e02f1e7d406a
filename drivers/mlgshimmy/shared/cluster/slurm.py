"""Stages as Slurm job arrays chained by afterok dependencies, then the assembly."""
from __future__ import annotations

import os
import shlex
import subprocess
from typing import Any, Dict, Mapping, Optional, Sequence

from mlgshimmy.shared.cluster.arrays import compress
from mlgshimmy.shared.cluster.manifest import now, write_manifest
from mlgshimmy.shared.cluster.refusal import Refused, say


def sbatch(arguments: Sequence[str], dry_run: bool, placeholder: str) -> str:
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


def submit_slurm(manifest: Dict[str, Any], plan: Optional[Mapping[Any, Any]], extra: Sequence[str],
                 dry_run: bool) -> Dict[str, Any]:
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
    print(f"follow: PYTHONPATH=drivers python3 -m mlgshimmy.shared.cluster status {directory}")
    return attempt
