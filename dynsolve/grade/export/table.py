"""A problem's variants as a quiz needs them: each variant's givens as text, each part's
expected answer in its display unit, and the absolute tolerance its grading rule allows.

Every quiz export (Moodle XML, PrairieLearn) is written from this table, so both grade a
variant exactly as ``dynsolve grade`` would: the answers come from
:func:`dynsolve.grade.expected.expected_answers` (the closed form where it answers, a
full solve elsewhere) and the rules from the spec's ``grading:`` section and the options.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 2 kg   # block mass
...   F = 10 N
... equations:
...   F = m*a
... find: a [m/s^2]
... ''', "p.dyn")
>>> table = variant_table(spec, {"s1": {"m": "4 kg"}})
>>> row = table.variants[0]
>>> row.givens["m"], row.answers["a"].value, row.answers["a"].tolerance  # 10/4, 1 %
('4 kg', 2.5, 0.025)
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

from dynsolve.grade.cells import CellError, read_cell, same_dim
from dynsolve.grade.expected import expected_answers
from dynsolve.grade.export.target import ExportError
from dynsolve.grade.semantics import SIGFIG_SLACK, Rule, rules_for
from dynsolve.quantities import unit_info
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions
from dynsolve.units import Dim

BASE = "base"  # the one row of a problem exported without variants


@dataclass(frozen=True)
class GivenLine:
    """A given as the question states it: its name and the spec's comment."""

    name: str
    description: str


@dataclass(frozen=True)
class Part:
    """A find: its name, display unit, rule, and whether a direction goes with it."""

    name: str
    unit: str
    rule: Rule
    directed: bool  # the answer is a magnitude; the key states a direction word


@dataclass(frozen=True)
class Answer:
    """One part's expected answer for one variant, in the part's display unit."""

    value: float  # a magnitude where the part is directed, else signed
    direction: str
    tolerance: float  # absolute, in the display unit, as the part's rule allows


@dataclass(frozen=True)
class Variant:
    """One student's variant: the givens' text (``66 kg``) and the expected answers."""

    student: str
    givens: Mapping[str, str]
    answers: Mapping[str, Answer]


@dataclass(frozen=True)
class VariantTable:
    """Everything a quiz export writes."""

    title: str
    givens: tuple[GivenLine, ...]
    parts: tuple[Part, ...]
    variants: tuple[Variant, ...]
    warnings: tuple[str, ...] = ()


def variant_table(
    spec: Spec,
    variants: Mapping[str, Mapping[str, str]] | None,
    options: SolveOptions | None = None,
    overrides: Rule | None = None,
    atol: str = "",
) -> VariantTable:
    """The table of ``variants`` (student → given cells; None: the problem as written, one
    row named ``base``). A variant that cannot be solved stops the export, naming it.
    ``atol`` (``0.01 m/s``) sets the absolute tolerance of the parts of its dimension."""
    options = options or SolveOptions()
    rows = dict(variants) if variants else {BASE: {}}
    result = expected_answers(spec, rows, options)
    failed = [(s, result[s].error) for s in rows if result[s].error]
    if failed:
        student, why = failed[0]
        raise ExportError(
            f"student {student}: no expected answer ({why})"
            + (f"; {len(failed) - 1} more students fail" if len(failed) > 1 else ""),
            hint="fix or redraw these variants (dynsolve variants) before exporting",
        )
    first = result[next(iter(rows))]
    rules = rules_for([f.name for f in spec.finds], spec.grading, overrides)
    names = list(first.answers)
    if atol:
        rules = with_atol(rules, {n: first.answers[n].dim for n in names}, atol)
    parts = tuple(
        Part(
            n,
            first.answers[n].unit,
            rules[n],
            any(result[s].answers[n].direction for s in rows),
        )
        for n in names
    )
    out = []
    for student, cells in rows.items():
        answers = {}
        for part in parts:
            expected = result[student].answers[part.name]
            if expected.unit != part.unit:
                raise ExportError(
                    f"student {student}: {part.name} is shown in {expected.unit}, "
                    f"the others' in {part.unit}",
                    hint="export the SI and US customary variants separately",
                )
            value = expected.value / unit_info(part.unit).factor
            answers[part.name] = Answer(value, expected.direction, tolerance(part, value))
        out.append(Variant(student, _given_texts(spec, cells), answers))
    lines = tuple(GivenLine(g.name, g.description) for g in spec.givens if g.quantity)
    title = spec.title or "dynsolve problem"
    return VariantTable(title, lines, parts, tuple(out), zero_key_warnings(parts, out))


def zero_key_warnings(parts: Sequence[Part], variants: Sequence[Variant]) -> tuple[str, ...]:
    """A warning per part whose key is 0 for some variant with no tolerance around it:
    only an answer of exactly 0 would be accepted there."""
    out = []
    for part in parts:
        zero = [v.student for v in variants if not v.answers[part.name].tolerance]
        if zero:
            out.append(
                f"the key of {part.name} is 0 for {zero[0]}"
                + (f" and {len(zero) - 1} more" if len(zero) > 1 else "")
                + " with no tolerance: only exactly 0 is accepted; set one, e.g. "
                + f"--atol '{f'0.01 {part.unit}'.strip()}'"
            )
    return tuple(out)


def with_atol(rules: dict[str, Rule], dims: Mapping[str, Dim], text: str) -> dict[str, Rule]:
    """The rules with ``text``'s absolute tolerance on every part of its dimension.

    >>> rules = with_atol({"a": Rule(), "T": Rule()}, {"a": Dim(L=1, T=-2), "T": Dim(1, 1, -2)},
    ...                   "0.02 m/s^2")
    >>> rules["a"].atol, rules["T"].atol
    (0.02, 0.0)
    """
    try:
        cell = read_cell(text)
    except CellError as error:
        raise ExportError(f"--atol {text}: {error}", hint="e.g. --atol '0.01 m/s'") from None
    matched = {n for n, dim in dims.items() if same_dim(dim) == same_dim(cell.dim)}
    if not matched or cell.unit is None:
        raise ExportError(
            f"--atol {text} matches the dimension of no part",
            hint="give a value with the unit of a part, e.g. --atol '0.01 m/s^2'",
        )
    return {n: replace(r, atol=abs(cell.value)) if n in matched else r for n, r in rules.items()}


def tolerance(part: Part, value: float) -> float:
    """The absolute tolerance (display unit) that ``part``'s rule allows around ``value``:
    ``max(atol, rtol·|value|)``; for ``sigfig N``, half a unit (0.51) of the N-th figure;
    for ``decdig N``, 0.51·10^-N.

    >>> rule = Rule(sigfig=3)
    >>> round(tolerance(Part("a", "m/s^2", rule, False), 4.5168), 6)  # 0.51 x 10^-2
    0.0051
    """
    rule = part.rule
    atol = rule.atol / unit_info(part.unit).factor
    if rule.sigfig and value:
        return SIGFIG_SLACK * 10 ** (math.floor(math.log10(abs(value))) - rule.sigfig + 1)
    if rule.decdig:
        return SIGFIG_SLACK * 10 ** (-rule.decdig)
    return max(atol, rule.rtol * abs(value))


def _given_texts(spec: Spec, cells: Mapping[str, str]) -> dict[str, str]:
    """Every valued given as text with its unit: the variant's cell, else the spec's."""
    out = {}
    for given in spec.givens:
        if given.quantity is None:
            continue
        unit = given.quantity.unit.text if given.quantity.unit else ""
        out[given.name] = cells.get(given.name) or f"{given.quantity.text} {unit}".strip()
    return out
