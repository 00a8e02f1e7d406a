"""Stages run here, one after the other, with GNU parallel."""
from __future__ import annotations

import os
import shlex
import shutil
import subprocess
from typing import Any, Mapping, Sequence

from mlgshimmy.shared.cluster.manifest import now, write_manifest
from mlgshimmy.shared.cluster.refusal import Refused, say


def run_parallel(manifest: Mapping[str, Any], extra: Sequence[str], resume: bool) -> int:
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
