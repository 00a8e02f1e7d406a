"""Slurm's array-index notation, both ways."""
from __future__ import annotations

from typing import List, Optional, Sequence, Tuple


def compress(indices: Sequence[int]) -> str:
    """[1, 2, 3, 7, 9, 10] -> '1-3,7,9-10'."""
    parts, indices = [], sorted(indices)
    start = previous = indices[0]
    for index in indices[1:] + [None]:
        if index is not None and index == previous + 1:
            previous = index
            continue
        parts.append(str(start) if start == previous else f"{start}-{previous}")
        if index is not None:
            start = previous = index
    return ",".join(parts)


def expand(text: str) -> List[int]:
    """'[1-3,5%2]' or '4' -> [1, 2, 3, 5] / [4]."""
    text = text.strip("[]").split("%")[0]
    indices = []
    for part in filter(None, text.split(",")):
        if "-" in part:
            low, high = part.split("-")
            indices.extend(range(int(low), int(high) + 1))
        else:
            indices.append(int(part))
    return indices


def parse_job_id(text: str) -> Tuple[Optional[str], Optional[List[int]]]:
    """'12_3' -> (12, [3]); '12_[1-4]' -> (12, [1, 2, 3, 4]); '12' -> (12, None)."""
    job, _, indices = text.strip().partition("_")
    if not job.isdigit():
        return None, None
    return job, (expand(indices) if indices else None)
