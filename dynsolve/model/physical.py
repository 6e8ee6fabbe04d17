"""Givens whose sign physics fixes: a value read for a role (a mass, μ, a stiffness …) is checked.

A coefficient of restitution lies in [0, 1]; in the same way a body's size, a spring's
stiffness, a density, g and a duration are positive, and a mass, a weight, a moment of
inertia, a radius of gyration, a coefficient of friction and an unstretched length are not
negative (a massless pulley or link beside bodies with mass, a pulley given inertia 0,
μ = 0 frictionless, a spring with no free length, a slender rod with no inertia about its
own axis); a scene in
which every body is massless is refused. A value that breaks its bound is refused before
anything is solved, at the given it comes from (or at the scene's text when it is an
expression of several givens), with the role that fixes the bound.

>>> from dynsolve.spec.ast import Name
>>> try:
...     check_sign(sympy.Integer(-60), Name("m_d", 9, 22), "a mass", NOT_NEGATIVE, {}, "d.dyn")
... except SpecError as error:
...     print(error.position, error.message)
d.dyn:9:22 m_d = -60 is used as a mass, which cannot be negative
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.numbers import real_value
from dynsolve.spec.ast import Expr, Given, Name

POSITIVE = "positive"  # > 0
NOT_NEGATIVE = "not negative"  # ≥ 0

HINTS = {
    "a mass": "a mass is never negative (0: a massless pulley or link)",
    "a weight": "a weight is never negative (0: a massless pulley or link)",
    "μs": "a coefficient of friction is never negative (0 is a smooth, frictionless contact)",
    "μk": "a coefficient of friction is never negative (0 is a smooth, frictionless contact)",
    "a spring stiffness": "a spring's stiffness k is positive (k = F/δ)",
    "a torsional stiffness": "a torsion spring's stiffness k is positive (k = M/Δθ, N·m/rad)",
    "gravity g": "g is positive (9.81 m/s², 32.2 ft/s²); 'gravity down' gives its direction; "
    "for a scene without weights, leave out the 'gravity' line",
    "a duration": "an interval's length is positive; its start and end are the two states",
    "a contact time": "a time of contact is positive (an impact lasts a short time t_c > 0)",
}


def check_sign(
    value: sympy.Expr,
    expr: Expr,
    what: str,
    bound: str,
    given_values: Mapping[sympy.Symbol, sympy.Expr],
    file: str,
    givens: Mapping[str, Given] | None = None,
) -> None:
    """Raise a positioned :class:`SpecError` when ``value`` (read from ``expr`` for the role
    ``what``) breaks ``bound`` (:data:`POSITIVE` or :data:`NOT_NEGATIVE`); symbolic values
    pass. The error points at the given when ``expr`` is one given's name (``givens``)."""
    number = real_value(value, given_values)
    if number is None:
        return
    if number > 0 or (number == 0 and bound == NOT_NEGATIVE):
        return
    shown, where, used = _source(expr, number, file, givens)
    hint = HINTS.get(what) or f"{what} is {bound}: check the given's sign"
    rule = "must be positive" if bound == POSITIVE else "cannot be negative"
    raise SpecError(f"{shown} is used as {what}{used}, which {rule}", where, hint=hint)


def check_some_mass(
    masses: Sequence[sympy.Expr],
    written: Sequence[Expr],
    given_values: Mapping[sympy.Symbol, sympy.Expr],
    file: str,
    givens: Mapping[str, Given] | None = None,
) -> None:
    """A massless body (a pulley, a link: mass 0) is an idealisation beside bodies with
    mass; a scene whose every body's mass (``masses``) is zero has nothing with inertia,
    and is refused at the first mass ``written`` (a ``mass`` or ``weight`` line's text)."""
    numbers = [real_value(value, given_values) for value in masses]
    if not masses or not written or any(n is None or n != 0 for n in numbers):
        return
    shown, where, used = _source(written[0], 0.0, file, givens)
    raise SpecError(
        f"{shown} is used as a mass{used}, and no body of the scene has mass: nothing has "
        "inertia, so no motion follows from the forces",
        where,
        hint="give the bodies their masses; a massless pulley or link is the only body of "
        "zero mass",
    )


def _source(
    expr: Expr, number: float, file: str, givens: Mapping[str, Given] | None
) -> tuple[str, Position, str]:
    """How a value is shown and where its error points: at the given when ``expr`` is one
    given's name (with the scene line that uses it), else at the scene's text."""
    given = givens.get(expr.text) if isinstance(expr, Name) and givens else None
    if given is not None and given.quantity is not None:
        unit = f" {given.quantity.unit.text}" if given.quantity.unit else ""
        shown = f"{given.name} = {given.quantity.text}{unit}"
        return shown, Position(file, given.line, given.column), f" (line {expr.line})"
    if isinstance(expr, Name):
        return f"{expr.text} = {number:g}", Position(file, expr.line, expr.column), ""
    return f"'{expr}' = {number:g}", Position(file, expr.line, expr.column), ""
