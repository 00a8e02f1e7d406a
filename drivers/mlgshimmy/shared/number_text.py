"""A number as a user types it on make's command line (RHO, MU, SET, a
grid's axis): plain ASCII decimal syntax only.  Python's float() also takes
'1_0' and non-ASCII digits ('١٠') as 10, which a typo should not become.
Standard library only: make reads it before anything is installed."""
import re
from typing import Optional

PLAIN = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
SYNTAX = "ASCII digits with an optional sign, '.' and exponent, e.g. 10, -2.5, 3.51e7"


def parse(text: str) -> Optional[float]:
    """The value of text (blanks around it allowed), None unless it is plain."""
    text = text.strip()
    return float(text) if PLAIN.fullmatch(text) else None
