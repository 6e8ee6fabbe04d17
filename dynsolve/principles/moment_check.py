"""Method II: a solved rigid body's moments balanced about other points than the one used.

The equations of a scene take moments about one point per body (the pin, G, or where the
unknown forces meet). With the solved values, the textbook's check is the moment equation
about other points P: the moment of the forces and couples about P must equal the moment
of the kinetic diagram about P,

    ΣM_P = I_G α + (r_G − r_P) × m a_G,

which holds at every point only if the force equations and the moment equation were
written and solved consistently. Each body is checked about G and about every point where
a force acts (a point where a force left unsolved has a moment arm is skipped; with fewer
than two points left there is no second point and no check); the check reports the worst
relative gap (to the size of the terms, in SI base units) and fails above
``MOMENT_AGREEMENT``.

>>> import sympy
>>> from dynsolve.model.scene import Body
>>> from dynsolve.principles.newton_euler import ForceTerm, Kinematics
>>> m, g, L, alpha = sympy.symbols("m g L alpha")
>>> rod = Body("rod", m, m * L**2 / 12, (L / 2, 0), (L / 2, 0), "rod", (L,), {}, False, "", 0, 0)
>>> weight = ForceTerm("W", "weight", "rod", (L / 2, 0), "G", (0, -1), m * g, True)
>>> pin = ForceTerm("O", "reaction", "rod", (0, 0), "O", (0, 1), m * g / 4, False)
>>> kin = Kinematics("rotation", alpha, (0, alpha * L / 2), 0)
>>> values = {m: 10, g: sympy.Rational(981, 100), L: 2, alpha: sympy.Rational(-2943, 400)}
>>> check = balance("rod", rod, [weight, pin], [], kin, values)
>>> check.passed, check.name
(True, 'second moment point: rod')
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy

from dynsolve.model.scene import Body, Vec
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.newton_euler import (
    CoupleTerm,
    ForceTerm,
    InclineAxes,
    Kinematics,
    cross,
)
from dynsolve.results import Check

MOMENT_AGREEMENT = 1e-9  # relative to the sum of the magnitudes of the terms


def balance(
    name: str,
    body: Body,
    forces: Sequence[ForceTerm],
    couples: Sequence[CoupleTerm],
    kinematics: Kinematics,
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> Check | None:
    """The moment check of one body about G and each point a force acts at; None where it
    cannot be evaluated (symbolic givens, an unknown point of action)."""
    points: list[tuple[str, Vec]] = [("G", body.G)]
    for force in forces:
        if all(force.point != p for _, p in points):
            simple = force.point_name.isidentifier()
            points.append(
                (force.point_name if simple else f"the point of {force.name}", force.point)
            )
    worst, shown, used = 0.0, "", []
    for label, P in points:
        gap = _gap(body, forces, couples, kinematics, P, values)
        if gap is None:  # a force left unsolved ("model only what is asked") has an arm here
            continue
        used.append(label)
        if gap[0] >= worst:
            worst, shown = gap[0], f"about {label}: {gap[1]:.6g} = {gap[2]:.6g}"
    if len(used) < 2:  # one point is the equation the solve used: no second point
        return None
    names = ", ".join(used)
    passed = worst <= MOMENT_AGREEMENT
    detail = (
        f"ΣM_P = I_G α + r_G/P × m a_G about {names} with the solved values; the worst, "
        f"{shown} (relative gap {worst:.1e})"
    )
    return Check(f"second moment point: {name}", passed, detail)


def moment_equation(
    body: Body,
    forces: Sequence[ForceTerm],
    couples: Sequence[CoupleTerm],
    kinematics: Kinematics,
    P: Vec,
    axes: InclineAxes | None = None,
) -> tuple[sympy.Expr, sympy.Expr]:
    """ΣM_P of the forces and couples, and the kinetic diagram's moment about P,
    I_G α + r_G/P × m a_G, both in the unknowns: the equation Method II writes (its arms
    from t and n components where the body is on incline ``axes``).

    >>> from dynsolve.model.scene import Body
    >>> from dynsolve.principles.newton_euler import ForceTerm, Kinematics
    >>> m, g, L, alpha = sympy.symbols("m g L alpha")
    >>> rod = Body("rod", m, m * L**2 / 12, (L / 2, 0), (L / 2, 0), "rod", (L,), {}, False,
    ...            "", 0, 0)
    >>> weight = ForceTerm("W", "weight", "rod", (L / 2, 0), "G", (0, -1), m * g, True)
    >>> kin = Kinematics("rotation", alpha, (0, alpha * L / 2), 0)
    >>> moment_equation(rod, [weight], [], kin, (0, 0))
    (-L*g*m/2, L**2*alpha*m/3)
    """
    arm = cross if axes is None else axes.cross  # on an incline: arms in β, not the slope
    arms = [tidy(arm((f.point[0] - P[0], f.point[1] - P[1]), f.direction)) for f in forces]
    applied = sympy.Add(*(f.magnitude * arm for f, arm in zip(forces, arms, strict=True)))
    applied += sympy.Add(*(c.moment for c in couples))
    r = (body.G[0] - P[0], body.G[1] - P[1])
    if axes is not None and kinematics.along is not None and kinematics.tangent is not None:
        kinetic = body.I_G * kinematics.alpha + body.mass * kinematics.along * axes.cross(
            r, kinematics.tangent
        )
    else:
        kinetic = body.I_G * kinematics.alpha + body.mass * cross(r, kinematics.a_G)
    return applied, kinetic


def _gap(
    body: Body,
    forces: Sequence[ForceTerm],
    couples: Sequence[CoupleTerm],
    kinematics: Kinematics,
    P: Vec,
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> tuple[float, float, float] | None:
    """(relative gap, ΣM_P, kinetic moment about P) at the solved values, or None."""
    arms = [(f, tidy(cross((f.point[0] - P[0], f.point[1] - P[1]), f.direction))) for f in forces]
    terms = [f.magnitude * arm for f, arm in arms if arm != 0]
    terms += [c.moment for c in couples]
    r = (body.G[0] - P[0], body.G[1] - P[1])
    a_G = kinematics.a_G
    kinetic = [body.I_G * kinematics.alpha, body.mass * cross(r, a_G)]
    numbers = [real_value(t, values) for t in (*terms, *kinetic)]
    if any(n is None for n in numbers):
        return None
    applied = sum(numbers[: len(terms)])  # type: ignore[arg-type]
    inertial = sum(numbers[len(terms) :])  # type: ignore[arg-type]
    size = sum(abs(n) for n in numbers)  # type: ignore[arg-type]
    return abs(applied - inertial) / max(size, 1e-300), applied, inertial
