"""The state of every line of a submission, from the tasks' marks and the
scheduler (Slurm) or the job logs (GNU parallel)."""
from __future__ import annotations

import os
from typing import Any, Dict, List, Mapping, Optional, Tuple

from mlgshimmy.shared.cluster.environment import export_prefix
from mlgshimmy.shared.cluster.manifest import jobs_of
from mlgshimmy.shared.cluster.scheduler import DONE, QUEUED, scheduler_states


def read_mark(path: str) -> Optional[Dict[str, Any]]:
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


def strip_prefix(line: str, manifest: Mapping[str, Any]) -> str:
    prefix = export_prefix("", manifest["environment"])
    return line[len(prefix):] if prefix and line.startswith(prefix) else line


def file_lines(manifest: Mapping[str, Any], file: str) -> List[str]:
    with open(os.path.join(manifest["dir"], file)) as handle:
        return handle.read().splitlines()


def slurm_status(manifest: Mapping[str, Any]) -> List[Dict[str, Any]]:
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


def parallel_status(manifest: Mapping[str, Any]) -> List[Dict[str, Any]]:
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


def alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def status(manifest: Mapping[str, Any]) -> Tuple[List[Dict[str, Any]], int]:
    report = (slurm_status if manifest["scheduler"] == "slurm" else parallel_status)(manifest)
    states = [entry["state"] for step in report for entry in step["entries"]]
    if any(state in QUEUED for state in states):
        code = 3
    elif all(state == DONE for state in states):
        code = 0
    else:
        code = 1
    return report, code
