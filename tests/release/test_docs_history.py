"""The docs explain what is done and why, not how it was found: git keeps
the history.  A phrase that narrates it ("used to", "first version",
"earlier run", "this session", ...) fails here, naming file and line.

Run: /usr/bin/python3 -m pytest -q tests/release/test_docs_history.py
"""
import pathlib
import re

import helpers

ROOT = pathlib.Path(helpers.ROOT)
HISTORY = re.compile(r"\b(used to|first version|earlier run|before this|this session|same session|"
                     r"was found|at first|previously|no longer a band|as it was drawn)\b", re.I)


def history(text):
    """(line number, phrase) of each narrating phrase."""
    return [(n, m.group(0)) for n, line in enumerate(text.splitlines(), 1)
            for m in HISTORY.finditer(line)]


def test_no_doc_narrates_its_history():
    pages = sorted((ROOT / "docs").glob("*.md")) + [ROOT / "README.md",
                                                   ROOT / "drivers" / "README.md"]
    found = [f"{page.relative_to(ROOT)}:{n}: {phrase}"
             for page in pages for n, phrase in history(page.read_text())]
    assert not found, "history prose (git keeps it):\n  " + "\n  ".join(found)


def test_the_check_sees_a_narrating_phrase():
    assert history("ok\nThe scan used to start at 0.005 mm.\nIn an earlier run: 7 s.") == \
        [(2, "used to"), (3, "earlier run")]
    assert history("The scan starts at zero freeplay; the prototype tested it.") == []
