"""Every figure and study, as each declares itself: a literal `DECLARED =
{target: {...}}` in its module (a package: in its declared.py), read as
text, nothing imported, so that make can use it before anything is built
(as depends.py reads imports).  From it come the make rules of the
figures, FIGURES (quickest first), REGRESS_FIGURES, REGRESS_QUICK, the
figures with parts, the submit targets, the lines of `make help` and the
report's entries:

    python3 drivers/mlgshimmy/shared/jobs/catalogue.py make > build/deps/catalogue.mk

A figure's entry (figures/figNN.py):
    "help"     its line in `make help` ("Fig. 7: zero freeplay, ...")
    "time"     its typical time on one core ("10 s", "1.5 min", "+ 5 s")
    "report"   what the paper shows, for the report
    "regress"  True: under regression (tests/reference/<fig>/); "quick":
               `make test` compares it too; "with <fig>": compared inside
               <fig>'s set (drawn from its runs)
    "parts"    True: its driver lists parts (jobs.run_figure(parts=...)),
               run as make jobs and submitted stage by stage
    "after"    the figures whose cached results it reads
    "needs"    "simulator" (build/bin/mlg_simulate), "library" (libmlg.so)
    "cached"   False: no cached result (it computes nothing, or simulates);
               its redraw is the same command, or "redraw" (e.g. "--plot")
    "options"  driver options (a variant: "--strut-variant 1")
    "paper"    {quantity: value} of the result values the paper prints
               (shared.paper.PAPER); "calibrated": those the parameter set
               was fitted to; "held_out": {quantity: the paper's symbol};
               "repeats": {quantity: [figure, quantity]} of printed numbers
               another figure shows first (counted once, there)
A study's entry (studies/<name>.py, keyed by its make target): "help",
"time", "usage" (the help's target column), "grid"
(the make variable of its grid options: submitted a job per point),
"carries" (make variables its job needs, e.g. RUN), "in_figures" (made by
`make figures`), "report": {"command", "text", "tables", "figures"}.
"""
import ast
import os
import re
import sys
from typing import Dict, List

PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ROOMS = ("figures", "studies")
FIGURE_KEYS = {"help", "time", "report", "regress", "parts", "after", "needs", "cached",
               "redraw", "options", "paper", "calibrated", "held_out", "repeats"}
STUDY_KEYS = {"help", "time", "usage", "grid", "carries", "in_figures", "report"}
NEEDS = {"simulator": "$(MLG_SIMULATE)", "library": "$(MLG_SHARED)"}
TIME = re.compile(r"^(?:\+ |> )?(\d+(?:\.\d+)?) (s|min)$")


class DeclarationError(ValueError):
    """A declaration that cannot be read: names its file and the key."""


def declaration_file(room: str, name: str, root: str = PACKAGE_DIR) -> str:
    base = os.path.join(root, room, name)
    return os.path.join(base, "declared.py") if os.path.isdir(base) else base + ".py"


def modules(room: str, root: str = PACKAGE_DIR) -> List[str]:
    """The room's modules and packages, sorted (no __init__, no __main__)."""
    found = []
    for entry in sorted(os.listdir(os.path.join(root, room))):
        path = os.path.join(root, room, entry)
        if entry.endswith(".py") and not entry.startswith("__"):
            found.append(entry[:-3])
        elif os.path.isfile(os.path.join(path, "__init__.py")):
            found.append(entry)
    return found


def declared(path: str) -> Dict:
    """The literal DECLARED of a file, or None when it has none."""
    with open(path) as source:
        tree = ast.parse(source.read(), path)
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id == "DECLARED" for t in node.targets):
            try:
                return ast.literal_eval(node.value)
            except ValueError as exc:
                raise DeclarationError(f"{path}: DECLARED must be literals only ({exc})")
    return None


def seconds(time: str) -> float:
    """A typical time in seconds ("+ 5 s": 5, after what it reads)."""
    m = TIME.match(time)
    if not m:
        raise ValueError(f"time {time!r} is not like '10 s', '1.5 min', '+ 5 s'")
    return float(m.group(1)) * (60 if m.group(2) == "min" else 1)


def quick_first(entries: List[Dict]) -> List[Dict]:
    """The entries by typical time, quickest first (`make -jN figures` starts
    them in this order, so that the first figures are drawn in seconds); a
    time "+ 5 s" counts after the longest of the figures it reads."""
    by_name = {e["name"]: e for e in entries}

    def total(e):
        after = [total(by_name[n]) for n in e.get("after", []) if n in by_name]
        return seconds(e["time"]) + (max(after) if e["time"].startswith("+") and after else 0)
    return sorted(entries, key=total)


def check(path: str, room: str, target: str, entry: Dict) -> None:
    keys = FIGURE_KEYS if room == "figures" else STUDY_KEYS
    unknown = set(entry) - keys
    if unknown:
        raise DeclarationError(f"{path}: {target}: unknown key {sorted(unknown)[0]!r} "
                               f"(known: {', '.join(sorted(keys))})")
    for key in ("help", "time") + (("report",) if room == "figures" else ()):
        if not isinstance(entry.get(key), str):
            raise DeclarationError(f"{path}: {target}: '{key}' is missing")
    try:
        seconds(entry["time"])
    except ValueError as exc:
        raise DeclarationError(f"{path}: {target}: {exc}")
    for need in entry.get("needs", []):
        if need not in NEEDS:
            raise DeclarationError(f"{path}: {target}: needs {need!r}: one of {sorted(NEEDS)}")


def entries(root: str = PACKAGE_DIR) -> List[Dict]:
    """Every declared target: its entry with "name" (the target), "room",
    "module" (the driver's module under mlgshimmy) and "file" added; the
    figures first, each room by module name, a module's targets in the
    order it declares them."""
    out = []
    for room in ROOMS:
        for name in modules(room, root):
            path = declaration_file(room, name, root)
            found = declared(path) if os.path.exists(path) else None
            for target, entry in (found or {}).items():
                check(path, room, target, entry)
                out.append(dict(entry, name=target, room=room,
                                module=f"{room}.{name}", file=path))
    names = [e["name"] for e in out]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise DeclarationError(f"declared twice: {', '.join(twice)}")
    for e in out:
        for other in e.get("after", []):
            if other not in names:
                raise DeclarationError(f"{e['file']}: {e['name']}: after {other!r}, "
                                       "which nothing declares")
    return out


def figures(root: str = PACKAGE_DIR) -> List[Dict]:
    return [e for e in entries(root) if e["room"] == "figures"]


def studies(root: str = PACKAGE_DIR) -> List[Dict]:
    return [e for e in entries(root) if e["room"] == "studies"]


def help_line(usage: str, time: str, text: str) -> str:
    """One target line of `make help`: the times right-aligned."""
    return f"  {usage}{time:>{max(31 - len(usage), len(time) + 2)}}  {text}"


def _words(name: str, values: List[str]) -> str:
    return f"{name} := {' '.join(values)}".rstrip() + "\n"


def _define(name: str, lines: List[str]) -> str:
    return f"define {name}\n" + "".join(line + "\n" for line in lines) + "endef\n"


def figure_rule(e: Dict) -> str:
    """The make rule of one figure: mk/figures.mk's cached_figure or
    uncached_figure."""
    driver = e["module"].split(".")[-1]
    if not e.get("cached", True) and (driver != e["name"] or e.get("options")):
        raise DeclarationError(f"{e['file']}: {e['name']}: a figure without a cache is "
                               "its module's only target")
    inputs = [NEEDS[n] for n in e.get("needs", []) if n != "library"]
    results = [f"$(call result,{other})" for other in e.get("after", [])]
    if e.get("cached", True):
        args = [e["name"], " ".join(results + inputs)]
        if driver != e["name"] or e.get("options"):
            args += [driver, e.get("options", "")]
        return f"$(eval $(call cached_figure,{','.join(args).rstrip(',')}))\n"
    order_only = " | packages" if "library" in e.get("needs", []) else ""
    library = [NEEDS["library"]] if "library" in e.get("needs", []) else []
    prerequisites = " ".join(results + inputs + library) + order_only
    redraw = e.get("redraw", "")
    plot_prerequisites = "" if redraw else " ".join(inputs + library) + order_only
    return (f"$(eval $(call uncached_figure,{driver},{prerequisites.strip()},"
            f"{plot_prerequisites.strip()},{redraw}))\n")


def make_text(root: str = PACKAGE_DIR) -> str:
    """The makefile: rules, lists, help lines and submit targets."""
    figs, studs = figures(root), studies(root)
    regress = [e["name"] for e in figs if e.get("regress") in (True, "quick")]
    quick = [e["name"] for e in figs if e.get("regress") == "quick"]
    with_parts = [e["name"] for e in figs if e.get("parts")]
    made = [e["name"] for e in quick_first(figs + [e for e in studs if e.get("in_figures")])]
    whole = [n for n in made if n not in with_parts] + \
        [e["name"] for e in studs if not e.get("grid") and not e.get("in_figures")]
    grids = [f"{e['name']}:{e['module'].split('.')[-1]}:{e['grid']}"
             for e in studs if e.get("grid")]
    text = ["# Generated by drivers/mlgshimmy/shared/jobs/catalogue.py from the figures'\n"
            "# and studies' declarations (DECLARED); do not edit.\n",
            _words("CATALOGUE_READ", sorted({os.path.relpath(e["file"], os.path.dirname(
                os.path.dirname(root))) for e in figs + studs}))]
    text += [figure_rule(e) for e in figs]
    text += [_words("FIGURES_WITH_PARTS", with_parts),
             f"FIGURES += {' '.join(made)}\n",
             f"REGRESS_FIGURES += {' '.join(regress)}\n",
             f"REGRESS_QUICK += {' '.join(quick)}\n"]
    for e in figs:
        if str(e.get("regress", "")).startswith("with "):
            text.append(f"REGRESS_WITH_{e['regress'][5:]} += {e['name']}\n")
    text += [_words("SUBMIT_WHOLE", whole), _words("SUBMIT_GRIDS", grids)]
    for e in studs:
        if e.get("carries"):
            carried = " ".join(f"{v}=$(call shell_quote,$({v}))" for v in e["carries"])
            text.append(f"submit-{e['name']}: SUBMIT_CARRY = {carried}\n")
    text.append(_define("HELP_FIGURES", [help_line(e["name"], e["time"], e["help"])
                                         for e in figs]))
    text.append(_define("HELP_STUDIES", [help_line(e.get("usage", e["name"]), e["time"],
                                                   e["help"]) for e in studs]))
    submit = lambda names: ", ".join(f"submit-{n}" for n in names)   # noqa: E731
    text.append(_define("HELP_SUBMIT", [
        help_line(submit(e["name"] for e in studs if e.get("grid")), "1 s",
                  "a study's grid, a job per point, then its summary"),
        help_line(submit(e["name"] for e in studs if not e.get("grid")), "1 s",
                  "a study as one job (with the RHO, MU, EOM, SET given)")]))
    return "".join(text)


def main(argv: List[str]) -> int:
    if argv != ["make"]:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        sys.stdout.write(make_text())
    except (DeclarationError, OSError, SyntaxError) as exc:
        print(f"catalogue: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
