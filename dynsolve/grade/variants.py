"""The variants file: write and read each student's givens (CSV), bounded and positioned.

Format: a header ``student,units,NAME,...`` then one row per student; a cell holds a
given's value with its unit as a spec would write it (``45 kg``); an empty cell keeps the
spec's value. ``units`` is the system a row's values are in: ``SI``, or ``US`` (US
customary: a variant drawn from an FPS spec, or a twin, whose id is the student's id
followed by ``@US``).

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "v.csv"
>>> rows = [VariantRow("s01", "SI", {"m": "45 kg"}),
...         VariantRow("s01@US", "US", {"m": "3.083 slug"})]
>>> write_variants(path, rows, ("m",))
>>> read_variants(path)
{'s01': {'m': '45 kg'}, 's01@US': {'m': '3.083 slug'}}
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from dynsolve.errors import Position, SpecError
from dynsolve.files import read_capped, write_text
from dynsolve.safe_csv import csv_text, unescape_cell

MAX_BYTES = 64 * 1024 * 1024
MAX_ROWS = 200_000
MAX_CELL = 200
MAX_ID = 64
ID_COLUMNS = ("student", "student_id", "id")
TWIN_SUFFIX = "@US"


class CsvError(SpecError):
    """A roster or variants file is malformed (its position names the row)."""


@dataclass(frozen=True)
class VariantRow:
    """One row of the variants file: a student (or a US twin) and their givens."""

    student: str
    units: str  # "SI" or "US"
    cells: Mapping[str, str]


def write_variants(path: Path, rows: Iterable[VariantRow], names: Sequence[str]) -> None:
    """Write the rows, with a column per given in ``names`` (atomic, as every output)."""
    table = [(row.student, row.units, *(row.cells.get(n, "") for n in names)) for row in rows]
    write_text(path, csv_text([("student", "units", *names), *table]))


@dataclass(frozen=True)
class VariantTable:
    """A variants file as read: each student's cells, and where each cell and header is."""

    path: str
    cells: dict[str, dict[str, str]]  # student -> {given: cell text}, empty cells left out
    lines: dict[str, tuple[int, list[int]]]  # student -> their line, each cell's column
    columns: dict[str, int]  # given -> its index in a row (and in the header)
    header: list[int]  # the header cells' columns

    def where(self, student: str, given: str) -> Position:
        """The position of ``student``'s cell of ``given``."""
        line, columns = self.lines[student]
        return Position(self.path, line, columns[self.columns[given]])

    def heading(self, given: str) -> Position:
        """The position of ``given``'s header."""
        return Position(self.path, 1, self.header[self.columns[given]])


def read_variants(path: str | Path) -> dict[str, dict[str, str]]:
    """Each student's (or twin's) id → {given name: cell text}; empty cells are left out."""
    return read_variant_table(path).cells


def read_variant_table(path: str | Path) -> VariantTable:
    """The variants file with the position of every cell (for errors that point at it).

    >>> import pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "v.csv"
    >>> _ = path.write_text("student,units,m,r\\ns1,SI,45 kg,0.4 m\\n")
    >>> table = read_variant_table(path)
    >>> str(table.where("s1", "r")).split(":", 1)[1], str(table.heading("m")).split(":", 1)[1]
    ('2:13', '1:15')
    """
    header, top, rows = _read_table(path, "variants")
    named = [(i, h) for i, h in enumerate(header) if i > 0 and h != "units"]
    out: dict[str, dict[str, str]] = {}
    lines: dict[str, tuple[int, list[int]]] = {}
    for line, row, columns in rows:
        student = _student(row[0], path, line, out)
        out[student] = {h: row[i] for i, h in named if row[i]}
        lines[student] = (line, columns)
    return VariantTable(str(path), out, lines, {h: i for i, h in named}, top)


def read_roster(path: str | Path) -> list[str]:
    """The student ids of a roster CSV: the column headed student/student_id/id, else the
    first column; other columns (names, emails) are ignored.

    >>> import pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "roster.csv"
    >>> _ = path.write_text("name,id\\nAda,s1\\nBen,s2\\n")
    >>> read_roster(path)
    ['s1', 's2']
    """
    header, _, rows = _read_table(path, "roster")
    lowered = [h.lower() for h in header]
    column = next((lowered.index(c) for c in ID_COLUMNS if c in lowered), 0)
    seen: dict[str, None] = {}
    for line, row, _ in rows:
        seen[_student(row[column], path, line, seen)] = None
    if not seen:
        raise CsvError(f"{path} lists no students", Position(str(path), 1, 1), "add rows")
    return list(seen)


def _student(text: str, path: str | Path, line: int, seen: Mapping[str, object]) -> str:
    student = text.strip()
    where = Position(str(path), line, 1)
    if not student or len(student) > MAX_ID or not student.isprintable():
        raise CsvError(
            f"a student id must be 1 to {MAX_ID} printable characters, got {student[:20]!r}",
            where,
            hint="fix the id in the first column",
        )
    if student in seen:
        raise CsvError(f"student '{student}' appears twice", where, "keep one row per student")
    return student


def _read_table(
    path: str | Path, what: str
) -> tuple[list[str], list[int], list[tuple[int, list[str], list[int]]]]:
    """The header and its cells' columns, and the non-empty rows, each with its line and
    its cells' columns."""
    raw = read_capped(path, MAX_BYTES)
    where = Position(str(path), 1, 1)
    if len(raw) > MAX_BYTES:
        raise CsvError(f"the {what} file is over {MAX_BYTES} bytes", where, "split the class")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise CsvError(f"the {what} file is not UTF-8 text", where, "save it as UTF-8") from None
    lines = text.split("\n")
    reader = csv.reader(io.StringIO(text, newline=""))
    try:
        header = [h.strip() for h in next(reader)]
    except (StopIteration, csv.Error):
        raise CsvError(f"the {what} file is empty", where, "write a header row") from None
    if not header or not header[0]:
        raise CsvError(f"the {what} file has no header", where, "first row: student,...")
    rows = []
    try:
        for row in reader:
            line = reader.line_num
            if not any(cell.strip() for cell in row):
                continue
            if len(rows) >= MAX_ROWS:
                raise CsvError(f"more than {MAX_ROWS} rows", Position(str(path), line, 1), "")
            if len(row) != len(header):
                raise CsvError(
                    f"row has {len(row)} cells, the header {len(header)}",
                    Position(str(path), line, 1),
                    hint="every row needs one cell per column (commas inside a cell: quote it)",
                )
            if any(len(cell) > MAX_CELL for cell in row):
                raise CsvError(
                    f"a cell is over {MAX_CELL} characters", Position(str(path), line, 1), ""
                )
            cells = [unescape_cell(cell.strip()) for cell in row]
            rows.append((line, cells, _field_columns(row, lines[line - 1 : line])))
    except csv.Error as error:
        raise CsvError(
            f"cannot read the {what} file: {error}",
            Position(str(path), reader.line_num, 1),
            hint="check the quoting",
        ) from None
    return header, _field_columns(header, lines[:1]), rows


def _field_columns(row: Sequence[str], raw: Sequence[str]) -> list[int]:
    """The 1-based column where each cell of ``row`` starts on its ``raw`` line (1 for
    every cell when the record spans lines or does not match).

    >>> _field_columns(["a", "b,c", "d"], ['a,"b,c",d'])
    [1, 3, 9]
    """
    text = raw[0] if len(raw) == 1 else ""
    columns = [1]
    if '"' not in text:  # the common case: the cells as they are, one comma apart
        for cell in text.split(",")[:-1]:
            columns.append(columns[-1] + len(cell) + 1)
    else:
        quoted = False
        for index, char in enumerate(text):
            if char == '"':
                quoted = not quoted
            elif char == "," and not quoted:
                columns.append(index + 2)
    return columns if len(columns) == len(row) else [1] * len(row)
