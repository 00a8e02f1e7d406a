"""What every job line carries so that it runs anywhere: the environment and an
absolute cd."""
from __future__ import annotations

import os
import re
import shlex
from typing import Dict, Mapping, Sequence

from mlgshimmy.shared.cluster.refusal import Refused

# What every job line must carry (the Makefile exports the same)
CARRY = ("AUTO_DIR", "MLG_RUN_ROOT", "MLG_AUTO_THREADS", "MPLBACKEND", "SOURCE_DATE_EPOCH")
# ... and these where the submitting shell sets them (the CPU guards' factor)
CARRY_IF_SET = ("MLG_CPU_GUARD_SCALE",)
PATH_VARIABLES = ("AUTO_DIR", "MLG_RUN_ROOT")
ABSOLUTE_CD = re.compile(r"""^\s*cd\s+(['"]?)/""")


def defaults(root: str) -> Dict[str, str]:
    return {"AUTO_DIR": os.path.join(root, "build", "auto", "07p"),
            "MLG_RUN_ROOT": os.path.join(root, "build"),
            "MLG_AUTO_THREADS": "1", "MPLBACKEND": "Agg", "SOURCE_DATE_EPOCH": "0"}


def carried_environment(root: str, overrides: Sequence[str], extra: Sequence[str],
                        environ: Mapping[str, str] = os.environ) -> Dict[str, str]:
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


def export_prefix(line: str, environment: Mapping[str, str]) -> str:
    """`export A=... B=...; ` for the variables the line does not set itself."""
    missing = [f"{variable}={shlex.quote(value)}" for variable, value in environment.items()
               if not re.search(rf"(^|[\s;&|(]){re.escape(variable)}=", line)]
    return f"export {' '.join(missing)}; " if missing else ""


def self_sufficient(line: str, environment: Mapping[str, str], cwd: str) -> str:
    """The line with what it needs to run anywhere: the environment and an absolute cd."""
    body = line if ABSOLUTE_CD.match(line) else f"cd {shlex.quote(cwd)} || exit 1; {line}"
    return export_prefix(line, environment) + body
