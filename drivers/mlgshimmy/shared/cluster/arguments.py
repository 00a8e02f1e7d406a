"""The command line: submit, status, resume (and its alias resubmit)."""
from __future__ import annotations

import argparse


def parser() -> argparse.ArgumentParser:
    """The argument parser; the options after `--` are split off before it."""
    parser = argparse.ArgumentParser(
        prog="python3 -m mlgshimmy.shared.cluster",
        description="Submit staged job lists to Slurm or GNU parallel; status; resume. "
                    "Options after -- go to sbatch or parallel.",
        epilog="docs/cluster.md walks through it.")
    commands = parser.add_subparsers(dest="command", required=True)
    new = commands.add_parser("submit", help="write the job files and submit or run them")
    new.add_argument("--name", required=True, help="job name prefix (<name>-s<k>, "
                     "<name>-assemble) and directory name")
    new.add_argument("--scheduler", required=True, choices=["slurm", "parallel"])
    new.add_argument("--stage", action="append", default=[], metavar="FILE",
                     help="a stage's job list, one shell command per line (repeat, in order; "
                          "- reads standard input)")
    new.add_argument("--stages-from", metavar="CMD",
                     help="a command printing stage {k}'s lines, run for k = 1, 2, ... "
                          "until one prints nothing (or --stages N)")
    new.add_argument("--stages", type=int, help="the number of stages of --stages-from")
    new.add_argument("--allow-empty", action="store_true",
                     help="a stage without lines is skipped, not refused (job lists printed by "
                          "`jobs --missing`); with --stages-from it needs --stages N")
    new.add_argument("--assemble", metavar="CMD",
                     help="run after every stage completed (e.g. 'make fig11')")
    new.add_argument("--per-task", type=int, default=1, metavar="K",
                     help="slurm: K lines per array task (default 1)")
    new.add_argument("--throttle", type=int, metavar="M",
                     help="slurm: at most M tasks of a stage at once (--array=...%%M)")
    new.add_argument("--jobs", type=int, metavar="J", help="parallel: -j J")
    new.add_argument("--env", action="append", default=[], metavar="VAR=VALUE",
                     help="a value for a variable the lines carry (AUTO_DIR, MLG_RUN_ROOT, "
                          "MLG_AUTO_THREADS, MPLBACKEND, SOURCE_DATE_EPOCH) or another one")
    new.add_argument("--carry", action="append", default=[], metavar="VAR",
                     help="also carry this variable's value from here")
    new.add_argument("--out", metavar="DIR",
                     help="where submit/ and logs/ go (default: the repository's build/)")
    new.add_argument("--assemble-opt", action="append", default=[], metavar="OPT",
                     help="an sbatch option for the assembly job only (--assemble-opt=--mem=4G)")
    new.add_argument("--dry-run", action="store_true",
                     help="write the directory, print the sbatch commands, submit nothing")
    look = commands.add_parser("status", help="the state of every line of a submission")
    look.add_argument("dir")
    look.add_argument("--json", action="store_true", help="the report as JSON")
    look.add_argument("--all", action="store_true",
                      help="list pending and completed lines too (default: the others)")
    look.add_argument("--wait", action="store_true",
                      help="poll until no task is pending or running")
    look.add_argument("--timeout", type=float, default=3600, help="seconds for --wait")
    again = commands.add_parser("resume", help="rerun only what did not complete")
    again.add_argument("dir")
    again.add_argument("--dry-run", action="store_true")
    commands.add_parser("resubmit", help="the same as resume").add_argument("dir")
    return parser
