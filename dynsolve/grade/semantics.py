"""Grading semantics: judge one student cell against one expected answer under a rule.

Values are compared in SI base units, signed by the textbook convention (ccw, up, right
positive). How a cell's sign is read:

- a direction word sets the sign along the axis it names, and must name the key's axis:
  ``left`` for a downward acceleration, or ``down`` for an angular one, is the ``sign``
  verdict whatever the number (the senses of rotation are cw and ccw);
- a bare positive number is a magnitude where the key's sign is a direction (see
  :func:`directed`): right when it matches the key's size, as a textbook writes
  ``11.3 rad/s^2`` for a drum turning clockwise. A ``signed`` rule takes it as positive
  instead (a course that wants signs), as it always is for a signed scalar (work);
- an explicit sign (``-4.52``, ``+4.52``) is taken as written.

A key stated as an angle (``30.0° below the horizontal, to the left``) points along two
axes: its vertical word and its horizontal word (``down``, ``left``) both agree with it,
the opposite words (``up``, ``right``) are reversed; the value compared is the magnitude.
A sign agrees when the key's two words share it by the convention (down-left is negative,
up-right positive; a bare number under ``signed`` is positive); for a key pointing up-left
or down-right a sign cannot say which way, and is ``unreadable`` (a bare number is its
magnitude there, even under ``signed``).

The comparison is one of:

- tolerance (default): ``|s - k| <= max(atol, rtol |k|)``, rtol 1 % unless set;
- ``sigfig N``: the number must be WRITTEN with at least N significant figures, and lie
  within 0.51 units of the N-th significant figure of the key expressed in the unit the
  student wrote (PrairieLearn's ``pl-number-input`` sigfig rule), so with a key of
  4.5168 and N = 3, ``4.52`` and ``4.517`` pass, ``4.5`` fails (too few figures) and
  ``4.53`` fails (wrong value); ``14.8 ft/s^2`` (the key is 14.819 ft/s^2) passes;
- ``decdig N``: written to at least N decimal places, and within 0.51·10^-N of the key
  expressed in the unit the student wrote. In e-notation the place is the mantissa's
  decimals less the exponent: ``4.52e-1`` is written to 3 decimals, ``1.5e2`` to the tens.

A right magnitude with the wrong sign or direction, or a right value with too few
figures, earns the ``partial`` credit (0 unless set). A bare ``0`` is zero in any unit.

>>> from dynsolve.grade.cells import read_cell
>>> key = Key("a", -4.5168, Dim.of("acceleration"), "m/s^2", direction="down")
>>> judge("4.52 m/s^2 down", key, Rule()).verdict, judge("4.52 m/s^2", key, Rule()).verdict
('correct', 'correct')
>>> flipped = judge("4.52 m/s^2 up", key, Rule(partial=0.5))
>>> flipped.verdict, flipped.credit
('sign', 0.5)
>>> judge("4.52 m/s^2 left", key, Rule()).detail
"a is down: 'left' is along another axis (give up or down)"
>>> judge("4.52 m/s^2", key, Rule(signed=True)).verdict
'sign'
>>> judge("4.5 m/s^2 down", key, Rule(sigfig=3)).verdict
'sigfig'
>>> judge("4.52 m/s^2 up", key, Rule()).detail
"right magnitude, wrong direction: a is down ('up' is the other way; give down)"
>>> down_left = "30.0° below the horizontal, to the left"
>>> slope = Key("F", 19.3, Dim.of("force"), "N", direction=down_left)
>>> [judge(f"19.3 N {w}", slope, Rule()).verdict for w in ("left", "down", "right", "up")]
['correct', 'correct', 'sign', 'sign']
>>> judge("-19.3 N", slope, Rule()).verdict, judge("+19.3 N", slope, Rule()).verdict
('correct', 'sign')
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, replace
from fractions import Fraction

from dynsolve.grade.cells import (
    NEGATIVE,
    Cell,
    CellError,
    decimal_digits,
    fewest_figures,
    read_cell,
    same_dim,
    significant_figures,
)
from dynsolve.quantities import resolve_unit
from dynsolve.spec.ast import GradingRule
from dynsolve.units import Dim, natural_unit

DEFAULT_RTOL = 0.01
SIGFIG_SLACK = 0.51  # units of the last figure: PrairieLearn's allowance for rounding
NO_ANSWER = ("-", "\u2013", "\u2014")  # Moodle's mark for a question not answered
AXES = {"cw": "rotation", "ccw": "rotation", "up": "vertical", "down": "vertical"}
AXES |= {"left": "horizontal", "right": "horizontal"}
OPPOSITE = {"cw": "ccw", "ccw": "cw", "up": "down", "down": "up", "left": "right", "right": "left"}
_OBLIQUE = re.compile(r"° (above|below) the horizontal, to the (left|right)$")
PAIRS = {"rotation": "cw or ccw", "vertical": "up or down", "horizontal": "left or right"}
ANGULAR_UNITS = ("rad", "deg", "rev", "rpm")
LINEAR = frozenset(
    Dim.of(name) for name in ("length", "velocity", "acceleration", "force", "momentum")
)
VERDICTS = ("correct", "sign", "sigfig", "wrong", "dimension", "unreadable", "missing")


@dataclass(frozen=True)
class Key:
    """One expected answer: signed value in SI base units (cw/down/left negative)."""

    name: str
    value: float
    dim: Dim
    unit: str  # the display unit for feedback ("m/s^2")
    factor: float = 1.0  # the display unit's size in SI base units
    direction: str = ""  # as ``dynsolve solve`` states it: cw, down, "angle 53.1°" or ""

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
    signed: bool = False  # a bare number is taken as positive, not as a magnitude


@dataclass(frozen=True)
class PartResult:
    """The verdict on one part: one of VERDICTS, credit 0..1, and a sentence."""

    verdict: str
    credit: float
    detail: str
    value: float | None = None  # the student's value in SI base units, when read


def judge(
    text: str, key: Key, rule: Rule, header_unit: str = "", decimal_comma: bool = False
) -> PartResult:
    """Judge the cell ``text`` against ``key`` (a bare number takes ``header_unit``;
    ``decimal_comma``: the file writes ``4,52``)."""
    if not text.strip() or text.strip() in NO_ANSWER:
        return PartResult("missing", 0.0, "no answer")
    try:
        cell = read_cell(text, header_unit, decimal_comma)
    except CellError as error:
        return PartResult("unreadable", 0.0, str(error))
    if cell.unit is None and cell.value == 0:  # a bare 0 is zero in any unit
        cell = replace(cell, dim=key.dim, unit="")
    if cell.unit is None and not key.dim.dimensionless:
        return PartResult(
            "unreadable",
            0.0,
            f"no unit: write it ({key.unit}), or head the column '{key.name} [{key.unit}]' "
            "so that its bare numbers are in that unit",
        )
    if cell.dim is not key.dim and cell.dim != key.dim:
        return PartResult(
            "dimension",
            0.0,
            f"{cell.unit or 'a bare number'} is {_dimension(cell.dim)}; "
            f"{key.name} is {_dimension(key.dim)}",
            cell.value,
        )
    if not cell.signed and not rule.signed and key.value < 0 and directed(key):
        cell = replace(cell, value=-cell.value)  # a bare magnitude: the key's sense
    if len(agreeing_words(key.direction)) == 2:
        return _judge_oblique(cell, key, rule)
    misdirected = _axis_problem(cell, key)
    if misdirected:
        size = math.copysign(cell.value, key.value)
        if matches(size, key, rule, cell):
            return PartResult("sign", rule.partial, misdirected, cell.value)
        return PartResult("wrong", 0.0, f"off by {_off(size, key)}", cell.value)
    return _compare(cell, key, rule)


@functools.lru_cache(maxsize=1024)
def agreeing_words(direction: str) -> tuple[str, ...]:
    """The direction words that agree with a key's stated ``direction``: the word itself
    along one axis, the vertical and the horizontal word for an angle, none for "".

    >>> agreeing_words("cw"), agreeing_words("31.0° below the horizontal, to the left")
    (('cw',), ('down', 'left'))
    >>> agreeing_words("53.1° above the horizontal, to the right"), agreeing_words("")
    (('up', 'right'), ())
    """
    if direction in AXES:
        return (direction,)
    found = _OBLIQUE.search(direction)
    if found is None:
        return ()
    return ("up" if found[1] == "above" else "down", found[2])


def _judge_oblique(cell: Cell, key: Key, rule: Rule) -> PartResult:
    """Judge a cell against a key stated as an angle (``key.value`` is its magnitude):
    a word agrees when it is one of the key's two words, a sign when both words carry it."""
    words = agreeing_words(key.direction)
    size = abs(cell.value)
    if cell.direction and AXES[cell.direction] == "rotation":
        detail = (
            f"'{cell.direction}' is a sense of rotation; {key.name} is {key.direction} "
            f"(give {' or '.join(words)})"
        )
        if matches(size, key, rule, cell):
            return PartResult("sign", rule.partial, detail, cell.value)
        return PartResult("wrong", 0.0, f"off by {_off(size, key)}", cell.value)
    negative = [w in NEGATIVE for w in words]
    if cell.direction:
        agrees = cell.direction in words
    elif rule.signed and not cell.signed and negative[0] == negative[1]:
        agrees = not negative[0]  # a bare number taken as positive: up and right
    elif cell.signed:
        if negative[0] != negative[1]:
            return PartResult(
                "unreadable",
                0.0,
                f"a sign cannot say which way {key.name} points: it is {key.direction} "
                f"({words[0]} is {'negative' if negative[0] else 'positive'}, {words[1]} "
                f"{'negative' if negative[1] else 'positive'} by the convention); give the "
                f"magnitude, or the magnitude and {words[0]} or {words[1]}",
                cell.value,
            )
        agrees = (cell.value < 0) == negative[0]
    else:
        agrees = True  # a bare number: the magnitude
    return _compare(replace(cell, value=size if agrees else -size), key, rule)


def directed(key: Key) -> bool:
    """Whether the key's sign is a direction (so a bare number may be its magnitude): a
    direction stated with it, an angular unit, or a length, velocity, acceleration, force
    or momentum; not a signed scalar such as work or energy (-50 J is not 50 J).

    >>> directed(Key("U", -50.0, Dim.of("energy"), "J"))
    False
    """
    if key.direction:
        return True
    return any(unit in key.unit for unit in ANGULAR_UNITS) or key.dim in LINEAR


def _axis_problem(cell: Cell, key: Key) -> str:
    """Why the cell's direction word names another axis than the key's, or ""."""
    if not cell.direction:
        return ""
    said = AXES[cell.direction]
    expected = AXES.get(key.direction, "")
    if not expected:  # no direction stated with the key (equation mode): its dimension
        if any(unit in key.unit for unit in ANGULAR_UNITS):
            expected = "rotation"
        elif said == "rotation" and key.dim in LINEAR:
            return f"'{cell.direction}' is a sense of rotation; {key.name} is not angular"
        else:
            return ""
    if said == expected:
        return ""
    if expected == "rotation":
        return f"'{cell.direction}' is not a sense of rotation: give cw or ccw"
    return (
        f"{key.name} is {key.direction}: '{cell.direction}' is along another axis "
        f"(give {PAIRS[expected]})"
    )


def _compare(cell: Cell, key: Key, rule: Rule) -> PartResult:
    short = _short(cell, rule)
    if short:  # fewer figures or decimals than asked: judged to the figures written
        if rule.decdig:  # to the decimal place written (0 or less: units, tens, …)
            place = SIGFIG_SLACK * 10.0 ** -decimal_digits(cell.number)
            factor = cell.factor or key.factor
            right = abs(cell.value - key.value) / factor <= place
        else:
            figures = replace(rule, sigfig=significant_figures(cell.number))
            right = matches(cell.value, key, figures, cell)
        if right:
            return PartResult("sigfig", rule.partial, short, cell.value)
    elif matches(cell.value, key, rule, cell):
        return PartResult("correct", 1.0, "", cell.value)
    if key.value and matches(-cell.value, key, rule, cell):
        return PartResult("sign", rule.partial, _reversed(cell, key), cell.value)
    off = f"off by {_off(cell.value, key)}"
    rounded = _rounded(cell, key, rule)
    return PartResult("wrong", 0.0, f"{rounded} ({off})" if rounded else off, cell.value)


def _reversed(cell: Cell, key: Key) -> str:
    """The feedback for a right magnitude pointing the other way: the words that agree."""
    words = agreeing_words(key.direction)
    if not words:
        return "right magnitude, wrong sign or direction (ccw, up, right are positive)"
    if cell.direction:
        said = f"'{cell.direction}' is the other way"
    elif cell.signed:
        written = cell.number if cell.number.startswith("-") else f"+{cell.number}"
        said = f"'{written}' is the other way: ccw, up, right are positive"
    else:
        said = "a bare number is positive here: ccw, up, right are positive"
    give = " or ".join(words)
    return f"right magnitude, wrong direction: {key.name} is {key.direction} ({said}; give {give})"


def _rounded(cell: Cell, key: Key, rule: Rule) -> str:
    """The sentence for an answer that is the key rounded to 1 or 2 significant figures
    in the unit written (``110 N`` for 105.86 N), or ""."""
    figures = fewest_figures(cell.number)
    factor = cell.factor or key.factor
    target = abs(key.value) / factor
    if figures > 2 or target == 0 or not math.isfinite(target):
        return ""
    rounded = float(f"{target:.{figures}g}")
    if not math.isclose(abs(float(cell.number)), rounded, rel_tol=1e-9):
        return ""
    plural = "s" * (figures != 1)
    return f"rounded to {figures} significant figure{plural}: keep at least {max(rule.sigfig, 3)}"


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
    """Whether ``value`` (SI base units) matches the key under ``rule``'s comparison
    (significant figures and decimals counted in ``cell``'s unit, when given).

    >>> k = Key("T", 105.863, Dim.of("force"), "N")
    >>> matches(106.0, k, Rule(sigfig=3)), matches(107.0, k, Rule(sigfig=3))
    (True, False)
    """
    target = key.value
    if rule.sigfig:  # the figures of the key in the unit written
        if target == 0:
            return abs(value) <= rule.atol
        factor = cell.factor if cell is not None and cell.factor else 1.0
        place = math.floor(math.log10(abs(target / factor))) - rule.sigfig + 1
        return abs(value - target) / factor <= SIGFIG_SLACK * 10.0**place
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
                for f in ("rtol", "atol", "sigfig", "decdig", "partial", "signed")
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
    if key == "signed":  # 'signed' (1) or 'magnitude' (0)
        return replace(rule, signed=bool(value))
    return replace(rule, **{key: float(value)})
