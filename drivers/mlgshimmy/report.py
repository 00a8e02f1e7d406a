"""The reproduction report: one HTML page, $MLG_RUN_ROOT/report/index.html
(default build/report/), built from what the figures left behind -- their
cached results ($MLG_RUN_ROOT/<fig>/result.json: provenance), their tables
(tables/<fig>.json, written by shared.paper.report when a figure is drawn)
and their PNGs (figures/<fig>.png, copied beside the page).  It computes
nothing and imports no figure module: a figure not yet made shows as
missing, with the command that makes it.

    make report            # or: python3 -m mlgshimmy.report [--out DIR]

A sidebar links every part. The page opens with the scorecard (every
number the paper prints, shared.paper.PAPER, once, beside ours, the
relative error and a status; the values the paper withholds,
shared.paper.HELD_OUT, with ours), then the provenance (commit, AUTO,
compilers, Python, numpy, matplotlib; folded), then one section per
figure: what the paper shows, our PNG and its table, the qualitative
features the tests check (shared.checks) with a link to the figure's
section of docs/reproduction.md, and its cached result's provenance
(folded); then the studies beyond the paper that have been run
(their tables and figures, STUDIES)."""
from __future__ import annotations

import argparse
import datetime
import html
import json
import os
import platform
import shutil
import subprocess
import sys
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import autosession, checks, gear_answers, motion, paper, provenance
from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs import catalogue
from mlgshimmy.shared.jobs.atomic import write_text

# (figure, command, what the paper shows): the order of the page; and the
# studies beyond the paper: (name, command, what, text files, figures), each
# path relative to the run root, shown when made (the side-stay runs by glob).
# Both as the figures and studies declare themselves (shared.jobs.catalogue).
FIGURES = [(e["name"], f"make {e['name']}", e["report"]) for e in catalogue.figures()]
STUDIES = [(e["name"], e["report"]["command"], e["report"]["text"], e["report"]["tables"],
            e["report"]["figures"]) for e in catalogue.studies() if "report" in e]
STATUS_CLASS = {"agrees": "good", "calibrated": "calib", "off its calibration": "bad",
                "close": "close", "off": "bad", "missing": "bad", "held out": "held"}
STATUS_TEXT = {
    "agrees": "within the digits the paper prints",
    "calibrated": "the parameter set was fitted to it (c_psi; docs/model.md section 5)",
    "off its calibration": "the parameter set was fitted to it, but ours is outside the "
                           "printed digits (the model or the parameter set changed since)",
    "close": f"outside the printed digits, relative error within {paper.CLOSE:.0%}",
    "off": f"relative error beyond {paper.CLOSE:.0%}",
    "missing": "not computed yet (run the figure's command)",
    "held out": "the paper replaces the value by a symbol: ours is shown, the paper's "
                "is not known here",
}


def _run(*command):
    try:
        proc = subprocess.run(command, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return proc.stdout.strip() if proc.returncode == 0 else None


def read_result(figure: str, root: str) -> Tuple[Optional[Dict[str, Any]], Any]:
    """(provenance, data) of a figure's cached result, or (None, None)."""
    try:
        with open(os.path.join(root, figure, "result.json")) as source:
            record = json.load(source)
    except (OSError, ValueError):
        return None, None
    return record.get("provenance") or {}, record.get("data")


def read_rows(figure: str, root: str) -> Optional[List[Dict[str, Any]]]:
    """The table rows of a figure (tables/<fig>.json), or None."""
    try:
        with open(os.path.join(root, "tables", f"{figure}.json")) as source:
            return json.load(source)["rows"]
    except (OSError, ValueError, KeyError):
        return None


def read_notes(figure: str, root: str) -> List[str]:
    """The lines under a figure's table (tables/<fig>.json: the named points,
    their criticality checked), or []."""
    try:
        with open(os.path.join(root, "tables", f"{figure}.json")) as source:
            return list(json.load(source).get("notes", []))
    except (OSError, ValueError, AttributeError):
        return []


def read_summary(figure: str, root: str) -> Optional[List[Dict[str, Any]]]:
    """Rows of a simulation summary (<fig>/summary.txt: "name value"
    lines, Fig. 8), or None."""
    try:
        with open(os.path.join(root, figure, "summary.txt")) as source:
            pairs = [line.split() for line in source if line.strip()]
    except OSError:
        return None
    rows = []
    for pair in pairs:
        if len(pair) == 2:
            try:
                value = float(pair[1])
            except ValueError:
                continue
            rows.append({"quantity": pair[0], "paper": None, "ours": value, "ours_table": None,
                         "rel_error": None, "status": None, "held_out": None})
    return rows or None


def read_extras(figure: str, root: str) -> Dict[str, Any]:
    """What a figure left beside its PNG: {"caption": the text of
    figures/<fig>_caption.txt or None, "motions": [case of
    figures/<fig>_motion.json (studies.animate --fig11) with "gif" (its
    animation, or None) and "settled" (what the simulation settled on,
    shared.motion.KINDS' words, or None)]}."""
    out = {"caption": None, "motions": []}
    try:
        with open(os.path.join(root, "figures", f"{figure}_caption.txt")) as source:
            out["caption"] = source.read()
    except OSError:
        pass
    try:
        with open(os.path.join(root, "figures", f"{figure}_motion.json")) as source:
            cases = json.load(source)
    except (OSError, ValueError):
        cases = []
    for case in cases:
        gif = os.path.join(root, "figures", f"{case['name']}.gif")
        data = read_result(case["name"], root)[1] or {}
        out["motions"].append(dict(case, gif=gif if os.path.exists(gif) else None,
                                   settled=motion.KINDS.get(data.get("kind"))))
    return out


def tools() -> List[Tuple[str, str]]:
    """[(tool, version)] of what made and drew the results, read now."""
    import matplotlib
    import numpy
    first = lambda text: text.splitlines()[0] if text else "not found"   # noqa: E731
    return [("commit (now)", provenance.git_commit() or "unknown"),
            ("AUTO-07p", f"{provenance.auto_version() or 'unknown'} ({autosession.auto_dir()})"),
            ("C compiler", first(_run("cc", "--version"))),
            ("Fortran compiler", first(_run("gfortran", "--version"))),
            ("Python", f"{platform.python_version()} ({sys.executable})"),
            ("numpy", numpy.__version__), ("matplotlib", matplotlib.__version__),
            ("system", platform.platform())]


def collect_studies(root: str) -> List[Dict[str, Any]]:
    """[{"name", "command", "what", "texts": [(path, text)], "pngs": [path],
    "notes": the lines under its table}] of the studies that were run (their
    files exist)."""
    import glob
    out = []
    for name, command, what, texts, pngs in STUDIES:
        found_texts = []
        for pattern in texts:
            for path in sorted(glob.glob(os.path.join(root, pattern))):
                with open(path) as source:
                    found_texts.append((path, source.read()))
        found_pngs = [p for pattern in pngs for p in sorted(glob.glob(os.path.join(root, pattern)))]
        out.append({"name": name, "command": command, "what": what, "texts": found_texts,
                    "pngs": found_pngs, "notes": read_notes(name, root)})
    return out


def collect(root: str) -> Dict[str, Any]:
    """Everything the page shows, as plain data (the test reads it too)."""
    figures = []
    for figure, command, shows in FIGURES:
        provenance, data = read_result(figure, root)
        png = os.path.join(root, "figures", f"{figure}.png")
        rows = read_rows(figure, root) or read_summary(figure, root)
        entry = {"figure": figure, "command": command, "shows": shows,
                 "provenance": provenance, "cached": data is not None,
                 "png": png if os.path.exists(png) else None, "rows": rows,
                 "notes": read_notes(figure, root), **read_extras(figure, root)}
        result = os.path.join(root, figure, "result.json")
        entry["stale"] = bool(entry["png"] and os.path.exists(result)
                              and os.path.getmtime(entry["png"]) < os.path.getmtime(result))
        figures.append(entry)
    by_figure = {f["figure"]: f for f in figures}

    def ours_of(figure, quantity):
        rows = by_figure.get(figure, {}).get("rows") or []
        return next((r["ours"] for r in rows if r["quantity"] == quantity), None)
    score, printed_at = [], {}
    for figure, printed in paper.PAPER.items():
        for quantity, value in printed.items():
            ours = ours_of(figure, quantity)
            row = {"figure": figure, "quantity": quantity, "paper": value, "ours": ours,
                   "rel_error": None if ours is None else (ours - value) / value,
                   "status": paper.status(figure, quantity, value, ours), "also": []}
            first = paper.REPEATS.get((figure, quantity))
            if first:    # the same printed number: one row, where it is printed first
                printed_at[first]["also"].append({"figure": figure, "quantity": quantity,
                                                  "ours": ours, "status": row["status"]})
            else:
                printed_at[(figure, quantity)] = row
                score.append(row)
    for figure, held in paper.HELD_OUT.items():
        rows = {r["quantity"]: r for r in (by_figure.get(figure, {}).get("rows") or [])}
        for quantity, symbol in held.items():
            row = rows.get(quantity)
            score.append({"figure": figure, "quantity": quantity, "paper": symbol,
                          "ours": row["ours"] if row else None, "rel_error": None,
                          "status": "held out" if row else "missing"})
    return {"figures": figures, "score": score, "tools": tools(), "studies": collect_studies(root),
            "written": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")}


def _number(value):
    if value is None:
        return "&ndash;"
    if isinstance(value, str):
        return html.escape(value)
    return f"{value:.6g}"


def _status(status):
    if not status:
        return ""
    return (f'<span class="st {STATUS_CLASS.get(status, "")}" '
            f'title="{html.escape(STATUS_TEXT.get(status, ""))}">{html.escape(status)}</span>')


def _also(row):
    """The other figures that show the same printed number, with their value."""
    return "".join(f'<br><span class="also">also <a href="#{a["figure"]}">{a["figure"]}</a> '
                   f'({html.escape(a["quantity"])}): {_number(a["ours"])}</span>'
                   for a in row.get("also", []))


def _scorecard(score):
    counts = {}
    for row in score:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    summary = ", ".join(f"{n} {s}" for s, n in counts.items())
    lines = ['<table class="score"><thead><tr><th>figure</th><th>quantity</th><th>paper</th>'
             '<th>ours</th><th>rel. error</th><th>status</th></tr></thead><tbody>']
    for row in score:
        lines.append(
            f'<tr><td><a href="#{row["figure"]}">{row["figure"]}</a>{_also(row)}</td>'
            f'<td>{html.escape(row["quantity"])}</td><td>{_number(row["paper"])}</td>'
            f'<td>{_number(row["ours"])}</td><td>{html.escape(paper.relative(row["rel_error"]))}'
            f'</td><td>{_status(row["status"])}</td></tr>')
    lines.append("</tbody></table>")
    legend = "".join(f"<li>{_status(s)} {html.escape(t)}</li>" for s, t in STATUS_TEXT.items())
    return (f"<p>{len(score)} numbers, each counted once: {html.escape(summary)}.</p>"
            + "\n".join(lines) + f'<ul class="legend">{legend}</ul>')


def _checks(figure, docs):
    """The qualitative features the tests check, and the figure's docs section."""
    heading, found = checks.CHECKS.get(figure, (None, []))
    if heading is None:
        return ""
    items = "".join(f"<li>{html.escape(feature)} <code>{html.escape(test)}</code></li>"
                    for feature, test in found)
    return (f'<div class="checks"><b>Checked by the tests</b> (discussed in <a href="{docs}#'
            f'{checks.anchor(heading)}">{checks.DOCS}: {html.escape(checks.title(heading))}</a>)'
            f"<ul>{items}</ul></div>")


def _table(rows):
    printed = any(r["paper"] is not None for r in rows)
    with_table = any(r.get("ours_table") is not None for r in rows)
    head = ["quantity"] + (["paper"] if printed else []) + ["ours"] \
        + (["ours, printed c_psi"] if with_table else []) \
        + (["rel. error", "status"] if printed else [])
    out = ['<table class="numbers"><thead><tr>' + "".join(f"<th>{h}</th>" for h in head)
           + "</tr></thead><tbody>"]
    for r in rows:
        cells = [html.escape(r["quantity"]) + (f' <span class="st held">held out: '
                                               f'{html.escape(r["held_out"])}</span>'
                                               if r.get("held_out") else "")]
        if printed:
            cells.append(_number(r["paper"]))
        cells.append(_number(r["ours"]))
        if with_table:
            cells.append(_number(r.get("ours_table")))
        if printed:
            cells += [html.escape(paper.relative(r["rel_error"])), _status(r["status"])]
        out.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    out.append("</tbody></table>")
    return "\n".join(out)


def _caption(text):
    """A caption file as HTML: paragraphs, and "- " lines as lists."""
    out = []
    for block in text.strip().split("\n\n"):
        lines = block.splitlines()
        items = [line[2:] for line in lines if line.startswith("- ")]
        rest = " ".join(line for line in lines if not line.startswith("- "))
        if rest:
            out.append(f"<p>{html.escape(rest)}</p>")
        if items:
            out.append("<ul>" + "".join(f"<li>{html.escape(i)}</li>" for i in items) + "</ul>")
    return '<div class="caption">' + "".join(out) + "</div>"


def _motions(figure, motions, images):
    """The gear's motion in each kind of region: a list linking each kind
    to its animation, then the animations."""
    links, shown = [], []
    for m in motions:
        kind = motion.KINDS[m["kind"]]
        anchor = f"{figure}-motion-{m['kind']}"
        where = (f"V = {m['V']:g} m/s, F* = {m['Fstar']:g}, in the region where it is "
                 + ("the only stable state" if m["alone"] else "one of the stable states")
                 + f" (start: {m['start']})")
        settled = (f"settled on {m['settled']}" if m["settled"] else "not simulated yet")
        flag = "" if m["settled"] in (None, kind) else ' <span class="st bad">another state</span>'
        links.append(f'<li><a href="#{anchor}">{html.escape(kind)}</a>: {html.escape(where)}; '
                     f"{html.escape(settled)}{flag}</li>")
        src = images.get(m["gif"])
        shown.append(f'<figure id="{anchor}"><img src="{html.escape(src)}" alt="{anchor}">'
                     f"<figcaption>{html.escape(kind)}: {html.escape(where)}</figcaption></figure>"
                     if src else f'<p id="{anchor}" class="missing">No animation of '
                     f"{html.escape(kind)} yet: <code>make {figure}-motion</code>.</p>")
    return ("<h3>The gear's motion in each kind of region</h3><ul>" + "".join(links) + "</ul>"
            + "".join(shown))


def _figure(entry, image, docs):
    figure = entry["figure"]
    parts = [f'<section id="{figure}"><h2>{figure}</h2>',
             f'<p class="shows"><b>Paper:</b> {html.escape(entry["shows"])}</p>',
             f'<p class="cmd"><code>{html.escape(entry["command"])}</code>']
    if not entry["provenance"] and entry["cached"] is False and \
            figure not in ("fig06", "fig08", "fig15", "fig19"):
        parts.append(" &middot; <b>no cached result</b>")
    parts.append("</p>")
    if image:
        note = (' <span class="st close">the PNG is older than the cached result: '
                f'<code>make {figure}-plot</code></span>' if entry["stale"] else "")
        parts.append(f'<figure><img src="{html.escape(image)}" alt="{figure}">'
                     f"<figcaption>ours: {figure}.png{note}</figcaption></figure>")
    else:
        parts.append(f'<p class="missing">No figure yet: run <code>{html.escape(entry["command"])}'
                     "</code>.</p>")
    if entry.get("caption"):
        parts.append(_caption(entry["caption"]))
    if entry.get("motions"):
        parts.append(_motions(figure, entry["motions"], entry.get("images", {})))
    rows = entry["rows"]
    if rows:
        printed = [r for r in rows if r["paper"] is not None or r.get("held_out")]
        rest = [r for r in rows if not (r["paper"] is not None or r.get("held_out"))]
        if printed:
            parts.append(_table(printed + (rest if len(rest) <= 12 else [])))
            rest = rest if len(rest) > 12 else []
        elif len(rest) <= 12:
            parts.append(_table(rest))
            rest = []
        if rest:
            parts.append(f"<details><summary>all {len(rest)} further numbers of this figure"
                         f"</summary>{_table(rest)}</details>")
    elif image:
        parts.append("<p>No table: the paper prints no number for this figure and the "
                     "driver writes none.</p>")
    if entry.get("notes"):
        parts.append("<ul>" + "".join(f"<li>{html.escape(line)}</li>" for line in entry["notes"])
                     + "</ul>")
    parts.append(_checks(figure, docs))
    if entry["provenance"]:
        rows = "".join(f"<tr><th>{html.escape(str(k))}</th><td>{html.escape(str(v))}</td></tr>"
                       for k, v in entry["provenance"].items())
        parts.append('<details class="prov"><summary>provenance of the cached result'
                     f'</summary><table class="tools"><tbody>{rows}</tbody></table></details>')
    parts.append("</section>")
    return "\n".join(parts)


STYLE = """
body { font-family: system-ui, sans-serif; margin: 0; line-height: 1.4; color: #222;
       display: flex; align-items: flex-start; }
nav.side { position: sticky; top: 0; height: 100vh; overflow-y: auto; flex: none; width: 12em;
           box-sizing: border-box; padding: 1em; background: #f5f6f8; border-right: 1px solid #ddd;
           font-size: 0.9em; }
nav.side a { display: block; padding: 0.1em 0; text-decoration: none; color: #1f4e8c; }
nav.side .group { margin-top: 0.8em; font-weight: bold; color: #555; }
nav.side .missing { color: #a04000; }
main { flex: 1; min-width: 0; max-width: 72em; padding: 1em 2em; }
@media (max-width: 50em) { body { display: block; }
  nav.side { position: static; height: auto; width: auto; border-right: none; } }
.caption { font-size: 0.85em; color: #333; max-width: 60em; }
.checks { font-size: 0.9em; background: #f7faf7; border-left: 3px solid #7bb07b;
          padding: 0.3em 0.8em; margin: 0.5em 0; }
.checks ul { margin: 0.2em 0; } .also { font-size: 0.8em; color: #555; }
details.prov { font-size: 0.85em; color: #555; margin: 0.4em 0; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; padding-top: 0.5em; }
img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figure { margin: 0.5em 0; } figcaption { font-size: 0.85em; color: #555; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.9em; display: block;
        overflow-x: auto; max-width: 100%; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: left; vertical-align: top; }
th { background: #f0f0f0; }
.st { padding: 0 0.4em; border-radius: 0.3em; font-size: 0.85em; white-space: nowrap; }
.good { background: #cfe3ff; } .calib { background: #e6e6e6; } .close { background: #ffe8b3; }
.bad { background: #f6c7a8; } .held { background: #eadcf0; }
ul.legend { font-size: 0.85em; } code { background: #f4f4f4; padding: 0 0.2em; }
.missing { color: #a04000; }
pre { overflow-x: auto; font-size: 0.8em; background: #f8f8f8; padding: 0.5em; }
"""


def _study(study, images):
    parts = [f'<section id="study-{study["name"]}"><h2>{html.escape(study["name"])}</h2>',
             f"<p>{html.escape(study['what'])} <code>{html.escape(study['command'])}</code></p>"]
    if study.get("notes"):   # what it found, in its numbers (the lines under its table)
        parts.append("<ul>" + "".join(f"<li>{html.escape(n)}</li>" for n in study["notes"])
                     + "</ul>")
    if not (study["texts"] or study["pngs"]):
        parts.append(f'<p class="missing">Not run: <code>{html.escape(study["command"])}</code>.'
                     "</p>")
    for path in study["pngs"]:
        src = images.get(path)
        if src:
            parts.append(f'<figure><img src="{html.escape(src)}" alt="{study["name"]}">'
                         f"<figcaption>{html.escape(os.path.basename(path))}</figcaption></figure>")
    for path, text in study["texts"]:
        parts.append(f"<details><summary>{html.escape(os.path.basename(path))}</summary>"
                     f'<pre>{html.escape(text)}</pre></details>')
    parts.append("</section>")
    return "\n".join(parts)


def _sidebar(info, at_gear=False):
    figures = "".join(f'<a href="#{f["figure"]}"' + ("" if f["png"] else
                      ' class="missing" title="not made yet"') + f'>{f["figure"]}</a>'
                      for f in info["figures"])
    studies = "".join(f'<a href="#study-{s["name"]}">{s["name"]}</a>' for s in info["studies"])
    return ('<nav class="side"><a href="#top"><b>mlg-shimmy report</b></a>'
            + ('<a href="#gear">Your gear</a>' if at_gear else '<a href="#scorecard">Scorecard</a>')
            + '<a href="#provenance">Provenance</a>'
            f'<div class="group">Figures</div>{figures}'
            f'<div class="group">Studies</div>{studies}</nav>')


def page(info: Mapping[str, Any], images: Mapping[str, str],
         docs: str = os.path.join("..", "..", checks.DOCS), lead: str = "") -> str:
    """The HTML page; docs: the link to docs/reproduction.md from it; lead:
    HTML shown first (the design answers at a changed gear).  At a changed
    gear the page shows what was made there and no scorecard: the paper's
    numbers are its own gear's, and the answers give the paper's gear beside
    each of the changed gear's."""
    if lead:
        info = {**info, "figures": [f for f in info["figures"] if f["png"]],
                "studies": [st for st in info["studies"] if st["texts"] or st["pngs"]]}
    score = "" if lead else (
        '<h2 id="scorecard">Scorecard: every number the paper prints</h2>\n'
        + _scorecard(info["score"]))
    tools = "".join(f"<tr><th>{html.escape(k)}</th><td>{html.escape(str(v))}</td></tr>"
                    for k, v in info["tools"])
    commits = sorted({f["provenance"].get("git_commit") or "unknown"
                      for f in info["figures"] if f["provenance"]})
    sections = "\n".join(_figure(f, images.get(f["figure"]), docs) for f in info["figures"])
    studies = "\n".join(_study(st, images) for st in info["studies"])
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>mlg-shimmy: reproduction report</title><style>{STYLE}</style></head>
<body>
{_sidebar(info, bool(lead))}
<main>
<h1 id="top">mlg-shimmy: {"your gear" if lead else "reproduction report"}</h1>
{lead}
<p>Howcroft, Lowenberg, Neild and Krauskopf, <i>Effects of freeplay on the dynamic stability
of an aircraft main landing gear</i>: {"the figures made at your gear" if lead else
"every figure beside the numbers the paper prints"}.
Generated {html.escape(info["written"])} by <code>make report</code> from the cached results;
nothing here is copied by hand. All figures use our calibrated parameter set: Table 1's,
except the torsional damping c_psi = 724.0034 N m s/rad (instead of 410), calibrated so that
the zero-freeplay Hopf point at F* = 1 lies at the paper's 346.1 m/s
(docs/model.md, section 5; <code>make calibrate</code> recomputes it).</p>
{score}
<h2 id="provenance">Provenance</h2>
<details><summary>the tools that made and drew the results, and the commits of the cached
results</summary>
<table class="tools"><tbody>{tools}
<tr><th>commits of the cached results</th><td>{html.escape(", ".join(commits) or "none")}</td></tr>
</tbody></table></details>
{sections}
<h2 id="studies">Studies beyond the paper</h2>
<p>Computed by the project's own studies, not compared with the paper; shown when they have
been run.</p>
{studies}
</main>
</body></html>
"""


def build(out: Optional[str] = None, root: Optional[str] = None) -> str:
    """Write the page and its images; returns the page's path.  At a
    changed gear it opens with the design answers (shared.gear_answers)."""
    root = root or paths.run_root()
    out = out or os.path.join(root, "report")
    os.makedirs(os.path.join(out, "figures"), exist_ok=True)
    info = collect(root)
    images = {}
    for entry in info["figures"]:
        if entry["png"]:
            target = os.path.join(out, "figures", f"{entry['figure']}.png")
            shutil.copyfile(entry["png"], target)
            images[entry["figure"]] = f"figures/{entry['figure']}.png"
        entry["images"] = {}
        for gif in (m["gif"] for m in entry["motions"] if m["gif"]):
            shutil.copyfile(gif, os.path.join(out, "figures", os.path.basename(gif)))
            entry["images"][gif] = f"figures/{os.path.basename(gif)}"
    for study in info["studies"]:
        for path in study["pngs"]:
            name = os.path.basename(path)
            shutil.copyfile(path, os.path.join(out, "figures", name))
            images[path] = f"figures/{name}"
    target = os.path.join(out, "index.html")
    lead = gear_answers.section()
    write_text(target, page(info, images, os.path.relpath(os.path.join(paths.ROOT, checks.DOCS),
                                                          out), lead))
    write_text(os.path.join(out, "report.json"),
               json.dumps({k: v for k, v in info.items()}, indent=1, default=str) + "\n")
    missing = [f["figure"] for f in info["figures"] if not f["png"]]
    made = sum(1 for f in info["figures"] if f["png"])
    print(f"report: wrote {os.path.relpath(target, paths.ROOT)} " + (
        f"(your gear: {made} figures made there)" if lead else
        f"({len(info['score'])} scorecard rows, {len(images)} figures"
        + (f"; missing: {' '.join(missing)}" if missing else "") + ")"))
    return target


def main(argv: Optional[Sequence[str]] = None) -> None:
    parser = argparse.ArgumentParser(prog="python3 -m mlgshimmy.report",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--out", help="directory of the page (default $MLG_RUN_ROOT/report)")
    args = parser.parse_args(argv)
    build(args.out)


if __name__ == "__main__":
    main()
