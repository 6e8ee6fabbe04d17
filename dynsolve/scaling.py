"""Rescaling a parsed spec's masses and lengths by 10^k, through the AST (never the text).

A given whose unit has dimension mass^a length^b (times any power of time) is multiplied
by 10^(k*(a+b)); so are the answer key's expected values and absolute tolerances. A
correct solver then returns every answer multiplied by the same factor of its own
dimension: the property the scale-invariance test and ``bench/accuracy.py`` check.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec("given:\\n  m = 2 kg\\n  h = 3 m\\nequations:\\n  E = m*g*h\\nfind: E\\n")
>>> [g.quantity.value for g in scale_spec(spec, 2).givens]
[Fraction(200, 1), Fraction(300, 1), Fraction(981, 1)]
"""

from __future__ import annotations

from dataclasses import replace
from fractions import Fraction

from dynsolve.results import Solution
from dynsolve.spec.ast import Given, Quantity, Spec, Tolerance, UnitExpr
from dynsolve.units import GRAVITY, Dim, registry, unit_named

__all__ = ["dim_scale", "exact_scale", "mismatches", "scale_spec", "unit_scale"]


def dim_scale(dim: Dim, k: int) -> Fraction:
    """The factor 10^(k*(a+b)) for a dimension mass^a length^b time^c.

    >>> dim_scale(Dim(1, 1, -2), 3), dim_scale(Dim(0, 0, -1), 9)
    (Fraction(1000000, 1), Fraction(1, 1))
    """
    power = k * (dim.M + dim.L)
    if power.denominator != 1:
        raise ValueError(f"a fractional power of ten 10^{power} is not exact")
    return Fraction(10) ** int(power)


def unit_scale(unit: str, k: int) -> Fraction:
    """The factor an answer in ``unit`` (pint-parsable, lb = pound-force) scales by.

    >>> unit_scale("N*m", 1), unit_scale("rad/s", 5)
    (Fraction(1000, 1), Fraction(1, 1))
    """
    from dynsolve.units import dim_of_unit

    return dim_scale(dim_of_unit(registry().Unit(unit)), k) if unit else Fraction(1)


def _unit_dim(unit: UnitExpr | None) -> Dim:
    """The dimension of a written unit (``kg*m^2``), a product of its factors."""
    dim = Dim()
    for factor in unit.factors if unit is not None else ():
        info = unit_named(factor.name)
        if info is None:
            raise ValueError(f"unknown unit {factor.name!r}")
        dim = dim * info.dim**factor.exponent
    return dim


def _scaled(quantity: Quantity | None, k: int) -> Quantity | None:
    if quantity is None:
        return None
    factor = dim_scale(_unit_dim(quantity.unit), k)
    value = quantity.value * factor
    return replace(quantity, value=value, text=str(float(value)))


def _scaled_tolerance(tolerance: Tolerance | None, k: int) -> Tolerance | None:
    if tolerance is None or tolerance.kind != "abs":
        return tolerance
    return replace(tolerance, value=tolerance.value * dim_scale(_unit_dim(tolerance.unit), k))


def _default_g(spec: Spec) -> Given:
    """The default gravitational acceleration of the spec's unit system as a given."""
    from dynsolve.spec.parser import parse_spec

    value, unit = GRAVITY[spec.system]
    return parse_spec(f"given:\n  g = {value} {unit}\nequations:\n  x = g\nfind: x\n").givens[0]


def scale_spec(spec: Spec, k: int) -> Spec:
    """``spec`` with every given, expected answer and absolute tolerance scaled by 10^k
    per unit of mass and length in its dimension; the default g, unless given, is added
    as a scaled given (it is a length per time squared)."""
    givens = tuple(replace(g, quantity=_scaled(g.quantity, k)) for g in spec.givens)
    if not any(g.name == "g" for g in givens):  # the default g is a length per time²: it scales
        givens += (replace(_default_g(spec), quantity=_scaled(_default_g(spec).quantity, k)),)
    answers = tuple(
        replace(a, quantity=_scaled(a.quantity, k), tolerance=_scaled_tolerance(a.tolerance, k))
        for a in spec.answers
    )
    return replace(spec, givens=givens, answers=answers)


def exact_scale(spec: Spec, k: int) -> int:
    """``k``, or the nearest even scale toward 0 when a given's unit has a half power of mass
    or length (k = 3 m^(1/2)/s^(3/2): 10^(9/2) is irrational, 10^8 is not).

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  k = 3 m^(1/2)/s\\nequations:\\n  v = k^2\\nfind: v\\n")
    >>> exact_scale(spec, 9), exact_scale(spec, -3), exact_scale(spec, 4)
    (8, -2, 4)
    """
    try:
        scale_spec(spec, k)
    except ValueError as error:
        if "fractional power of ten" not in str(error) or not k % 2:
            raise
        return k - 1 if k > 0 else k + 1
    return k


def mismatches(base: Solution, scaled: Solution, k: int, tolerance: float = 1e-9) -> list[str]:
    """How ``scaled`` (the spec solved after :func:`scale_spec` by ``k``) fails to be
    ``base`` rescaled: answers off by more than ``tolerance`` relative, or checks that
    pass or fail differently. Empty when the solve is scale invariant.

    >>> from dynsolve.pipeline import solve_spec
    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")
    >>> mismatches(solve_spec(spec), solve_spec(scale_spec(spec, 9)), 9)
    []
    """
    found = []
    before = {row.name: row for row in base.answers}
    for row in scaled.answers:
        old = before.get(row.name)
        if old is None or (old.value is None) != (row.value is None):
            found.append(f"{row.name}: {old and old.value} became {row.value}")
            continue
        if old.value is None or row.value is None:
            continue
        want = old.value * float(unit_scale(old.unit, k))
        if abs(row.value - want) > tolerance * abs(want):
            found.append(f"{row.name}: expected {want!r} ({old.value!r} scaled), got {row.value!r}")
    verdicts = {c.name: c.status for c in base.checks}
    for check in scaled.checks:
        if check.name == "unused givens" and check.name not in verdicts:
            continue  # the default g added as a given by scale_spec, when nothing uses it
        if verdicts.get(check.name, check.status) != check.status:
            found.append(f"check {check.name}: {verdicts.get(check.name)} became {check.status}")
    return found
