"""Reports of a graded class: per-student CSV and JSON, gradebook CSV, class summary data.

Pure functions from results to text or data; the CLI writes and prints them.

>>> from dynsolve.grade.run import StudentResult
>>> rows = [StudentResult("s1", 100.0, {"a": {"answer": "4.52 m/s^2", "verdict": "correct",
...         "credit": 1.0, "feedback": ""}}),
...         StudentResult("s2", 0.0, {"a": {"answer": "45.2 m/s^2", "verdict": "wrong",
...         "credit": 0.0, "feedback": "a power-of-ten slip (x10): check the unit prefix"}})]
>>> gradebook_csv(rows, {"a": 1.0}).splitlines()
['student,score,points,max_points', 's1,100.00,1,1', 's2,0.00,0,1']
>>> class_summary(rows)["parts"]["a"]["correct"]
0.5
"""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Mapping, Sequence
from typing import Any

from dynsolve.grade.run import StudentResult, parts_of
from dynsolve.safe_csv import csv_text

BINS = 10  # score distribution: 0-10, 10-20, …, 90-100 %
TOP_MISTAKES = 3


def results_csv(results: Sequence[StudentResult]) -> str:
    """One row per student: id, score, (with variants) their givens, then per part their
    answer, the expected value, its unit and direction, verdict, credit, feedback."""
    parts = parts_of(results)
    givens = any(r.givens for r in results)
    header = ["student", "score", *(["givens"] if givens else [])]
    for part in parts:
        header += [f"{part} answer", f"{part} expected", f"{part} expected unit"]
        header.append(f"{part} expected direction")
        header += [f"{part} verdict", f"{part} credit", f"{part} feedback"]
    rows: list[list[str]] = [header]
    for result in results:
        row = [result.student, f"{result.score:.2f}"]
        if givens:
            row.append("; ".join(f"{n} = {v}" for n, v in result.givens.items()))
        for part in parts:
            cell = result.parts[part]
            expected = cell.get("expected")
            row += [cell["answer"], "" if expected is None else f"{expected:.6g}"]
            row += [cell.get("expected_unit", ""), cell.get("expected_direction", "")]
            row += [cell["verdict"], f"{cell['credit']:g}"]
            row.append(cell["feedback"])
        rows.append(row)
    return csv_text(rows)


def results_json(
    results: Sequence[StudentResult], problem: str, path: str, warnings: Sequence[str] = ()
) -> str:
    """The whole report as JSON: problem, how keys were made, rows, summary, warnings."""
    document = {
        "problem": problem,
        "keys": path,
        "students": [r.as_dict() for r in results],
        "summary": class_summary(results),
        "warnings": list(warnings),
    }
    return json.dumps(document, indent=2, sort_keys=True) + "\n"


def gradebook_csv(results: Sequence[StudentResult], weights: Mapping[str, float]) -> str:
    """A gradebook import: ``student,score,points,max_points`` (score in %, 2 decimals;
    points = weighted credit earned, max_points = sum of the weights)."""
    total = sum(weights.values())
    rows = [["student", "score", "points", "max_points"]]
    for result in results:
        points = sum(weights[p] * float(c["credit"]) for p, c in result.parts.items())
        rows.append([result.student, f"{result.score:.2f}", f"{points:g}", f"{total:g}"])
    return csv_text(rows)


def class_summary(results: Sequence[StudentResult]) -> dict[str, Any]:
    """Per part: share correct, verdict counts, the most common diagnosed mistakes;
    and the score distribution (counts per 10 % bin) and mean."""
    parts: dict[str, Any] = {}
    count = len(results)
    for part in parts_of(results):
        cells = [r.parts[part] for r in results]
        verdicts = Counter(c["verdict"] for c in cells)
        named = (_mistake(c["feedback"]) for c in cells if c["verdict"] == "wrong")
        mistakes = Counter(m for m in named if m)  # an undiagnosed answer takes no slot
        parts[part] = {
            "correct": round(verdicts["correct"] / count, 4) if count else 0.0,
            "verdicts": dict(sorted(verdicts.items())),
            "mistakes": [[m, n] for m, n in mistakes.most_common(TOP_MISTAKES)],
        }
    bins = [0] * BINS
    for result in results:
        bins[min(int(result.score // (100 / BINS)), BINS - 1)] += 1
    mean = round(sum(r.score for r in results) / count, 2) if count else 0.0
    return {"students": count, "mean": mean, "distribution": bins, "parts": parts}


def _mistake(feedback: str) -> str:
    """The diagnosed mistake of a feedback sentence ("" when only "off by …")."""
    if feedback.startswith("off by"):
        return ""
    return feedback.split(" (off by")[0]
