"""Resolve parsed units and quantities against the unit table, with positioned errors.

>>> from dynsolve.spec.parser import parse_spec
>>> given = parse_spec("given:\\n  W = 40 lb", "w.dyn").givens[0]
>>> resolve_quantity(given.quantity, "FPS", "w.dyn")
(40, Dim(L=Fraction(1, 1), M=Fraction(1, 1), T=Fraction(-2, 1)))
>>> round(convert(1.0, "N", "FPS"), 4)
4.4482
"""

from __future__ import annotations

import functools
from fractions import Fraction
from typing import TYPE_CHECKING

from dynsolve.errors import Position, UnitError
from dynsolve.spec.ast import Quantity, UnitExpr
from dynsolve.units import (
    NAMED_DIMENSIONS,
    ONE,
    Dim,
    System,
    UnitInfo,
    from_base,
    natural_unit,
    suggest_unit,
    to_base,
    unit_named,
)

if TYPE_CHECKING:
    import sympy


def resolve_unit(unit: UnitExpr, file: str) -> UnitInfo:
    """The size and dimension of a unit expression; each name is looked up alone."""
    result = ONE
    for factor in unit.factors:
        where = Position(file, factor.line, factor.column)
        if factor.name in NAMED_DIMENSIONS:
            raise UnitError(
                f"'{factor.name}' is a dimension, not a unit",
                where,
                hint=f"write a unit such as {_example_unit(factor.name)}, "
                f"or 'name: {factor.name}' for a symbolic given",
            )
        try:
            named = unit_named(factor.name)
        except ValueError as exc:
            raise UnitError(str(exc), where, hint="dynsolve handles mechanical units") from None
        if named is None:
            raise UnitError(f"unknown unit '{factor.name}'", where, _unit_hint(factor.name))
        result = result * named**factor.exponent
    return result


def _unit_hint(name: str) -> str:
    """A hint for an unknown unit: a power written without '^' (``s2``), or the nearest name.

    >>> _unit_hint("s2")
    "write the power with '^': 's^2'"
    """
    stem = name.rstrip("0123456789")
    power = name[len(stem) :]
    if stem and power and power != "0" and unit_named(stem) is not None:
        return f"write the power with '^': '{stem}^{power}'"
    return suggest_unit(name) or "see docs/spec-language.md for the units dynsolve knows"


def _example_unit(dimension: str) -> str:
    return f"'{natural_unit(NAMED_DIMENSIONS[dimension], 'SI') or 'rad'}'"


def resolve_dimension(unit: UnitExpr, file: str) -> Dim:
    """The dimension of a symbolic given: a dimension name (``mass``) or any unit."""
    if len(unit.factors) == 1 and unit.factors[0].exponent == 1:
        name = unit.factors[0].name
        if name in NAMED_DIMENSIONS:
            return NAMED_DIMENSIONS[name]
    try:
        return resolve_unit(unit, file).dim
    except UnitError as exc:
        names = ", ".join(list(NAMED_DIMENSIONS)[:8])
        raise UnitError(
            f"unknown dimension or unit '{unit.text}'",
            exc.position,
            hint=f"use a dimension ({names}, …) or a unit",
        ) from None


def resolve_quantity(quantity: Quantity, system: System, file: str) -> tuple[sympy.Expr, Dim]:
    """A quantity's exact value in the system's base units, and its dimension."""
    if quantity.unit is None:
        import sympy

        return sympy.Rational(quantity.value.numerator, quantity.value.denominator), Dim()
    unit = resolve_unit(quantity.unit, file)
    return to_base(Fraction(quantity.value), unit, system), unit.dim


@functools.cache
def unit_info(text: str) -> UnitInfo:
    """A unit written as text (``m/s^2``, ``lb*ft``; ``""`` is a pure number)."""
    if not text:
        return ONE
    from dynsolve.spec.parser import parse_unit

    return resolve_unit(parse_unit(text), "<unit>")


def convert(value: float, unit: str, system: System) -> float:
    """A value in the system's base units expressed in ``unit`` (angles: ``""`` is rad)."""
    return from_base(value, unit_info(unit), system)
