"""A new submission directory: its job files, made self-sufficient, and its
manifest."""
from __future__ import annotations

import argparse
import datetime
import math
import os
import re
import secrets
from typing import Any, Dict, Sequence

from mlgshimmy.shared.cluster.environment import carried_environment, self_sufficient
from mlgshimmy.shared.cluster.joblists import stages_from_command, stages_from_files
from mlgshimmy.shared.cluster.manifest import now, write_manifest, write_new
from mlgshimmy.shared.cluster.refusal import NothingToDo, Refused, say
from mlgshimmy.shared.paths import ROOT

WRAPPER = os.path.join("mk", "cluster", "array-task.sh")
NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.+-]*$")


def create(args: argparse.Namespace, options: Sequence[str]) -> Dict[str, Any]:
    """Check the request, write the submission directory and return its manifest
    (nothing is submitted yet)."""
    root = ROOT
    if not os.path.isfile(os.path.join(root, WRAPPER)):
        raise Refused(f"{os.path.join(root, WRAPPER)} is missing: run the tool from a "
                      "checkout of the repository")
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
