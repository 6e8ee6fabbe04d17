"""The class summary ``dynsolve grade`` prints: per part share correct and common mistakes,
then the score distribution, as rich renderables.

>>> from dynsolve.grade.run import StudentResult
>>> row = StudentResult("s1", 100.0, {"a": {"answer": "1 m", "verdict": "correct",
...       "credit": 1.0, "feedback": ""}})
>>> import io
>>> from rich.console import Console
>>> console = Console(file=io.StringIO(), width=80, record=True)
>>> for part in summary_renderables([row], "Drum"):
...     console.print(part)
>>> "100%" in console.export_text()
True
"""

from __future__ import annotations

from collections.abc import Sequence

from rich.table import Table
from rich.text import Text

from dynsolve.grade.report import class_summary
from dynsolve.grade.run import StudentResult

BAR = 30  # characters of the longest distribution bar


def summary_renderables(results: Sequence[StudentResult], title: str) -> list[Table | Text]:
    """A parts table and a distribution table."""
    summary = class_summary(results)
    parts = Table(title=f"{title}: {summary['students']} students, mean {summary['mean']:.1f} %")
    parts.add_column("part")
    parts.add_column("correct", justify="right")
    parts.add_column("verdicts")
    parts.add_column("most common mistakes", overflow="fold")
    for name, part in summary["parts"].items():
        verdicts = ", ".join(f"{v} {n}" for v, n in part["verdicts"].items())
        mistakes = "; ".join(f"{m} ({n})" for m, n in part["mistakes"]) or "-"
        parts.add_row(Text(name), f"{100 * part['correct']:.0f}%", Text(verdicts), Text(mistakes))
    spread = Table(title="score distribution", show_header=True)
    spread.add_column("score")
    spread.add_column("students", justify="right")
    spread.add_column("")
    largest = max(summary["distribution"]) or 1
    for index, count in enumerate(summary["distribution"]):
        low = 10 * index
        label = f"{low}-{low + 10}%" if index < len(summary["distribution"]) - 1 else "90-100%"
        spread.add_row(label, str(count), "#" * round(BAR * count / largest))
    return [parts, spread]
