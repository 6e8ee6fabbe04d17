"""``dynsolve grade``'s work, without printing: read, key, grade, write the reports.

>>> import pathlib, tempfile
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "w.dyn").write_text("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")
>>> _ = (folder / "a.csv").write_text("student,W\\ns1,19.6 N\\ns2,2.0 kg\\n")
>>> run = grade(GradeRequest(folder / "w.dyn", folder / "a.csv"))
>>> [(r.student, r.score, r.parts["W"]["verdict"]) for r in run.results]
[('s1', 100.0, 'correct'), ('s2', 0.0, 'dimension')]
"""

from __future__ import annotations

import io
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path

from dynsolve.errors import SpecError
from dynsolve.files import read_capped, write_text
from dynsolve.grade.answers import AnswerSheet, check_header_units, read_answers
from dynsolve.grade.diagnose import Diagnoser
from dynsolve.grade.key import Keys, base_keys, variant_keys
from dynsolve.grade.report import gradebook_csv, results_csv, results_json
from dynsolve.grade.run import StudentResult, fingerprint, grade_sheet, journal_path
from dynsolve.grade.semantics import Rule, rules_for
from dynsolve.spec.parser import parse_bytes
from dynsolve.system import SolveOptions

MAX_ANSWERS_BYTES = 64 * 1024 * 1024


@dataclass(frozen=True)
class GradeRequest:
    """What the command line asked for."""

    problem: Path
    answers: Path
    report: Path | None = None  # per-student CSV
    json: Path | None = None
    gradebook: Path | None = None
    histogram: Path | None = None
    variants: Path | None = None
    overrides: Rule = field(default_factory=Rule)
    atol_text: str = ""  # "0.01 m/s": applied to the parts of its dimension
    resume: bool = False
    diagnose: bool = True
    options: SolveOptions = field(default_factory=SolveOptions)


@dataclass(frozen=True)
class GradeRun:
    """The outcome: every student's result, the rules used, the warnings, how keys were made."""

    results: list[StudentResult]
    rules: dict[str, Rule]
    warnings: tuple[str, ...]
    path: str
    title: str
    written: tuple[Path, ...]


def grade(request: GradeRequest, progress: Callable[[int, int], None] | None = None) -> GradeRun:
    """Grade the answers file against the problem and write the reports asked for."""
    spec_bytes = read_capped(request.problem, MAX_ANSWERS_BYTES)
    spec = parse_bytes(spec_bytes, str(request.problem))
    answers_text = _text(request.answers)
    finds = [f.name for f in spec.finds]
    sheet = read_answers(io.StringIO(answers_text), finds, str(request.answers))
    keys = _keys(request, spec, sheet)
    check_header_units(sheet, keys.shared, str(request.answers))
    rules = rules_for(list(keys.shared), spec.grading, request.overrides)
    warnings = list(sheet.warnings)
    if request.atol_text:
        rules = _with_atol(rules, keys, request.atol_text, warnings)
    warnings += zero_key_warnings(keys, rules)
    doctor = Diagnoser(spec, request.options) if request.diagnose else None
    journal = None
    anchor = request.report or request.json or request.gradebook
    if anchor is not None:
        journal = journal_path(anchor)
    elif request.resume:
        raise SpecError("--resume needs a report file (-o, --json or --gradebook)", None, "add -o")
    stamp = fingerprint(spec_bytes.decode("utf-8", "replace"), answers_text, repr(rules))
    results = grade_sheet(sheet, keys, rules, doctor, journal, stamp, request.resume, progress)
    written = _write(request, results, rules, spec.title, keys.path, warnings)
    if journal is not None and journal.exists():
        journal.unlink()
    return GradeRun(results, rules, tuple(warnings), keys.path, spec.title, written)


def _text(path: Path) -> str:
    raw = read_capped(path, MAX_ANSWERS_BYTES)
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise SpecError(f"{path} is not UTF-8 text", None, "save the CSV as UTF-8") from None


def _keys(request: GradeRequest, spec: object, sheet: AnswerSheet) -> Keys:
    if request.variants is None:
        return base_keys(spec, request.options)  # type: ignore[arg-type]
    try:
        from dynsolve.grade.variants import read_variants  # type: ignore[import-not-found]
    except ImportError:
        return variant_keys(spec, {}, request.options)  # type: ignore[arg-type]  # says why
    variants = read_variants(request.variants)
    return variant_keys(spec, variants, request.options)  # type: ignore[arg-type]


def zero_key_warnings(keys: Keys, rules: dict[str, Rule]) -> list[str]:
    """A warning per part whose key is exactly 0 for some student while its rule has no
    absolute tolerance: a relative tolerance (or significant figures) of 0 is 0, so only an
    answer of exactly 0 would pass.

    >>> from dynsolve.grade.semantics import Key
    >>> from dynsolve.units import Dim
    >>> keys = Keys({"a": Key("a", 0.0, Dim.of("acceleration"), "m/s^2")})
    >>> zero_key_warnings(keys, {"a": Rule()})[0].split(":")[0]
    'the key of a is 0'
    """
    out = []
    for part, rule in rules.items():
        if rule.atol:
            continue
        tables = [keys.shared, *keys.per_student.values()]
        zeros = [t[part] for t in tables if part in t and t[part].value == 0]
        if zeros:
            unit = zeros[0].unit
            out.append(
                f"the key of {part} is 0: with no absolute tolerance only an answer of exactly 0 "
                f"passes; set one, e.g. 'grading:' line '{part} atol 0.01 {unit}' or "
                f"--atol '0.01 {unit}'"
            )
    return out


def _with_atol(
    rules: dict[str, Rule], keys: Keys, text: str, warnings: list[str]
) -> dict[str, Rule]:
    from dynsolve.grade.cells import CellError, read_cell

    try:
        atol = read_cell(text)
    except CellError as error:
        raise SpecError(f"--atol {text}: {error}", None, "e.g. --atol '0.01 m/s'") from None
    out = dict(rules)
    for name, key in keys.shared.items():
        if key.dim == atol.dim:
            out[name] = replace(rules[name], atol=abs(atol.value))
    if all(out[n] == rules[n] for n in rules):
        warnings.append(f"--atol {text} matches the dimension of no part; ignored")
    return out


def _write(
    request: GradeRequest,
    results: list[StudentResult],
    rules: dict[str, Rule],
    title: str,
    path: str,
    warnings: list[str],
) -> tuple[Path, ...]:
    written: list[Path] = []
    if request.report is not None:
        write_text(request.report, results_csv(results))
        written.append(request.report)
    if request.json is not None:
        write_text(request.json, results_json(results, str(request.problem), path, warnings))
        written.append(request.json)
    if request.gradebook is not None:
        weights = {name: rule.weight for name, rule in rules.items()}
        write_text(request.gradebook, gradebook_csv(results, weights))
        written.append(request.gradebook)
    if request.histogram is not None:
        from dynsolve.grade.histogram import write_histogram

        write_histogram([r.score for r in results], request.histogram, title)
        written.append(request.histogram)
    return tuple(written)
