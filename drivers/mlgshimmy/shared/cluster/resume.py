"""Rerun only what did not complete."""
from __future__ import annotations

from typing import Any, Dict, Sequence

from mlgshimmy.shared.cluster.arrays import compress
from mlgshimmy.shared.cluster.manifest import jobs_of
from mlgshimmy.shared.cluster.parallel import run_parallel
from mlgshimmy.shared.cluster.refusal import Refused, say
from mlgshimmy.shared.cluster.scheduler import DONE
from mlgshimmy.shared.cluster.slurm import submit_slurm
from mlgshimmy.shared.cluster.status import status


def resume(manifest: Dict[str, Any], extra: Sequence[str], dry_run: bool) -> int:
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
