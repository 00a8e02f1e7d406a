"""python3 -m mlgshimmy.shared.cluster: the tool's entry (the package's text
says what it does)."""
from __future__ import annotations

import json
import sys
import time
from typing import Optional, Sequence

from mlgshimmy.shared.cluster import arguments
from mlgshimmy.shared.cluster.manifest import read_manifest
from mlgshimmy.shared.cluster.parallel import run_parallel
from mlgshimmy.shared.cluster.refusal import NothingToDo, Refused, say
from mlgshimmy.shared.cluster.resume import resume
from mlgshimmy.shared.cluster.slurm import submit_slurm
from mlgshimmy.shared.cluster.status import status
from mlgshimmy.shared.cluster.submission import create
from mlgshimmy.shared.cluster.summary import print_status


def main(argv: Optional[Sequence[str]] = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    options = []
    if "--" in argv:
        cut = argv.index("--")
        argv, options = argv[:cut], argv[cut + 1:]
    args = arguments.parser().parse_args(argv)
    try:
        if args.command == "submit":
            manifest = create(args, options)
            print(f"submission: {manifest['dir']}")
            if args.scheduler == "slurm":
                submit_slurm(manifest, None, [], args.dry_run)
                return 0
            if args.dry_run:
                print("dry run: GNU parallel not started")
                return 0
            rc = run_parallel(manifest, [], resume=False)
            report, code = status(manifest)
            print_status(manifest, report, code)
            return rc or code
        manifest = read_manifest(args.dir)
        if options and args.command == "status":
            raise Refused("status takes no scheduler options")
        if args.command == "status":
            deadline = time.monotonic() + args.timeout
            while True:
                report, code = status(manifest)
                if code != 3 or not args.wait or time.monotonic() > deadline:
                    break
                time.sleep(2)
            if args.json:
                print(json.dumps({"dir": manifest["dir"], "code": code, "steps": report},
                                 indent=1))
            else:
                print_status(manifest, report, code, every=args.all)
            return code
        rc = resume(manifest, options, getattr(args, "dry_run", False))
        if manifest["scheduler"] == "parallel":
            report, code = status(manifest)
            print_status(manifest, report, code)
            return rc or code
        return rc
    except NothingToDo as exc:
        say(str(exc))
        return 0
    except Refused as exc:
        say(str(exc))
        return 2


if __name__ == "__main__":
    sys.exit(main())

