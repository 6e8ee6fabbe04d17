"""Read a class's answers CSV, as written by hand or exported by Canvas, Gradescope or Moodle.

The delimiter (``,`` ``;`` or tab; an Excel ``sep=`` first line) and the decimal mark
(``4,52``) are detected from the file. The student id column is the first of
:data:`ID_HEADERS` present whose every row is filled (else the first present). Answer
columns are headed by a find's name, optionally with the unit bare numbers are graded
in, ``alpha [rad/s^2]`` or ``alpha (rad/s^2)``, optionally after an LMS prefix ending in
a colon (``123456: alpha [rad/s^2]``, ``1: T (N)``). When no column is named so,
numbered columns (``Response 1``, ``Answer 2``, ``Q3``: Moodle's responses report) are
matched to the finds in their order, with a warning saying so. Other columns are named in
one warning and ignored; a find without a column is graded "missing" for everyone, with
a warning. LMS rows that are no student (Canvas's ``Points Possible`` and Test Student,
Moodle's ``Overall average``) are skipped. The file is only read.

>>> import io
>>> sheet = read_answers(io.StringIO("student,a [m/s^2],x\\ns1,4.52,1\\n"), ["a", "T"], "a.csv")
>>> sheet.columns, sheet.units["a"], sheet.rows[0]
({'a': 'a [m/s^2]'}, 'm/s^2', ('s1', {'a': '4.52'}))
>>> print("\\n".join(sheet.warnings))
a.csv: column 'x' is not a find of the problem (finds: a, T); ignored
a.csv: no column for T: graded 'missing' for everyone
>>> moodle = "Surname;ID number;Response 1\\nDoe;u1;4,52 m/s^2\\n"
>>> sheet = read_answers(io.StringIO(moodle), ["a"], "m.csv")
>>> sheet.rows, sheet.decimal_comma
((('u1', {'a': '4,52 m/s^2'}),), True)
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, TextIO

from dynsolve.errors import DynsolveError, Position, SpecError
from dynsolve.grade.forms import normalise_unit
from dynsolve.grade.semantics import Key
from dynsolve.quantities import resolve_unit, unit_info
from dynsolve.spec.parser import parse_unit_at
from dynsolve.units import natural_unit

# Id headers, most specific first (lowercase). Canvas: SIS User ID, SIS Login ID (its
# 'Student' column holds names), quiz reports sis_id; Gradescope: SID, Email; Moodle:
# ID number, Username, Email address; dynsolve's own: student, student_id, id.
ID_HEADERS = (
    "sis user id",
    "sis_user_id",
    "sis_id",
    "sis login id",
    "student id",
    "student_id",
    "studentid",
    "student number",
    "sid",
    "id number",
    "idnumber",
    "username",
    "login id",
    "student",
    "id",
    "email address",
    "email",
    "e-mail",
)
SIS_HEADERS = ("sis user id", "sis_user_id", "sis_id", "sis login id")
OWN_HEADERS = ("student", "id", "student_id")
# Rows that are no student: Canvas's points row and its Test Student, Moodle's average.
SUMMARY_ROWS = ("points possible", "student, test", "test student", "overall average")
DELIMITERS = (",", ";", "\t")
MAX_ROWS = 1_000_000
SAMPLE_ROWS = 2000  # rows looked at to tell a decimal comma from a decimal point
SHOWN_IGNORED = 8  # ignored columns named in the warning
_HEADER = re.compile(
    r"^\s*(?:[^:\[\]()]*:\s*)?([A-Za-z][A-Za-z0-9_]*)\s*(?:\[(.*)\]|\((.*)\))?\s*$"
)
_NUMBERED = re.compile(r"^\s*(?:response|answer|question|q)\s*\.?\s*(\d+)\s*$", re.IGNORECASE)
_COMMA_NUMBER = re.compile(r"^\s*[-+\u2212]?\d+,(?!\d{3}(?:\D|$))\d+")
_POINT_NUMBER = re.compile(
    r"^\s*[-+\u2212]?(?:0|\d{4,})?\.\d+|^\s*[-+\u2212]?\d+\.(?!\d{3}(?:\D|$))\d+"
)


@dataclass(frozen=True)
class AnswerSheet:
    """The answers file as read: rows of (student, {find: cell}), header units, warnings."""

    rows: tuple[tuple[str, dict[str, str]], ...]
    columns: dict[str, str]  # find -> header as written
    units: dict[str, str]  # find -> unit of bare numbers ("" for none)
    warnings: tuple[str, ...]
    decimal_comma: bool = False  # the file writes 4,52
    unit_columns: dict[str, int] = field(default_factory=dict)  # find -> column of its unit
    id_header: str = "student"


def read_answers(stream: TextIO, finds: Sequence[str], name: str) -> AnswerSheet:
    """Read ``stream`` (CSV text named ``name`` in errors) against the problem's ``finds``."""
    text = stream.read()
    delimiter, skipped = _delimiter(text)
    reader = csv.reader(io.StringIO(text), delimiter=delimiter)
    try:
        for _ in range(skipped):
            next(reader, None)
        records = list(_records(reader, name))
    except csv.Error as error:  # a NUL byte, a field over the size limit, a broken quote
        raise SpecError(
            f"the answers file is not readable CSV: {error}",
            Position(name, reader.line_num or 1, 1),
            "save it as plain CSV (UTF-8, comma-separated)",
        ) from None
    if not records:
        raise SpecError("the answers file is empty", Position(name, 1, 1), "add a header row")
    (_, header), body = records[0], records[1:]
    body = [(line, r) for line, r in body if not _summary(r)]
    id_index = _id_column(header, [r for _, r in body], name)
    columns, units, unit_columns, warnings = _header(header, id_index, finds, name)
    rows: list[tuple[str, dict[str, str]]] = []
    seen: dict[str, int] = {}
    for line, record in body:
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
    comma = _decimal_comma(rows)
    if comma:
        warnings.append(f"{name}: numbers are written with a decimal comma (4,52): read so")
    if header[id_index].strip().lower() not in OWN_HEADERS:
        warnings.append(f"{name}: student ids from the column '{header[id_index].strip()}'")
    shown = {f: header[i].strip() for f, i in columns.items()}
    id_header = header[id_index].strip()
    return AnswerSheet(tuple(rows), shown, units, tuple(warnings), comma, unit_columns, id_header)


def check_header_units(sheet: AnswerSheet, keys: Mapping[str, Key], name: str) -> None:
    """Stop on a header unit of another dimension than its find's (``a [N]``): its bare
    numbers would all be graded 'dimension'."""
    for find, unit in sheet.units.items():
        key = keys.get(find)
        if not unit or key is None:
            continue
        dim = unit_info(unit).dim
        if dim != key.dim:
            example = key.unit or natural_unit(key.dim, "SI")
            raise SpecError(
                f"column '{sheet.columns[find]}': {unit} is {dim.name}, but {find} is "
                f"{key.dim.name} ({key.unit})",
                Position(name, 1, sheet.unit_columns.get(find, 1)),
                f"head the column '{find} [{example}]'",
            )


def _delimiter(text: str) -> tuple[str, int]:
    """The delimiter, from an Excel ``sep=X`` first line or the header's unquoted
    delimiters (the most frequent; a comma on a tie), and the lines to skip."""
    first = text.split("\n", 1)[0].strip()
    if first.lower().startswith("sep=") and len(first) == 5:
        return first[4], 1
    counts = dict.fromkeys(DELIMITERS, 0)
    quoted = False
    for char in first:
        if char == '"':
            quoted = not quoted
        elif not quoted and char in counts:
            counts[char] += 1
    best = max(DELIMITERS, key=lambda d: counts[d])
    return (best if counts[best] > counts[","] else ","), 0


def _records(reader: Any, name: str) -> Iterator[tuple[int, list[str]]]:
    """Each non-blank record with the line it starts on (the header's included)."""
    count = 0
    line = reader.line_num + 1
    for record in reader:
        if any(cell.strip() for cell in record):
            count += 1
            if count > MAX_ROWS + 1:
                raise SpecError(f"more than {MAX_ROWS} rows", Position(name, line, 1), "split it")
            yield line, record
        line = reader.line_num + 1


def _summary(record: list[str]) -> bool:
    """An LMS row that is no student (:data:`SUMMARY_ROWS` in one of its first cells)."""
    return any(cell.strip().lower() in SUMMARY_ROWS for cell in record[:3])


def _id_column(header: list[str], body: list[list[str]], name: str) -> int:
    lowered = [h.strip().lower() for h in header]
    present = [h for h in ID_HEADERS if h in lowered]
    if any(h in present for h in SIS_HEADERS) and "student" in present:
        present.remove("student")  # Canvas: 'Student' holds names
    if not present:
        raise SpecError(
            "no student id column",
            Position(name, 1, 1),
            "name one column 'student' or 'id' (LMS exports: 'SIS User ID', 'Student ID', "
            "'SID', 'ID number', 'Username', 'Email address' and others; docs/grading.md)",
        )
    indices = [lowered.index(h) for h in present]
    for index in indices:
        if all(index < len(r) and r[index].strip() for r in body):
            return index
    return indices[0]


def _header(
    header: list[str], id_index: int, finds: Sequence[str], name: str
) -> tuple[dict[str, int], dict[str, str], dict[str, int], list[str]]:
    columns: dict[str, int] = {}
    units: dict[str, str] = {}
    unit_columns: dict[str, int] = {}
    ignored: list[str] = []
    numbered: dict[int, int] = {}  # the number of 'Response N' -> its index
    column = 1
    for index, text in enumerate(header):
        if index != id_index:
            match = _HEADER.match(text)
            find = match[1] if match else ""
            unit, where = ("", 0)
            if match and find in finds:
                unit, where = _header_unit(match, text, name, column)
            if find not in finds or unit is None:
                number = _NUMBERED.match(text)
                if number and int(number[1]) not in numbered:
                    numbered[int(number[1])] = index
                else:
                    ignored.append(text.strip())
            elif find in columns:
                raise SpecError(f"two columns for {find}", Position(name, 1, column), "")
            else:
                columns[find], units[find], unit_columns[find] = index, unit, where
        column += len(text) + 1
    warnings: list[str] = []
    if not columns and numbered:
        pairs = []
        for number, index in sorted(numbered.items()):
            if number <= len(finds):
                columns[finds[number - 1]], units[finds[number - 1]] = index, ""
                pairs.append(f"'{header[index].strip()}' -> {finds[number - 1]}")
            else:
                ignored.append(header[index].strip())
        warnings.append(
            f"{name}: columns matched to the finds in their order: {', '.join(pairs)}; "
            "check that the quiz asks them in this order; bare numbers in them have no "
            "unit: to give them one, head every answer column by its find and unit "
            f"('{finds[0]} [unit]', ...)"
        )
    else:
        ignored += [header[i].strip() for i in numbered.values()]
    if ignored:
        warnings.insert(0, _ignored(ignored, finds, name))
    for find in finds:
        if find not in columns:
            warnings.append(f"{name}: no column for {find}: graded 'missing' for everyone")
    return columns, units, unit_columns, warnings


def _header_unit(match: re.Match[str], text: str, name: str, column: int) -> tuple[str | None, int]:
    """The unit of a header and its column: ``[unit]`` must be a unit (else the run
    stops); ``(text)`` that is no unit (``(1.0 pts)``) makes the column no answer (None)."""
    bracketed, parenthesised = match[2], match[3]
    written = bracketed if bracketed is not None else parenthesised
    if written is None or not written.strip():
        return "", 0
    where = column + max(text.find("[" if bracketed is not None else "("), 0)
    try:
        unit = normalise_unit(written.strip())
        resolve_unit(parse_unit_at(unit, name, 1, where), name)
    except (DynsolveError, ValueError) as error:
        if bracketed is None:
            return None, 0
        if isinstance(error, ValueError):
            raise SpecError(str(error), Position(name, 1, where + 1), "e.g. 'a [m/s^2]'") from None
        raise
    return unit, where + 1


def _ignored(columns: list[str], finds: Sequence[str], name: str) -> str:
    if len(columns) == 1:
        return (
            f"{name}: column '{columns[0]}' is not a find of the problem "
            f"(finds: {', '.join(finds)}); ignored"
        )
    shown = ", ".join(f"'{c}'" for c in columns[:SHOWN_IGNORED])
    more = f" and {len(columns) - SHOWN_IGNORED} more" if len(columns) > SHOWN_IGNORED else ""
    return (
        f"{name}: {len(columns)} columns are not finds of the problem "
        f"(finds: {', '.join(finds)}); ignored: {shown}{more}"
    )


def _decimal_comma(rows: list[tuple[str, dict[str, str]]]) -> bool:
    """Whether the answers write decimals with a comma: more cells like ``4,52`` than
    like ``4.52`` (``1,060`` and ``1.060`` could be either, and are not counted)."""
    commas = points = 0
    for _, cells in rows[:SAMPLE_ROWS]:
        for cell in cells.values():
            commas += bool(_COMMA_NUMBER.match(cell))
            points += bool(_POINT_NUMBER.match(cell))
    return commas > points
