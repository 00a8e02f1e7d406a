"""What a cached figure cost to compute, part by part: `make profile-fig11
[RHO= MU= ...]` reads the cost each cached part and result records
(cache.compute_once: wall and CPU seconds, AUTO's runs and the simulator
included) and lists the most expensive first, with the totals.  The CPU
seconds are the figure's work; the wall seconds depend on what else ran."""
import json
import os
import sys
from typing import Dict, List, Optional

from mlgshimmy.shared import paths, suggest
from mlgshimmy.shared.jobs import cache, catalogue


def costs(figure: str, root: Optional[str] = None) -> List[Dict]:
    """[{"part", "wall_seconds", "cpu_seconds"}] of the figure's cached parts
    and its assembly ("result"), most CPU first; a record computed before
    costs were kept has None for both."""
    found = []
    where = cache.parts_dir(figure, root)
    names = sorted(n[:-len(".json")] for n in os.listdir(where)
                   if n.endswith(".json")) if os.path.isdir(where) else []
    for part, path in [(n, cache.path(figure, n, root)) for n in names] + \
            [("result", cache.path(figure, None, root))]:
        try:
            with open(path) as source:
                cost = json.load(source).get("cost") or {}
        except (OSError, ValueError):
            continue
        found.append({"part": part, "wall_seconds": cost.get("wall_seconds"),
                      "cpu_seconds": cost.get("cpu_seconds")})
    return sorted(found, key=lambda c: -(c["cpu_seconds"] or 0))


def table(found: List[Dict], top: int = 5) -> str:
    """The `top` most expensive parts and the totals, as text."""
    def number(v):
        return "-" if v is None else f"{v:.0f}"
    lines = [f"{'part':24s} {'CPU s':>8s} {'wall s':>8s}"]
    lines += [f"{c['part']:24s} {number(c['cpu_seconds']):>8s} {number(c['wall_seconds']):>8s}"
              for c in found[:top]]
    cpu = sum(c["cpu_seconds"] or 0 for c in found)
    unknown = sum(c["cpu_seconds"] is None for c in found)
    lines.append(f"{'all ' + str(len(found)) + ' parts':24s} {cpu:8.0f}"
                 + (f"   ({unknown} computed before costs were kept)" if unknown else ""))
    return "\n".join(lines)


def main(argv: List[str]) -> int:
    if len(argv) != 1:
        print("usage: python -m mlgshimmy.shared.jobs.costs <figure>", file=sys.stderr)
        return 2
    figure = argv[0]
    known = [e["name"] for e in catalogue.figures()]
    if figure not in known:
        print(f"profile: no figure {figure!r}{suggest.did_you_mean(figure, known)}",
              file=sys.stderr)
        return 2
    found = costs(figure)
    if not found:
        print(f"profile: {figure} has no cached result under {paths.under_root(figure)} "
              f"(run `make {figure}` with the same RHO, MU, EOM and SET)", file=sys.stderr)
        return 1
    print(f"{figure}: what its cached parts cost (most CPU first)")
    print(table(found))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
