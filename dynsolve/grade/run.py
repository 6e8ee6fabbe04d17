"""Grade every row of an answers sheet: verdicts, credit, feedback; journaled for --resume.

Each finished row is appended to a :class:`~dynsolve.grade.journal.Journal` next to the
report. A rerun with ``resume`` reads the journal, keeps its rows and grades only the
rest, so the report is identical to an uninterrupted run's. The journal's first line is
a fingerprint of everything that decides a verdict: a journal of another run is refused.

>>> from dynsolve.grade.semantics import Key, Rule
>>> from dynsolve.units import Dim
>>> keys = {"a": Key("a", 4.5168, Dim.of("acceleration"), "m/s^2")}
>>> row = grade_row("s1", {"a": "4.52 m/s^2"}, keys, {"a": Rule()}, {"a": ""}, None)
>>> row.score, row.parts["a"]["verdict"]
(100.0, 'correct')
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from dynsolve.grade.answers import AnswerSheet
from dynsolve.grade.diagnose import Diagnoser
from dynsolve.grade.journal import Journal
from dynsolve.grade.key import Keys
from dynsolve.grade.semantics import Key, Rule, judge


@dataclass(frozen=True)
class StudentResult:
    """One student's grade: score in percent and, per part, answer, verdict, credit, feedback."""

    student: str
    score: float
    parts: Mapping[str, Mapping[str, Any]]
    givens: Mapping[str, str] = field(default_factory=dict)  # their variant's, as written

    def as_dict(self) -> dict[str, Any]:
        """The JSON form (also a journal line)."""
        return {
            "student": self.student,
            "score": self.score,
            "givens": dict(self.givens),
            "parts": dict(self.parts),
        }

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> StudentResult:
        """Read back :meth:`as_dict`."""
        givens = dict(data.get("givens", {}))
        return cls(str(data["student"]), float(data["score"]), dict(data["parts"]), givens)


def grade_row(
    student: str,
    cells: Mapping[str, str],
    keys: Mapping[str, Key],
    rules: Mapping[str, Rule],
    units: Mapping[str, str],
    doctor: Diagnoser | None,
    decimal_comma: bool = False,
) -> StudentResult:
    """Grade one student's cells against their keys (``decimal_comma``: the file's mark)."""
    parts: dict[str, dict[str, Any]] = {}
    earned = total = 0.0
    for name, key in keys.items():
        rule = rules[name]
        text = cells.get(name, "")
        result = judge(text, key, rule, units.get(name, ""), decimal_comma)
        feedback = result.detail
        if result.verdict == "wrong" and doctor is not None and result.value is not None:
            named = doctor.diagnose(name, result.value, keys, rule, student)
            feedback = f"{named} ({result.detail})" if named else result.detail
        parts[name] = {
            "answer": text.strip(),
            "expected": float(f"{key.value / key.factor:.12g}"),  # no conversion noise
            "expected_unit": key.unit,
            "expected_direction": key.direction,  # cw, down, "30.0° below the horizontal, …"
            "verdict": result.verdict,
            "credit": result.credit,
            "feedback": feedback,
        }
        earned += rule.weight * result.credit
        total += rule.weight
    score = round(100.0 * earned / total, 2) if total else 0.0
    return StudentResult(student, score, parts)


def fingerprint(*texts: str) -> str:
    """A digest of the run's inputs (problem, answers, rules).

    >>> fingerprint("a", "b") == fingerprint("a", "b") != fingerprint("ab", "")
    True
    """
    digest = hashlib.sha256()
    for text in texts:
        digest.update(len(text).to_bytes(8, "little") + text.encode("utf-8"))
    return digest.hexdigest()


def grade_sheet(
    sheet: AnswerSheet,
    keys: Keys,
    rules: Mapping[str, Rule],
    doctor: Diagnoser | None,
    journal: Journal | None = None,
    stamp: str = "",
    resume: bool = False,
    progress: Callable[[int, int], None] | None = None,
) -> list[StudentResult]:
    """Grade every row in order; with a ``journal``, record each row as it is finished
    and, with ``resume``, reuse the rows a previous run recorded under the same ``stamp``."""
    recorded = journal.start(stamp, resume) if journal is not None else {}
    done = {student: StudentResult.from_dict(row) for student, row in recorded.items()}
    if doctor is not None and keys.per_student:  # variants: each student's own model
        doctor = Diagnoser(doctor.spec, doctor.options, doctor.model, keys.variants)
    results: list[StudentResult] = []
    for index, (student, cells) in enumerate(sheet.rows, start=1):
        if student in done:
            results.append(done[student])
        else:
            row = graded(student, cells, keys, rules, sheet.units, doctor, sheet.decimal_comma)
            results.append(row)
            if journal is not None:
                journal.append(row.as_dict())
        if progress is not None:
            progress(index, len(sheet.rows))
    return results


def graded(
    student: str,
    cells: Mapping[str, str],
    keys: Keys,
    rules: Mapping[str, Rule],
    units: Mapping[str, str],
    doctor: Diagnoser | None,
    decimal_comma: bool = False,
) -> StudentResult:
    """One student's row: graded against their keys, with their variant's givens; or not
    graded ("no key": their variant failed; "no variant": the variants file lacks them);
    ``decimal_comma``: the answers file writes 4,52."""
    if keys.unknown(student):
        why = f"no row for '{student}' in the variants file"
        return not_graded(student, keys, "no variant", why, cells)
    if student in keys.errors:
        row = not_graded(student, keys, "no key", keys.errors[student], cells)
    else:
        row = grade_row(
            student, cells, keys.for_student(student), rules, units, doctor, decimal_comma
        )
    if not keys.by_variant:
        return row
    return replace(row, givens=dict(keys.variants.get(student, {})))


def not_graded(
    student: str, keys: Keys, verdict: str, why: str, cells: Mapping[str, str] | None = None
) -> StudentResult:
    """A row graded 0 in every part with ``verdict`` ("no key", "no variant") and ``why``;
    the student's ``cells`` are shown as they wrote them."""
    parts = {
        name: {
            "answer": (cells or {}).get(name, "").strip(),
            "expected": None,
            "expected_unit": "",
            "expected_direction": "",
            "verdict": verdict,
            "credit": 0.0,
            "feedback": why,
        }
        for name in keys.shared
    }
    return StudentResult(student, 0.0, parts)


def parts_of(results: Iterable[StudentResult]) -> list[str]:
    """The part names, in order, of the first result."""
    for result in results:
        return list(result.parts)
    return []
