"""The gradebook as a scores CSV that Gradescope and Moodle import: ``SID, Total Score,
Max Points`` (Gradescope's own column names; Moodle's CSV grade import maps ``SID`` to
the user's ID number and ``Total Score`` to the grade item).

>>> from dynsolve.grade.export.gradebook import Total
>>> totals = [Total("s1", 50.0, 1.5, 3.0), Total("-s2", 0.0, 0.0, 3.0)]
>>> print(*scores_csv(totals, 10).splitlines(), sep="\\n")
SID,Total Score,Max Points
s1,5,10
'-s2,0,10
"""

from __future__ import annotations

from collections.abc import Sequence

from dynsolve.grade.export.gradebook import Total, number_text
from dynsolve.safe_csv import csv_text

HEADER = ("SID", "Total Score", "Max Points")


def scores_csv(totals: Sequence[Total], points: float | None = None) -> str:
    """One row per student; ``points`` rescales every total to be out of it (each row's
    own ``max_points`` when None)."""
    rows = [list(HEADER)]
    for total in totals:
        out_of = points if points is not None else total.max_points
        rows.append([total.student, number_text(total.scaled(out_of)), number_text(out_of)])
    return csv_text(rows)
