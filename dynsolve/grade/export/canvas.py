"""The gradebook as a Canvas gradebook import CSV: ``Student, ID, SIS User ID, SIS Login
ID, Section`` then one assignment column, preceded by a ``Points Possible`` row.

Canvas matches a row to a student by its Canvas ``ID``, ``SIS User ID`` or ``SIS Login
ID``; an assignment header ``Name (12345)`` updates the assignment with that Canvas id,
a bare name creates a new assignment. With a roster (Canvas's own gradebook export) each
graded student is found by any of the three ids and the row copies its name and section.

>>> from dynsolve.grade.export.gradebook import Total
>>> print(*canvas_csv([Total("s1", 50.0, 1.5, 3.0)], "Drum (77)", 10).splitlines(), sep="\\n")
Student,ID,SIS User ID,SIS Login ID,Section,Drum (77)
    Points Possible,,,,,10
,,s1,,,5
"""

from __future__ import annotations

import csv
import io
from collections.abc import Mapping, Sequence
from pathlib import Path

from dynsolve.errors import Position
from dynsolve.grade.export.gradebook import Total, number_text, read_csv_text
from dynsolve.grade.export.target import ExportError
from dynsolve.safe_csv import csv_text

IDENTITY = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
ID_COLUMNS = ("ID", "SIS User ID", "SIS Login ID")
POINTS_ROW = "    Points Possible"  # as Canvas writes it in its own export
MAX_ASSIGNMENT = 255
Roster = Mapping[str, Mapping[str, str]]  # any of a student's ids -> their identity cells


def canvas_csv(
    totals: Sequence[Total],
    assignment: str,
    points: float | None = None,
    roster: Roster | None = None,
    id_column: str = "SIS User ID",
) -> str:
    """The import file: one row per graded student (``points``: the assignment's points
    possible, the gradebook's own maximum when None). Without a roster the student's id
    goes in ``id_column``; with one, a student it does not list stops the export."""
    check_assignment(assignment)
    if id_column not in ID_COLUMNS:
        raise ExportError(f"unknown Canvas id column {id_column!r}", hint=", ".join(ID_COLUMNS))
    possible = points if points is not None else max(t.max_points for t in totals)
    rows = [[*IDENTITY, assignment], [POINTS_ROW, "", "", "", "", number_text(possible)]]
    missing = [t.student for t in totals if roster is not None and t.student not in roster]
    if missing:
        more = f" and {len(missing) - 5} more" if len(missing) > 5 else ""
        shown = ", ".join(missing[:5]) + more
        raise ExportError(
            f"{len(missing)} graded student(s) not in the Canvas roster: {shown}",
            hint="ids are matched exactly against the roster's ID, SIS User ID and SIS Login "
            "ID columns; fix the answers file's ids or export the roster again",
        )
    _refuse_two_ids_of_one_student(totals, roster)
    for total in totals:
        if roster is not None:
            cells = [roster[total.student].get(column, "") for column in IDENTITY]
        else:
            cells = [total.student if column == id_column else "" for column in IDENTITY]
        rows.append([*cells, number_text(total.scaled(points))])
    return csv_text(rows)


def _refuse_two_ids_of_one_student(totals: Sequence[Total], roster: Roster | None) -> None:
    """Two graded ids that are one Canvas student (``s001`` their SIS User ID, ``ada``
    their login) would give them two rows and two grades: refused."""
    if roster is None:
        return
    seen: dict[tuple[str, ...], str] = {}
    for total in totals:
        who = tuple(roster[total.student].get(c, "") for c in IDENTITY)
        if who in seen:
            raise ExportError(
                f"graded ids {seen[who]!r} and {total.student!r} are one Canvas student "
                f"({who[0] or who[1]})",
                hint="keep one row per student in the answers file",
            )
        seen[who] = total.student


def check_assignment(name: str) -> None:
    """An assignment header Canvas can read: one line, 1 to 255 characters."""
    if not name.strip() or len(name) > MAX_ASSIGNMENT or not name.isprintable():
        raise ExportError(
            f"the assignment name must be 1 to {MAX_ASSIGNMENT} printable characters",
            hint="e.g. --assignment 'Drum and block (12345)', with the Canvas assignment id",
        )


def read_roster(path: Path) -> dict[str, dict[str, str]]:
    """A Canvas gradebook export as a roster: each student's ``ID``, ``SIS User ID`` and
    ``SIS Login ID`` → their identity cells (the ``Points Possible`` row is skipped)."""
    reader = csv.DictReader(io.StringIO(read_csv_text(path), newline=""))
    try:
        return _roster(path, reader)
    except csv.Error as error:
        where = Position(str(path), reader.line_num, 1)
        raise ExportError(f"cannot read {path}: {error}", where, "check the quoting") from None


def _roster(path: Path, reader: csv.DictReader[str]) -> dict[str, dict[str, str]]:
    where = Position(str(path), 1, 1)
    header = [h.strip() for h in reader.fieldnames or []]
    if "Student" not in header or not any(c in header for c in ID_COLUMNS):
        raise ExportError(
            f"{path} is not a Canvas gradebook export: no Student and ID columns",
            where,
            hint="in Canvas: Grades > Export > Export Entire Gradebook",
        )
    roster: dict[str, dict[str, str]] = {}
    for row in reader:
        cells = {k.strip(): (v or "").strip() for k, v in row.items() if k is not None}
        if cells.get("Student", "").strip() in ("Points Possible", ""):
            continue
        identity = {column: cells.get(column, "") for column in IDENTITY}
        for column in ID_COLUMNS:
            key = identity[column]
            if key and roster.get(key, identity) != identity:
                raise ExportError(
                    f"id {key!r} names two students in the Canvas roster",
                    Position(str(path), reader.line_num, 1),
                )
            if key:
                roster[key] = identity
    return roster
