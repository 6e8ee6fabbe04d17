"""Read one student's answer cell (``4.52 m/s^2 down``) as a value in SI base units.

The cell goes through dynsolve's own answer grammar (:func:`parse_answer_cell`) and unit
table; nothing is evaluated. A cell that cannot be read raises :class:`CellError` with
the reason, which the grader reports as that part's verdict.

>>> cell = read_cell("23.8 lb")
>>> round(cell.value, 2), cell.dim == Dim.of("force"), cell.number
(105.87, True, '23.8')
>>> read_cell("4.52 m/s^2 down").value
-4.52
>>> cell = read_cell("4,52 m s⁻² downwards", decimal_comma=True)
>>> cell.value, cell.unit, cell.direction, cell.signed
(-4.52, 'm/s^2', 'down', True)
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

from dynsolve.errors import DynsolveError
from dynsolve.grade.forms import normalise
from dynsolve.quantities import resolve_unit
from dynsolve.spec.ast import UnitExpr
from dynsolve.spec.parser import parse_answer_cell, parse_unit
from dynsolve.units import Dim, UnitInfo

MAX_CELL = 80  # characters: an answer is a number, a unit and a direction word
NEGATIVE = ("cw", "down", "left")  # the textbook convention: ccw, up, right positive
LARGEST = 1e200  # beyond this a float product would overflow: not an answer


class CellError(ValueError):
    """A cell that cannot be read; the message says why."""


@dataclass(frozen=True)
class Cell:
    """A student's answer: signed value in SI base units, its dimension and how it was written.

    ``unit`` is None for a bare number (no unit in the cell nor in the column header)."""

    value: float  # SI base units (m, kg, s, rad), direction word applied as a sign
    dim: Dim
    number: str  # the number as written, sign included: "-4.52", "1.20e3"
    unit: str | None  # the unit as written ("" for none given but taken from the header)
    factor: float  # the unit's size in SI base units
    direction: str  # the direction word (cw, ccw, up, down, left, right) or ""
    signed: bool = False  # a sign (-, +) or a direction word was written


@functools.lru_cache(maxsize=65536)
def read_cell(text: str, header_unit: str = "", decimal_comma: bool = False) -> Cell:
    """The cell ``text``; a bare number takes ``header_unit`` (a column header's unit).
    ``decimal_comma``: the file writes decimals with a comma (see :mod:`.forms`).

    >>> read_cell("11.3", "rad/s^2").unit
    ''
    >>> read_cell("11.3").unit is None
    True
    """
    text = original = text.strip()
    if len(text) > MAX_CELL:
        raise CellError(f"the answer is longer than {MAX_CELL} characters")
    try:
        written = normalise(text, decimal_comma)
    except ValueError as error:
        raise CellError(str(error)) from None
    text = written.text
    number, unit, direction = _parsed(text)
    unit_text = _unit_text(unit, original) if unit is not None else ""
    if direction and (number.startswith("-") or written.plus):
        raise CellError(f"'{text}' has both a sign and a direction word: give one")
    if unit_text:
        info, shown = _unit(unit_text), unit_text
    elif header_unit:
        info, shown = _unit(header_unit), ""
    else:
        info, shown = UnitInfo(1.0, same_dim(Dim())), None
    magnitude = float(number)
    if not math.isfinite(magnitude) or abs(magnitude) * info.factor > LARGEST:
        raise CellError(f"{number} is out of range")
    value = magnitude * info.factor * (-1.0 if direction in NEGATIVE else 1.0)
    signed = bool(direction) or written.plus or number.startswith("-")
    return Cell(value, info.dim, number, shown, info.factor, direction, signed)


def _parsed(text: str) -> tuple[str, UnitExpr | None, str]:
    """Number text, unit and direction word, through the answers grammar."""
    try:
        answer = parse_answer_cell(text)
    except DynsolveError as error:
        raise CellError(f"cannot read '{text}': {error.message}") from None
    if answer.tolerance is not None:
        raise CellError(f"'{text}' has a tolerance: give one value")
    assert answer.quantity is not None
    quantity = answer.quantity
    return quantity.text, quantity.unit, answer.direction or ""


def _unit_text(unit: UnitExpr, written: str) -> str:
    """The unit's text, once every name in it is known and none is raised to the power 0
    (``g0`` reads as g^0 = 1: taken silently, the number would be in the header's unit).

    >>> read_cell("0.827 g0", "ft/s^2")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    dynsolve.grade.cells.CellError: '0.827 g0': g to the power 0 is no unit at all (a 0 after ...
    """
    for factor in unit.factors:
        _unit(factor.name)  # an unknown name is unreadable whatever its power
        if factor.exponent == 0:
            gravity = " (standard gravity is g_0)" if factor.name == "g" else ""
            glued = "" if "^" in written else " (a 0 after a unit reads as ^0)"
            raise CellError(
                f"'{written}': {factor.name} to the power 0 is no unit at all{glued}: "
                f"write the unit without the 0{gravity}"
            )
    return unit.text


_DIMS: dict[Dim, Dim] = {}


def same_dim(dim: Dim) -> Dim:
    """One shared object per dimension, so that grading compares dimensions by identity.

    >>> same_dim(Dim.of("force")) is same_dim(Dim(1, 1, -2))
    True
    """
    return _DIMS.setdefault(dim, dim)


@functools.lru_cache(maxsize=4096)
def _unit(text: str) -> UnitInfo:
    try:
        info = resolve_unit(parse_unit(text), "<cell>")
        return UnitInfo(info.factor, same_dim(info.dim))
    except DynsolveError as error:
        hint = f" ({error.hint})" if error.hint else ""
        raise CellError(f"unit '{text}': {error.message}{hint}") from None


def significant_figures(number: str) -> int:
    """Significant figures as written: leading zeros never count; every other digit does,
    trailing zeros of a whole number included (``450`` has 3: the doubt goes to the student).

    >>> [significant_figures(n) for n in ("4.5", "4.50", "0.0452", "450", "-1.20e3", "0")]
    [2, 3, 3, 3, 3, 1]
    """
    mantissa = number.lstrip("+-").lower().split("e")[0]
    digits = mantissa.replace(".", "").lstrip("0")
    return len(digits) or 1


def fewest_figures(number: str) -> int:
    """Significant figures with the doubt going the other way: the trailing zeros of a
    whole number do not count (``110`` may be 105.86 rounded to 2 figures).

    >>> [fewest_figures(n) for n in ("110", "1.10", "0.011", "1.1e2", "0")]
    [2, 3, 2, 2, 1]
    """
    mantissa = number.lstrip("+-").lower().split("e")[0]
    if "." in mantissa:
        return significant_figures(number)
    return len(mantissa.strip("0")) or 1


def decimal_digits(number: str) -> int:
    """The decimal place the number is written to: digits after the point, less the power
    of ten (``1.5e2`` = 150 is written to the tens, -1; ``4.52e-1`` = 0.452 to 3 decimals).

    >>> decimal_digits("4.520"), decimal_digits("12"), decimal_digits("1.5e2")
    (3, 0, -1)
    >>> decimal_digits("4.52e-1"), decimal_digits("2E+3")
    (3, -3)
    """
    mantissa, _, exponent = number.lower().partition("e")
    return len(mantissa.partition(".")[2]) - (int(exponent) if exponent else 0)
