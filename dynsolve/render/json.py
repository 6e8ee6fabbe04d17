"""Render a solution as JSON: full precision, every unit a string pint can parse.

>>> from dynsolve.results import Solution
>>> empty = Solution("f.dyn", "T", "", "SI", "equations", (), (), (), (), (), (), "solved")
>>> render_json(empty).splitlines()[1]
'  "title": "T",'
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict
from typing import Any

from dynsolve.results import Solution

# 2: givens' "si" became "base" (the system's base units); 3: checks and assumptions have a
# "status": "passed", "failed" or "not_run" (could not run or decide; "passed" is then false)
SCHEMA_VERSION = 3


def solution_dict(solution: Solution) -> dict[str, Any]:
    """The solution as plain JSON-ready data (``value`` keeps full float precision)."""
    return {
        "title": solution.title,
        "file": solution.file,
        "source": solution.source,
        "units": solution.system,
        "mode": solution.mode,
        "status": solution.status,
        "passed": solution.passed,
        "givens": [asdict(g) for g in solution.givens],
        "equations": [asdict(e) for e in solution.equations],
        "steps": [asdict(s) for s in solution.steps],
        "answers": [
            {
                "name": a.name,
                "value": a.value,
                "unit": a.unit,
                "shown": a.shown,
                "exact": a.formula,
                "latex": a.latex,
                "direction": a.direction,
            }
            for a in solution.answers
        ],
        "checks": [
            {"name": c.name, "status": c.status, "passed": c.passed, "detail": c.detail}
            for c in solution.checks
        ],
        "key": [asdict(k) for k in solution.key],
        "free_body": [asdict(b) for b in solution.free_body],
        "assumptions": [
            {"name": a.name, "status": a.status, "holds": a.holds, "detail": a.detail}
            for a in solution.assumptions
        ],
        "messages": list(solution.messages),
        "warnings": list(solution.warnings),
        "remarks": [r.text for r in solution.remarks],
        "trials": [asdict(trial) for trial in solution.trials],
        "energy": [asdict(term) for term in solution.energy],
        "second_moments": [asdict(row) for row in solution.second_moments],
        "schema": SCHEMA_VERSION,
    }


def render_json(solution: Solution) -> str:
    """The solution as an indented, strict JSON document (no ``Infinity`` or ``NaN``)."""
    data = _finite(solution_dict(solution))
    return json.dumps(data, indent=2, ensure_ascii=False, allow_nan=False) + "\n"


def _finite(data: Any) -> Any:
    """``data`` with every infinite or nan float replaced by ``None``.

    >>> _finite({"v": [1.5, float("inf")], "n": float("nan")})
    {'v': [1.5, None], 'n': None}
    """
    if isinstance(data, float):
        return data if math.isfinite(data) else None
    if isinstance(data, dict):
        return {key: _finite(value) for key, value in data.items()}
    if isinstance(data, list | tuple):
        return [_finite(value) for value in data]
    return data
