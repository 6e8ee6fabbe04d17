"""Resolve parsed units and quantities against the registry, with positioned errors.

>>> from dynsolve.spec.parser import parse_spec
>>> given = parse_spec("given:\\n  W = 40 lb", "w.dyn").givens[0]
>>> resolve_quantity(given.quantity, "FPS", "w.dyn")
(40, Dim(L=Fraction(1, 1), M=Fraction(1, 1), T=Fraction(-2, 1)))
"""

from __future__ import annotations

from fractions import Fraction
from typing import TYPE_CHECKING

from dynsolve.errors import Position, UnitError
from dynsolve.spec.ast import Quantity, UnitExpr
from dynsolve.units import NAMED_DIMENSIONS, Dim, System, dim_of_unit, registry, suggest_unit

if TYPE_CHECKING:
    import pint
    import sympy


def resolve_unit(unit: UnitExpr, file: str) -> tuple[pint.Unit, Dim]:
    """The pint unit and dimension of a unit expression; each name is looked up alone."""
    ureg = registry()
    result = ureg.dimensionless
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
            named = ureg.Unit(factor.name)
        except Exception:  # pint raises several types for unknown names
            hint = suggest_unit(factor.name)
            raise UnitError(f"unknown unit '{factor.name}'", where, hint or "see docs") from None
        result = result * named ** float(factor.exponent)
    try:
        dim = dim_of_unit(result)
    except ValueError as exc:
        where = Position(file, unit.line, unit.column)
        raise UnitError(str(exc), where, hint="dynsolve handles mechanical units") from None
    return result, dim


def _example_unit(dimension: str) -> str:
    from dynsolve.units import natural_unit

    return f"'{natural_unit(NAMED_DIMENSIONS[dimension], 'SI') or 'rad'}'"


def resolve_dimension(unit: UnitExpr, file: str) -> Dim:
    """The dimension of a symbolic given: a dimension name (``mass``) or any unit."""
    if len(unit.factors) == 1 and unit.factors[0].exponent == 1:
        name = unit.factors[0].name
        if name in NAMED_DIMENSIONS:
            return NAMED_DIMENSIONS[name]
    try:
        return resolve_unit(unit, file)[1]
    except UnitError as exc:
        names = ", ".join(list(NAMED_DIMENSIONS)[:8])
        raise UnitError(
            f"unknown dimension or unit '{unit.text}'",
            exc.position,
            hint=f"use a dimension ({names}, …) or a unit",
        ) from None


def resolve_quantity(quantity: Quantity, system: System, file: str) -> tuple[sympy.Expr, Dim]:
    """A quantity's exact value in the system's base units, and its dimension."""
    from dynsolve.units import to_base

    if quantity.unit is None:
        import sympy

        return sympy.Rational(quantity.value.numerator, quantity.value.denominator), Dim()
    unit, dim = resolve_unit(quantity.unit, file)
    return to_base(Fraction(quantity.value), unit, system), dim
