"""A submission directory's manifest.json and its write-once job files."""
from __future__ import annotations

import datetime
import json
import os
from typing import Any, Dict, List, Mapping

from mlgshimmy.shared.cluster.refusal import Refused


def write_new(path: str, text: str, mode: int = 0o444) -> None:
    with open(path, "x") as out:
        out.write(text)
    os.chmod(path, mode)


def write_manifest(directory: str, manifest: Mapping[str, Any]) -> None:
    target = os.path.join(directory, "manifest.json")
    temporary = f"{target}.{os.getpid()}.part"
    with open(temporary, "w") as out:
        json.dump(manifest, out, indent=1)
        out.write("\n")
    os.replace(temporary, target)


def read_manifest(directory: str) -> Dict[str, Any]:
    try:
        with open(os.path.join(directory, "manifest.json")) as handle:
            manifest = json.load(handle)
    except OSError as exc:
        raise Refused(f"{directory}: no manifest.json ({exc.strerror}); not a submission "
                      "directory") from None
    manifest["dir"] = os.path.abspath(directory)
    return manifest


def now() -> str:
    return datetime.datetime.now().astimezone().isoformat(timespec="seconds")


def jobs_of(manifest: Mapping[str, Any]) -> List[str]:
    ids = []
    for attempt in manifest["attempts"]:
        ids += [stage["job"] for stage in attempt.get("stages", {}).values()]
        if attempt.get("assemble"):
            ids.append(attempt["assemble"]["job"])
    return ids
