"""Grade every row of an answers sheet: verdicts, credit, feedback; journaled for --resume.

Each finished row is appended to a journal (JSON lines, flushed and fsync'd) next to the
report. A rerun with ``resume`` reads the journal, keeps its rows and grades only the
rest, so the report is identical to an uninterrupted run's. The journal's first line is
a fingerprint of the problem, the answers and the rules: a journal of another run is
refused. It is removed once the reports are written.

>>> from dynsolve.grade.semantics import Key, Rule
>>> from dynsolve.units import Dim
>>> keys = {"a": Key("a", 4.5168, Dim.of("acceleration"), "m/s^2")}
>>> row = grade_row("s1", {"a": "4.52 m/s^2"}, keys, {"a": Rule()}, {"a": ""}, None)
>>> row.score, row.parts["a"]["verdict"]
(100.0, 'correct')
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from dynsolve.errors import SpecError
from dynsolve.grade.answers import AnswerSheet
from dynsolve.grade.diagnose import Diagnoser
from dynsolve.grade.key import Keys
from dynsolve.grade.semantics import Key, Rule, judge

JOURNAL_SUFFIX = ".journal"
SYNC_EVERY = 200  # rows between fsyncs; each row is flushed to the OS as it is finished


@dataclass(frozen=True)
class StudentResult:
    """One student's grade: score in percent and, per part, answer, verdict, credit, feedback."""

    student: str
    score: float
    parts: Mapping[str, Mapping[str, Any]]

    def as_dict(self) -> dict[str, Any]:
        """The JSON form (also a journal line)."""
        return {"student": self.student, "score": self.score, "parts": dict(self.parts)}

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> StudentResult:
        """Read back :meth:`as_dict`."""
        return cls(str(data["student"]), float(data["score"]), dict(data["parts"]))


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
    journal: Path | None = None,
    stamp: str = "",
    resume: bool = False,
    progress: Callable[[int, int], None] | None = None,
) -> list[StudentResult]:
    """Grade every row in order; with a ``journal``, record each row as it is finished
    and, with ``resume``, reuse the rows a previous run recorded under the same ``stamp``."""
    done = _read_journal(journal, stamp) if (journal and resume) else {}
    if doctor is not None and keys.per_student:  # variants: each student's own model
        doctor = Diagnoser(doctor.spec, doctor.options, doctor.model, keys.variants)
    results: list[StudentResult] = []
    handle = _open_journal(journal, stamp, bool(done)) if journal else None
    try:
        for index, (student, cells) in enumerate(sheet.rows, start=1):
            if student in done:
                results.append(done[student])
            else:
                if student in keys.errors:
                    row = _no_key(student, keys, keys.errors[student])
                else:
                    mine = keys.for_student(student)
                    row = grade_row(
                        student, cells, mine, rules, sheet.units, doctor, sheet.decimal_comma
                    )
                results.append(row)
                if handle is not None:
                    _append(handle, row.as_dict(), sync=index % SYNC_EVERY == 0)
            if progress is not None:
                progress(index, len(sheet.rows))
    finally:
        if handle is not None:
            _sync(handle)
            handle.close()
    return results


def _no_key(student: str, keys: Keys, why: str) -> StudentResult:
    parts = {
        name: {"answer": "", "verdict": "no key", "credit": 0.0, "feedback": why}
        for name in keys.shared
    }
    return StudentResult(student, 0.0, parts)


def _open_journal(path: Path, stamp: str, keep: bool) -> Any:
    if keep:
        return path.open("a", encoding="utf-8")
    handle = path.open("w", encoding="utf-8")
    _append(handle, {"fingerprint": stamp})
    return handle


def _append(handle: Any, record: Mapping[str, Any], sync: bool = True) -> None:
    """One record as one line, flushed (a killed process loses nothing flushed); fsync'd
    when ``sync`` (a crash of the machine loses at most the rows since)."""
    handle.write(json.dumps(record) + "\n")  # key order kept: parts in find order
    handle.flush()
    if sync:
        _sync(handle)


def _sync(handle: Any) -> None:
    handle.flush()
    os.fsync(handle.fileno())


def _read_journal(path: Path, stamp: str) -> dict[str, StudentResult]:
    """Rows a killed run finished; a torn last line (killed mid-write) is dropped."""
    if not path.exists():
        return {}
    lines = path.read_text(encoding="utf-8").split("\n")
    records = []
    for line in lines:
        try:
            records.append(json.loads(line))
        except json.JSONDecodeError:
            break  # the torn tail: everything before it was fsync'd whole
    if not records or records[0].get("fingerprint") != stamp:
        raise SpecError(
            f"{path} is the journal of another run (other problem, answers or rules)",
            None,
            "delete it, or rerun without --resume",
        )
    rows = (StudentResult.from_dict(r) for r in records[1:])
    good = _whole(lines, len(records))
    if not good:  # rewrite without the torn tail, so that appends start on a fresh line
        path.write_text("".join(json.dumps(r) + "\n" for r in records))
    return {row.student: row for row in rows}


def _whole(lines: list[str], parsed: int) -> bool:
    return all(not line for line in lines[parsed:])


def journal_path(report: Path) -> Path:
    """The journal kept next to ``report`` while grading."""
    return report.with_name(report.name + JOURNAL_SUFFIX)


def parts_of(results: Iterable[StudentResult]) -> list[str]:
    """The part names, in order, of the first result."""
    for result in results:
        return list(result.parts)
    return []
