"""Write a sweep as a table: CSV (long format, one row per point) or JSON.

Columns: each swept given, then each find, with its unit in the header (``m_b [kg]``,
``alpha [rad/s^2]``), a find's direction where one is stated, the regime, how the point
was answered (``closed form`` or ``per point``) and, where a point has no answer, why.
Numbers carry full precision (``repr``); a point without a value is an empty cell (null
in JSON). Text cells are written safely for spreadsheets (:func:`dynsolve.safe_csv.escape_cell`).

>>> import numpy as np
>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.parametric.evaluate import sweep_points
>>> from dynsolve.parametric.ranges import Axis
>>> text = "given:\\n  m = 2 kg\\n  F = 10 N\\nequations:\\n  F = m*a\\nfind: a"
>>> spec = parse_spec(text, "p.dyn")
>>> axis = Axis("m", "kg", np.array([1.0, 4.0]), 1.0)
>>> csv_text(sweep_points(spec, (axis,), (axis.values,), (2,))).splitlines()
['m [kg],a [m/s^2],regime,path', '1.0,10.0,,closed form', '4.0,2.5,,closed form']
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterator

from dynsolve import safe_csv
from dynsolve.parametric.evaluate import Sweep


def header(name: str, unit: str) -> str:
    """A column's header: the name and, when it has one, the unit in brackets."""
    return f"{name} [{unit}]" if unit else name


def columns(result: Sweep) -> list[str]:
    """The table's headers, in order."""
    names = [header(axis.name, axis.unit) for axis in result.axes]
    for answer in result.answers:
        names.append(header(answer.name, answer.unit))
        if answer.directions:
            names.append(f"{answer.name} direction")
    names += ["regime", "path"]
    return names + (["note"] if result.notes else [])


def rows(result: Sweep) -> Iterator[list[float | str | None]]:
    """Each point's cells (numbers as floats, None where there is no value)."""
    givens = [result.givens[axis.name].tolist() for axis in result.axes]
    answers = [(answer.values.tolist(), answer.directions) for answer in result.answers]
    for i in range(result.size):
        row: list[float | str | None] = [column[i] for column in givens]
        for values, directions in answers:
            row.append(values[i] if math.isfinite(values[i]) else None)
            if directions:
                row.append(directions[i])
        row += [result.regimes[i], result.paths[i]]
        if result.notes:
            row.append(result.notes.get(i, ""))
        yield row


def csv_text(result: Sweep) -> str:
    """The table as CSV text, every cell escaped against formula injection."""
    cells = (
        ["" if cell is None else repr(cell) if isinstance(cell, float) else cell for cell in row]
        for row in rows(result)
    )
    return safe_csv.csv_text([columns(result), *cells])


def json_text(result: Sweep) -> str:
    """The table as JSON: the problem, the columns (name, unit), one object per point and
    how many points each path answered."""
    names = columns(result)
    units = {header(a.name, a.unit): a.unit for a in (*result.axes, *result.answers)}
    document = {
        "problem": result.file,
        "title": result.title,
        "shape": list(result.shape),
        "columns": [{"name": name, "unit": units.get(name, "")} for name in names],
        "points": [dict(zip(names, row, strict=True)) for row in rows(result)],
        "paths": result.counts(),
        "per_point_reasons": list(result.reasons),
    }
    return json.dumps(document, indent=1, ensure_ascii=False) + "\n"
