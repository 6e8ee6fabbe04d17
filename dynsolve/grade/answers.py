"""Read a class's answers CSV: a student id column and one column per find.

Headers are ``student`` (or ``id``, ``student_id``) and find names, optionally with the
unit bare numbers are graded in: ``alpha [rad/s^2]``. Unknown columns are named in a
warning and ignored; a find without a column is graded "missing" for everyone, with a
warning. The file is only read.

>>> import io
>>> sheet = read_answers(io.StringIO("student,a [m/s^2],x\\ns1,4.52,1\\n"), ["a", "T"], "a.csv")
>>> sheet.columns, sheet.units["a"], sheet.rows[0]
({'a': 'a [m/s^2]'}, 'm/s^2', ('s1', {'a': '4.52'}))
>>> print("\\n".join(sheet.warnings))
a.csv: column 'x' is not a find of the problem (finds: a, T); ignored
a.csv: no column for T: graded 'missing' for everyone
"""

from __future__ import annotations

import csv
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, TextIO

from dynsolve.errors import DynsolveError, Position, SpecError
from dynsolve.spec.parser import parse_unit_at

ID_HEADERS = ("student", "id", "student_id")
MAX_ROWS = 1_000_000
_HEADER = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*(?:\[(.*)\])?\s*$")


@dataclass(frozen=True)
class AnswerSheet:
    """The answers file as read: rows of (student, {find: cell}), header units, warnings."""

    rows: tuple[tuple[str, dict[str, str]], ...]
    columns: dict[str, str]  # find -> header as written
    units: dict[str, str]  # find -> unit of bare numbers ("" for none)
    warnings: tuple[str, ...]


def read_answers(stream: TextIO, finds: Sequence[str], name: str) -> AnswerSheet:
    """Read ``stream`` (CSV text named ``name`` in errors) against the problem's ``finds``."""
    reader = csv.reader(stream)
    try:
        return _read(reader, finds, name)
    except csv.Error as error:  # a NUL byte, a field over the size limit, a broken quote
        raise SpecError(
            f"the answers file is not readable CSV: {error}",
            Position(name, reader.line_num or 1, 1),
            "save it as plain CSV (UTF-8, comma-separated)",
        ) from None


def _read(reader: Any, finds: Sequence[str], name: str) -> AnswerSheet:
    header = next(reader, None)
    if not header:
        raise SpecError("the answers file is empty", Position(name, 1, 1), "add a header row")
    id_index, columns, units, warnings = _header(header, finds, name)
    rows: list[tuple[str, dict[str, str]]] = []
    seen: dict[str, int] = {}
    for line, record in enumerate(reader, start=2):
        if not any(cell.strip() for cell in record):
            continue
        if len(rows) >= MAX_ROWS:
            raise SpecError(f"more than {MAX_ROWS} rows", Position(name, line, 1), "split it")
        raw = record[id_index] if id_index < len(record) else ""
        student = raw.strip()
        if raw.strip(" ") != student:  # a tab, a line break, a no-break space: said, not hidden
            warnings.append(
                f"{name}:{line}: student id {raw!r} has a tab or other blank around it; "
                f"read as '{student}'"
            )
        if not student:
            raise SpecError("a row without a student id", Position(name, line, 1), "fill it in")
        if student in seen:
            raise SpecError(
                f"student '{student}' appears twice (first on line {seen[student]})",
                Position(name, line, 1),
                "keep one row per student",
            )
        seen[student] = line
        cells = {f: record[i] if i < len(record) else "" for f, i in columns.items()}
        rows.append((student, cells))
    shown = {f: header[i].strip() for f, i in columns.items()}
    return AnswerSheet(tuple(rows), shown, units, tuple(warnings))


def _header(
    header: list[str], finds: Sequence[str], name: str
) -> tuple[int, dict[str, int], dict[str, str], list[str]]:
    lowered = [h.strip().lower() for h in header]
    id_index = next((lowered.index(h) for h in ID_HEADERS if h in lowered), -1)
    if id_index < 0:
        raise SpecError(
            "no student id column", Position(name, 1, 1), "name one column 'student' or 'id'"
        )
    columns: dict[str, int] = {}
    units: dict[str, str] = {}
    warnings: list[str] = []
    column = 1
    for index, text in enumerate(header):
        match = _HEADER.match(text)
        if index != id_index:
            if match is None or match[1] not in finds:
                warnings.append(
                    f"{name}: column '{text.strip()}' is not a find of the problem "
                    f"(finds: {', '.join(finds)}); ignored"
                )
            elif match[1] in columns:
                raise SpecError(f"two columns for {match[1]}", Position(name, 1, column), "")
            else:
                columns[match[1]] = index
                units[match[1]] = _unit(match[2] or "", name, column + text.find("["))
        column += len(text) + 1
    for find in finds:
        if find not in columns:
            warnings.append(f"{name}: no column for {find}: graded 'missing' for everyone")
    return id_index, columns, units, warnings


def _unit(text: str, name: str, offset: int) -> str:
    """A header's unit, checked now so that a typo stops the run before any grading."""
    if not text.strip():
        return ""
    from dynsolve.quantities import resolve_unit

    try:
        resolve_unit(parse_unit_at(text.strip(), name, 1, offset), name)
    except DynsolveError:
        raise
    return text.strip()
