"""Grading semantics: judge one student cell against one expected answer under a rule.

Values are compared in SI base units, signed by the textbook convention (ccw, up, right
positive; a direction word gives the sign). The comparison is one of:

- tolerance (default): ``|s - k| <= max(atol, rtol |k|)``, rtol 1 % unless set;
- ``sigfig N``: the number must be WRITTEN with at least N significant figures, and lie
  within 0.51 units of the N-th significant figure of the key (PrairieLearn's
  ``pl-number-input`` sigfig rule), so with a key of 4.5168 and N = 3, ``4.52`` and
  ``4.517`` pass, ``4.5`` fails (too few figures) and ``4.53`` fails (wrong value);
- ``decdig N``: written to at least N decimal places, and within 0.51·10^-N of the key
  expressed in the unit the student wrote. In e-notation the place is the mantissa's
  decimals less the exponent: ``4.52e-1`` is written to 3 decimals, ``1.5e2`` to the tens.

A right magnitude with the wrong sign or direction, or a right value with too few
figures, earns the ``partial`` credit (0 unless set).

>>> from dynsolve.grade.cells import read_cell
>>> key = Key("a", -4.5168, Dim.of("acceleration"), "m/s^2")
>>> judge("4.52 m/s^2 down", key, Rule()).verdict
'correct'
>>> flipped = judge("4.52 m/s^2", key, Rule(partial=0.5))
>>> flipped.verdict, flipped.credit
('sign', 0.5)
>>> judge("4.5 m/s^2 down", key, Rule(sigfig=3)).verdict
'sigfig'
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from fractions import Fraction

from dynsolve.grade.cells import (
    Cell,
    CellError,
    decimal_digits,
    read_cell,
    same_dim,
    significant_figures,
)
from dynsolve.quantities import resolve_unit
from dynsolve.spec.ast import GradingRule
from dynsolve.units import Dim, natural_unit

DEFAULT_RTOL = 0.01
SIGFIG_SLACK = 0.51  # units of the last figure: PrairieLearn's allowance for rounding
VERDICTS = ("correct", "sign", "sigfig", "wrong", "dimension", "unreadable", "missing")


@dataclass(frozen=True)
class Key:
    """One expected answer: signed value in SI base units (cw/down/left negative)."""

    name: str
    value: float
    dim: Dim
    unit: str  # the display unit for feedback ("m/s^2")
    factor: float = 1.0  # the display unit's size in SI base units

    def __post_init__(self) -> None:
        object.__setattr__(self, "dim", same_dim(self.dim))


@dataclass(frozen=True)
class Rule:
    """How one part is judged (see the module docstring)."""

    rtol: float = DEFAULT_RTOL
    atol: float = 0.0  # SI base units
    sigfig: int = 0
    decdig: int = 0
    weight: float = 1.0
    partial: float = 0.0


@dataclass(frozen=True)
class PartResult:
    """The verdict on one part: one of VERDICTS, credit 0..1, and a sentence."""

    verdict: str
    credit: float
    detail: str
    value: float | None = None  # the student's value in SI base units, when read


def judge(text: str, key: Key, rule: Rule, header_unit: str = "") -> PartResult:
    """Judge the cell ``text`` against ``key`` (a bare number takes ``header_unit``)."""
    if not text.strip():
        return PartResult("missing", 0.0, "no answer")
    try:
        cell = read_cell(text, header_unit)
    except CellError as error:
        return PartResult("unreadable", 0.0, str(error))
    if cell.unit is None and not key.dim.dimensionless:
        return PartResult(
            "unreadable", 0.0, f"no unit: write it ({key.unit}) or put it in the column header"
        )
    if cell.dim is not key.dim and cell.dim != key.dim:
        return PartResult(
            "dimension",
            0.0,
            f"{cell.unit or 'a bare number'} is {_dimension(cell.dim)}; "
            f"{key.name} is {_dimension(key.dim)}",
            cell.value,
        )
    return _compare(cell, key, rule)


def _compare(cell: Cell, key: Key, rule: Rule) -> PartResult:
    short = _short(cell, rule)
    if short:  # fewer figures or decimals than asked: judged to the figures written
        if rule.decdig:  # to the decimal place written (0 or less: units, tens, …)
            place = SIGFIG_SLACK * 10.0 ** -decimal_digits(cell.number)
            factor = cell.factor or key.factor
            right = abs(cell.value - key.value) / factor <= place
        else:
            right = matches(cell.value, key, replace(rule, sigfig=significant_figures(cell.number)))
        if right:
            return PartResult("sigfig", rule.partial, short, cell.value)
    elif matches(cell.value, key, rule, cell):
        return PartResult("correct", 1.0, "", cell.value)
    if key.value and matches(-cell.value, key, rule, cell):
        return PartResult(
            "sign",
            rule.partial,
            "right magnitude, wrong sign or direction (ccw, up, right are positive)",
            cell.value,
        )
    return PartResult("wrong", 0.0, f"off by {_off(cell.value, key)}", cell.value)


def _short(cell: Cell, rule: Rule) -> str:
    """Why the number is written with too few figures or decimals, or ""."""
    figures = significant_figures(cell.number)
    if rule.sigfig and figures < rule.sigfig:
        plural = "s" * (figures != 1)
        return f"{cell.number} has {figures} significant figure{plural}; give {rule.sigfig}"
    if rule.decdig and decimal_digits(cell.number) < rule.decdig:
        return f"{cell.number} is written to fewer than {rule.decdig} decimals; give {rule.decdig}"
    return ""


def matches(value: float, key: Key, rule: Rule, cell: Cell | None = None) -> bool:
    """Whether ``value`` (SI base units) matches the key under ``rule``'s comparison.

    >>> k = Key("T", 105.863, Dim.of("force"), "N")
    >>> matches(106.0, k, Rule(sigfig=3)), matches(107.0, k, Rule(sigfig=3))
    (True, False)
    """
    target = key.value
    if rule.sigfig:
        if target == 0:
            return abs(value) <= rule.atol
        place = math.floor(math.log10(abs(target))) - rule.sigfig + 1
        return abs(value - target) <= SIGFIG_SLACK * 10.0**place
    if rule.decdig:
        factor = cell.factor if cell is not None and cell.factor else key.factor
        return abs(value - target) / factor <= SIGFIG_SLACK * 10.0**-rule.decdig
    return abs(value - target) <= max(rule.atol, rule.rtol * abs(target)) * (1 + 1e-12)


def _off(value: float, key: Key) -> str:
    if key.value == 0:
        return f"{value / key.factor:.4g} {key.unit}".strip()
    return f"{100 * abs(value - key.value) / abs(key.value):.3g} %"


def _dimension(dim: Dim) -> str:
    unit = natural_unit(dim, "SI")
    return f"{dim.name}" + (f" ({unit})" if unit else "")


def rules_for(
    parts: Sequence[str], spec_rules: Sequence[GradingRule], overrides: Rule | None = None
) -> dict[str, Rule]:
    """Each part's rule: defaults, then the spec's ``grading:`` lines (general ones first,
    then the part's own: a part's ``rtol`` makes it graded by tolerance even under a
    general ``sigfig``), then ``overrides`` from the command line (its non-default fields).

    >>> from dynsolve.spec.grading_line import parse_grading_line
    >>> lines = [parse_grading_line(t, "p", 1, 0) for t in ("sigfig 3", "T weight 2")]
    >>> r = rules_for(["T", "a"], lines)
    >>> r["T"].weight, r["a"].weight, r["a"].sigfig
    (2.0, 1.0, 3)
    """
    out: dict[str, Rule] = {}
    for part in parts:
        rule = Rule()
        for spec_rule in sorted(spec_rules, key=lambda r: bool(r.part)):
            if spec_rule.part in ("", part):
                rule = _apply(rule, spec_rule.key, spec_rule.value, spec_rule)
        if overrides is not None:
            default = Rule()
            changed = {
                f: getattr(overrides, f)
                for f in ("rtol", "atol", "sigfig", "decdig", "partial")
                if getattr(overrides, f) != getattr(default, f)
            }
            if changed.get("sigfig"):
                changed.setdefault("decdig", 0)
            if changed.get("decdig"):
                changed.setdefault("sigfig", 0)
            rule = replace(rule, **changed)
        out[part] = rule
    return out


def _apply(rule: Rule, key: str, value: Fraction, source: GradingRule) -> Rule:
    if key == "atol":
        size = resolve_unit(source.unit, "<grading>").factor if source.unit else 1.0
        return replace(rule, atol=float(value) * size)
    if key in ("sigfig", "decdig"):
        other = "decdig" if key == "sigfig" else "sigfig"
        return replace(rule, **{key: int(value), other: 0})
    if key == "rtol" and source.part:  # a part's own tolerance replaces a general sigfig
        return replace(rule, rtol=float(value), sigfig=0, decdig=0)
    return replace(rule, **{key: float(value)})
