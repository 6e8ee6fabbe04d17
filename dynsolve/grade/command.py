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

import difflib
import io
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

from dynsolve.errors import Position, SpecError
from dynsolve.files import read_capped, write_text
from dynsolve.grade.answers import AnswerSheet, check_header_units, read_answers
from dynsolve.grade.diagnose import Diagnoser
from dynsolve.grade.journal import Journal, journal_path
from dynsolve.grade.key import Keys, base_keys, variant_keys
from dynsolve.grade.report import gradebook_csv, results_csv, results_json
from dynsolve.grade.run import StudentResult, fingerprint, grade_sheet, graded
from dynsolve.grade.semantics import Rule, rules_for
from dynsolve.grade.substitute import with_variant
from dynsolve.grade.variants import TWIN_SUFFIX, VariantTable, read_variant_table
from dynsolve.spec.ast import Spec
from dynsolve.spec.parser import parse_bytes
from dynsolve.system import SolveOptions

MAX_ANSWERS_BYTES = 64 * 1024 * 1024
NOT_GRADED = ("no key", "no variant")  # verdicts of a student who could not be graded
MAX_NAMED = 10  # students named in one warning
MAX_COMPARED = 2000  # variant ids an unknown id is compared with for the closest one
_QUOTED = re.compile(r"'[^']*'")


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
    fresh: bool = False  # start over, discarding an interrupted run's journal
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

    @property
    def ungraded(self) -> list[str]:
        """The students who could not be graded: no row in the variants file, or a
        variant that could not be solved."""
        return [
            r.student
            for r in self.results
            if any(p["verdict"] in NOT_GRADED for p in r.parts.values())
        ]


def grade(request: GradeRequest, progress: Callable[[int, int], None] | None = None) -> GradeRun:
    """Grade the answers file against the problem and write the reports asked for."""
    anchor = check_outputs(request)
    spec_bytes = read_capped(request.problem, MAX_ANSWERS_BYTES)
    spec = parse_bytes(spec_bytes, str(request.problem))
    answers_text = _text(request.answers)
    finds = [f.name for f in spec.finds]
    sheet = read_answers(io.StringIO(answers_text), finds, str(request.answers))
    journal = None
    if anchor is not None:
        journal = Journal.open(journal_path(anchor), request.resume, request.fresh)
    try:
        run = _grade(request, spec, spec_bytes, answers_text, sheet, journal, progress)
        if journal is not None:
            journal.remove()
        return run
    except BaseException:
        if journal is not None and journal.empty():
            journal.remove()  # nothing graded yet: no journal to resume from
        raise
    finally:
        if journal is not None:
            journal.close()


def _grade(
    request: GradeRequest,
    spec: Spec,
    spec_bytes: bytes,
    answers_text: str,
    sheet: AnswerSheet,
    journal: Journal | None,
    progress: Callable[[int, int], None] | None,
) -> GradeRun:
    keys = _keys(request, spec)
    check_header_units(sheet, keys.shared, str(request.answers))
    rules = rules_for(list(keys.shared), spec.grading, request.overrides)
    warnings = list(sheet.warnings)
    if request.atol_text:
        rules = _with_atol(rules, keys, request.atol_text, warnings)
    warnings += zero_key_warnings(keys, rules)
    absent, mismatched = variant_mismatches([s for s, _ in sheet.rows], keys, request)
    warnings += mismatched
    doctor = Diagnoser(spec, request.options) if request.diagnose else None
    stamp = fingerprint(
        spec_bytes.decode("utf-8", "replace"),
        answers_text,
        repr(keys.variants),  # the variants file's content, as read
        repr(rules),
        f"diagnose={request.diagnose}",
        repr(request.options),
    )
    results = grade_sheet(sheet, keys, rules, doctor, journal, stamp, request.resume, progress)
    for student in absent:  # variant students without a row: graded missing, listed
        results.append(graded(student, {}, keys, rules, {}, None))
    warnings = limit_warnings(warnings)
    written = _write(request, results, rules, spec.title, keys.path, warnings)
    return GradeRun(results, rules, tuple(warnings), keys.path, spec.title, written)


def check_outputs(request: GradeRequest) -> Path | None:
    """Refuse two outputs on one path, or an output on the journal's path, before any
    work; the report the journal is kept next to (None without a report)."""
    outputs = (
        ("-o", request.report),
        ("--json", request.json),
        ("--gradebook", request.gradebook),
        ("--histogram", request.histogram),
    )
    seen: dict[Path, str] = {}
    for option, path in outputs:
        if path is None:
            continue
        real = path.resolve()
        if real in seen:
            raise SpecError(
                f"{option} {path} is also the path of {seen[real]}: one report would "
                "overwrite the other",
                None,
                "give each report its own path",
            )
        seen[real] = f"{option} {path}"
    anchor = request.report or request.json or request.gradebook
    if anchor is None:
        if request.resume:
            raise SpecError(
                "--resume needs a report file (-o, --json or --gradebook)", None, "add -o"
            )
        return None
    journal = journal_path(anchor).resolve()
    if journal in seen:
        raise SpecError(
            f"{seen[journal]} is the path of this run's journal: writing it would delete the "
            "rows kept for --resume",
            None,
            "choose another path",
        )
    return anchor


def variant_mismatches(
    students: Sequence[str], keys: Keys, request: GradeRequest
) -> tuple[list[str], list[str]]:
    """With variants: the variant students who have no row in the answers file (a twin
    ``ID@US`` counts as its student), and a warning per answer id with no variant (naming
    the closest variant id) and for the absent students."""
    if not keys.by_variant:
        return [], []
    answers, variants = request.answers, request.variants
    unknown = [s for s in students if keys.unknown(s)]
    folded = {v.casefold(): v for v in keys.variants}
    warnings = [
        f"{answers}: student '{s}' has no row in {variants}{_closest(s, folded)}: "
        "not graded ('no variant')"
        for s in unknown[:MAX_NAMED]
    ]
    if len(unknown) > MAX_NAMED:
        warnings.append(
            f"{answers}: {len(unknown) - MAX_NAMED} more students have no row in {variants}: "
            "not graded ('no variant')"
        )
    answered = {s.removesuffix(TWIN_SUFFIX) for s in students}
    absent: dict[str, str] = {}
    for student in keys.variants:
        base = student.removesuffix(TWIN_SUFFIX)
        if base not in answered and base not in absent:
            absent[base] = student
    if absent:
        shown = ", ".join(list(absent.values())[:MAX_NAMED])
        more = f" and {len(absent) - MAX_NAMED} more" if len(absent) > MAX_NAMED else ""
        warnings.append(
            f"{len(absent)} students of {variants} have no row in {answers}: {shown}{more}; "
            "graded 'missing'"
        )
    return list(absent.values()), warnings


def _closest(student: str, folded: Mapping[str, str]) -> str:
    """' (closest: 'u002')' for the variant id nearest ``student`` (``folded``: the variant
    ids by their case-folded form), or ''."""
    match = folded.get(student.strip().casefold())
    if match is None:
        near = difflib.get_close_matches(student, list(folded.values())[:MAX_COMPARED], n=1)
        match = near[0] if near else None
    return f" (closest: '{match}')" if match is not None else ""


def limit_warnings(warnings: Sequence[str], keep: int = 5) -> list[str]:
    """The warnings with at most ``keep`` of each kind (the same text but for its quoted
    names), then one line counting the rest: 100,000 unknown columns are not 100,000 lines.

    >>> w = [f"column '{i}' is not a find" for i in range(9)] + ["other"]
    >>> limit_warnings(w, keep=2)[1:]
    ["column '1' is not a find", "... and 7 more like: column '…' is not a find", 'other']
    """
    kinds: dict[str, list[str]] = {}
    for warning in warnings:
        kinds.setdefault(_QUOTED.sub("'…'", warning), []).append(warning)
    out: list[str] = []
    for kind, same in kinds.items():
        out += same[:keep]
        if len(same) > keep:
            out.append(f"... and {len(same) - keep:,} more like: {kind}")
    return out


def _text(path: Path) -> str:
    raw = read_capped(path, MAX_ANSWERS_BYTES)
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise SpecError(f"{path} is not UTF-8 text", None, "save the CSV as UTF-8") from None
    nul = text.find("\0")
    if nul >= 0:  # never copied into a report
        line = text.count("\n", 0, nul) + 1
        column = nul - text.rfind("\n", 0, nul)
        raise SpecError(
            "the answers file holds a NUL byte",
            Position(str(path), line, column),
            "a NUL is not text (a binary or UTF-16 file?): save the CSV as UTF-8 text",
        )
    return text


def _keys(request: GradeRequest, spec: Spec) -> Keys:
    if request.variants is None:
        return base_keys(spec, request.options)
    table = read_variant_table(request.variants)
    check_variant_cells(spec, table)
    return variant_keys(spec, table.cells, request.options)


def check_variant_cells(spec: Spec, table: VariantTable) -> None:
    """Every cell of a variants file read and of its given's dimension, before any solve:
    a bad cell stops the run at its ``file:line:column`` (each distinct cell checked once)."""
    givens = {g.name for g in spec.givens}
    checked: set[tuple[str, str]] = set()
    for student, cells in table.cells.items():
        for name, text in cells.items():
            if (name, text) in checked:
                continue
            where = table.where(student, name) if name in givens else table.heading(name)
            with_variant(spec, {name: text}, student, where)
            checked.add((name, text))


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
