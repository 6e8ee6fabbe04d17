"""Read a graded class's totals: the gradebook CSV that ``dynsolve grade --gradebook`` writes
(``student,score,points,max_points``), checked row by row.

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "gb.csv"
>>> _ = path.write_text("student,score,points,max_points\\ns1,66.67,2,3\\n'=1+1,0.00,0,3\\n")
>>> [(t.student, t.points, t.max_points) for t in read_gradebook(path)]
[('s1', 2.0, 3.0), ('=1+1', 0.0, 3.0)]
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from dynsolve.errors import Position
from dynsolve.files import read_capped
from dynsolve.grade.export.target import ExportError
from dynsolve.safe_csv import unescape_cell

MAX_BYTES = 64 * 1024 * 1024
COLUMNS = ("student", "score", "points", "max_points")


@dataclass(frozen=True)
class Total:
    """One student's total: score in percent, weighted points earned out of ``max_points``."""

    student: str
    score: float
    points: float
    max_points: float

    def scaled(self, out_of: float | None) -> float:
        """The points earned on a scale of ``out_of`` (the gradebook's own when None)."""
        if out_of is None:
            return self.points
        return self.points / self.max_points * out_of if self.max_points else 0.0


def read_csv_text(path: Path) -> str:
    """A CSV file's text (UTF-8, a byte-order mark dropped), at most :data:`MAX_BYTES`;
    ExportError where it is larger or not UTF-8."""
    raw = read_capped(path, MAX_BYTES)
    where = Position(str(path), 1, 1)
    if len(raw) > MAX_BYTES:
        raise ExportError(f"{path} is over {MAX_BYTES} bytes", where)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise ExportError(f"{path} is not UTF-8 text", where, "save it as UTF-8") from None


def read_gradebook(path: Path) -> list[Total]:
    """Every row of a dynsolve gradebook CSV; a malformed file or row stops with its line."""
    reader = csv.reader(io.StringIO(read_csv_text(path), newline=""))
    try:
        return _totals(path, ((reader.line_num, row) for row in reader))
    except csv.Error as error:
        where = Position(str(path), reader.line_num, 1)
        raise ExportError(f"cannot read {path}: {error}", where, "check the quoting") from None


def _totals(path: Path, rows: Iterator[tuple[int, list[str]]]) -> list[Total]:
    where = Position(str(path), 1, 1)
    header = [h.strip().lower() for h in next(rows, (1, []))[1]]
    if tuple(header[:4]) != COLUMNS:
        raise ExportError(
            f"{path} is not a dynsolve gradebook: its header is {','.join(header[:4])!r}",
            where,
            hint="give the file 'dynsolve grade ... --gradebook FILE' wrote "
            "(student,score,points,max_points)",
        )
    totals: list[Total] = []
    seen: set[str] = set()
    for line, row in rows:
        if not any(cell.strip() for cell in row):
            continue
        totals.append(_total(row, Position(str(path), line, 1), seen))
    if not totals:
        raise ExportError(f"{path} lists no students", where, "grade the class first")
    return totals


def _total(row: list[str], where: Position, seen: set[str]) -> Total:
    if len(row) < len(COLUMNS):
        raise ExportError(f"the row has {len(row)} cells, not {len(COLUMNS)}", where)
    student = unescape_cell(row[0].strip())
    if not student or student in seen:
        raise ExportError(f"student id {student!r} is empty or appears twice", where)
    seen.add(student)
    try:
        score, points, max_points = (float(cell) for cell in row[1:4])
    except ValueError:
        raise ExportError(
            f"student {student}: score, points and max_points must be numbers", where
        ) from None
    if not all(math.isfinite(x) and x >= 0 for x in (score, points, max_points)):
        raise ExportError(f"student {student}: a negative or infinite number", where)
    return Total(student, score, points, max_points)


def number_text(value: float) -> str:
    """A score as a gradebook cell: at most 2 decimals, no trailing zeros.

    >>> number_text(2.0), number_text(6.6667), number_text(1.5)
    ('2', '6.67', '1.5')
    """
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text
