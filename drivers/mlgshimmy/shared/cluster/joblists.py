"""The stages' job lists: from files, or from a command run once a stage."""
from __future__ import annotations

import subprocess
import sys
from typing import List, Optional, Sequence

from mlgshimmy.shared.cluster.refusal import Refused

MAX_STAGES = 50


def read_lines(text: str) -> List[str]:
    """The commands of a job list: its lines without blank ones and # comments."""
    lines = []
    for raw in text.splitlines():
        line = raw.rstrip("\r").strip()
        if line and not line.startswith("#"):
            lines.append(line)
    return lines


def stages_from_files(files: Sequence[str], allow_empty: bool = False) -> List[List[str]]:
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


def stages_from_command(command: str, count: Optional[int], cwd: str,
                        allow_empty: bool = False) -> List[List[str]]:
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
