"""The status report as text: counts per stage, then the lines that need a look."""
from __future__ import annotations

import os
from typing import Any, Mapping, Sequence

from mlgshimmy.shared.cluster.scheduler import DONE


def print_status(manifest: Mapping[str, Any], report: Sequence[Mapping[str, Any]], code: int,
                 every: bool = False) -> None:
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
