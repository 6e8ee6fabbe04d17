"""Angular momentum of planar bodies and particles; kept about a pin through an impact.

A body of mass m, I_G about its mass centre G, moving with v_G and ω (ccw positive), has
about any point P (Hibbeler 19.1)

    H_P = I_G ω + (r_G/P × m v_G)_z,        p = m v_G,

which is ``I_G ω`` about G itself and ``m (r × v)`` for a particle (I_G = 0).

A particle A striking a body B that turns about a frictionless pin O (a bullet into a
pinned disk's rim or rod, a ballistic pendulum): the pin's impulse acts at O and the
finite forces (weights) give none over the short impact, so the angular momentum of A and
B together about O is conserved. With e = 0 the particle embeds, turning with B afterwards:

    m (r_A/O × v_A1) + I_O ω₁ = (I_O + m r_A/O²) ω₂;

with e > 0 the smooth contact leaves A's velocity across the line of impact n unchanged and
restitution holds at the contact point P (where A is): e (v_A1 − v_P1)·n = (v_P2 − v_A2)·n,
v_P = ω k × r_A/O.

>>> import sympy
>>> angular_momentum(sympy.Integer(2), sympy.Integer(3), (1, 0), 5, (0, 2), (0, 0))
11
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from dynsolve.model.momentum_events import Clutch, Reshape
from dynsolve.model.scene import Body, Impact, Vec
from dynsolve.numbers import real_value, tidy
from dynsolve.principles.newton_euler import cross, dot
from dynsolve.results import Assumption
from dynsolve.system import Equation
from dynsolve.units import Dim, with_unit

ANGULAR_MOMENTUM = Dim(2, 1, -1)  # kg·m²/s, slug·ft²/s
LINEAR_MOMENTUM = Dim(1, 1, -1)  # kg·m/s = N·s


def angular_momentum(
    mass: sympy.Expr, I_G: sympy.Expr, v_G: Vec, omega: sympy.Expr, G: Vec, point: Vec
) -> sympy.Expr:
    """H_P = I_G ω + (r_G/P × m v_G)_z of a body (ccw positive) about the point P.

    >>> m, v, d = sympy.symbols("m v d", positive=True)
    >>> angular_momentum(m, sympy.Integer(0), (v, 0), 0, (0, d), (0, 0))  # a particle
    -d*m*v
    """
    r = (G[0] - point[0], G[1] - point[1])
    return tidy(I_G * omega + mass * cross(r, v_G))


def linear_momentum(mass: sympy.Expr, v_G: Vec) -> Vec:
    """p = m v_G.

    >>> linear_momentum(sympy.Integer(2), (3, -1))
    (6, -2)
    """
    return (tidy(mass * v_G[0]), tidy(mass * v_G[1]))


def turning(omega: sympy.Expr, r: Vec) -> Vec:
    """The velocity ω k × r of a point at r from a fixed axis.

    >>> turning(sympy.Integer(2), (3, 0))
    (0, 6)
    """
    return (tidy(-omega * r[1]), tidy(omega * r[0]))


@dataclass(frozen=True)
class PinnedImpact:
    """The equations of a particle striking a pinned body, and the motion after it."""

    equations: tuple[Equation, ...]
    unknowns: Mapping[sympy.Symbol, Dim]
    velocities: Mapping[str, Vec]  # v_G after, of the particle and the body
    omega: sympy.Expr  # the body's ω after (ccw positive)
    approach: sympy.Expr  # (v_A1 − v_P1)·n: > 0 when A closes on the body's point P
    separation: sympy.Expr  # (v_P2 − v_A2)·n after it: ≥ 0
    lost: sympy.Expr  # T₁ − T₂ of the two: ≥ 0
    energy: sympy.Expr  # T₁ of the two, the scale of ``lost``
    reach: sympy.Expr | None  # how far the body reaches from the pin less |r_A/O|: ≥ 0


def pinned_impact(
    impact: Impact,
    particle: Body,
    body: Body,
    pin: tuple[str, Vec],
    before: Mapping[str, Vec],
    omega_1: sympy.Expr,
    state: int,
    embeds: bool,
) -> PinnedImpact:
    """Angular momentum of ``particle`` and ``body`` (pinned at ``pin``) about the pin,
    conserved through the impact, with restitution e along the line, or embedded (``embeds``:
    e = 0, the particle turns with the body afterwards). The particle's G is the point it
    strikes; the unknowns are named for ``state`` (after).

    >>> from dynsolve.model.scene import Body
    >>> z = sympy.Integer(0)
    >>> bullet = Body("bullet", sympy.Rational(1, 20), z, (0, sympy.Rational(1, 2)), (0, 0),
    ...               "particle", (), {}, True, "", 0, 0)
    >>> disk = Body("disk", sympy.Integer(10), sympy.Rational(5, 4), (0, 0), (0, 0), "disk",
    ...             (sympy.Rational(1, 2),), {}, False, "", 0, 0)
    >>> hit = pinned_impact(Impact("bullet", "disk", z, (1, 0)), bullet, disk, ("O", (0, 0)),
    ...                     {"bullet": (400, 0)}, z, 2, True)
    >>> sympy.solve(hit.equations[0].residual, list(hit.unknowns))  # −10 = 1.2625 ω₂
    [-800/101]
    """
    name, at = pin
    A, B = particle.name, body.name
    n = impact.line
    r_A = (particle.G[0] - at[0], particle.G[1] - at[1])
    r_G = (body.G[0] - at[0], body.G[1] - at[1])
    I_O = body.I_G + body.mass * dot(r_G, r_G)
    m = particle.mass
    v_A1 = before.get(A, (sympy.Integer(0), sympy.Integer(0)))
    omega = sympy.Symbol(f"omega_{state}_{B}", real=True)
    H_1 = I_O * omega_1 + m * cross(r_A, v_A1)
    v_P1, v_P2 = turning(omega_1, r_A), turning(omega, r_A)
    where = f"about the pin {name}: the pin's impulse acts at {name} and the weights' over the "
    where += "short impact is negligible"
    if embeds:  # A turns with B afterwards
        v_A2 = v_P2
        equations = (
            Equation(
                H_1,
                (I_O + m * dot(r_A, r_A)) * omega,
                "momentum",
                1,
                f"angular momentum of {A} and {B} conserved {where}; {A} embeds (e = 0): "
                f"m (r_{A}/{name} × v_{A}1) + I_{name} ω₁ = (I_{name} + m r_{A}/{name}²) ω₂",
            ),
        )
        unknowns: dict[sympy.Symbol, Dim] = {omega: Dim(0, 0, -1)}
    else:
        t = (-n[1], n[0])
        along = sympy.Symbol(f"vn_{state}_{A}", real=True)
        across = dot(v_A1, t)
        v_A2 = (along * n[0] + across * t[0], along * n[1] + across * t[1])
        equations = (
            Equation(
                H_1,
                I_O * omega + m * cross(r_A, v_A2),
                "momentum",
                1,
                f"angular momentum of {A} and {B} conserved {where}: "
                f"m (r_{A}/{name} × v_{A}1) + I_{name} ω₁ = m (r_{A}/{name} × v_{A}2) + "
                f"I_{name} ω₂ ({A}'s velocity across the line unchanged: a smooth contact)",
            ),
            Equation(
                impact.e * dot((v_A1[0] - v_P1[0], v_A1[1] - v_P1[1]), n),
                dot(v_P2, n) - along,
                "restitution",
                2,
                f"coefficient of restitution at the contact: e (v_{A}1 − v_P1)·n = "
                f"(v_P2 − v_{A}2)·n, v_P = ω k × r_{A}/{name} the point of {B} struck",
            ),
        )
        unknowns = {omega: Dim(0, 0, -1), along: Dim(1, 0, -1)}
    v_A2 = (tidy(v_A2[0]), tidy(v_A2[1]))
    T_1 = m * dot(v_A1, v_A1) / 2 + I_O * omega_1**2 / 2
    T_2 = m * dot(v_A2, v_A2) / 2 + I_O * omega**2 / 2
    return PinnedImpact(
        equations,
        unknowns,
        {A: v_A2, B: turning(omega, r_G)},
        omega,
        tidy(dot((v_A1[0] - v_P1[0], v_A1[1] - v_P1[1]), n)),
        tidy(dot((v_P2[0] - v_A2[0], v_P2[1] - v_A2[1]), n)),
        tidy(T_1 - T_2),
        tidy(T_1),
        reach(body, r_G, r_A),
    )


def reach(body: Body, r_G: Vec, r_A: Vec) -> sympy.Expr | None:
    """|r_G/O| + the body's half-size less |r_A/O|: ≥ 0 when the struck point A lies within
    the body's reach from the pin (a rod's half-length, a round body's radius); None for a
    body given only its inertia (no size to check against).

    >>> rod = Body("rod", 1, 1, (0, -1), (0, -1), "rod", (sympy.Integer(2),), {}, False, "",
    ...            0, 0)
    >>> reach(rod, (0, -1), (0, -3))  # the tip is 2 from the pin; a point 3 away is not on it
    -1
    """
    size = body.sizes[0] / 2 if body.shape == "rod" and body.sizes else body.radius
    if size is None:
        return None
    return tidy(sympy.sqrt(dot(r_G, r_G)) + size - sympy.sqrt(dot(r_A, r_A)))


def pinned_impact_checks(
    k: int,
    struck: tuple[str, str],
    embeds: bool,
    pin: str,
    checks: tuple[tuple[str, sympy.Expr], ...],
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> list[Assumption]:
    """What a particle's impact on a pinned body assumes, checked against the solution:
    it strikes (closing along the line), separates or moves with the body after, and loses
    energy (T₁ − T₂ ≥ 0); a check whose value is unknown is not shown as passed.
    ``struck`` is (the particle, the pinned body); ``checks`` holds ("approach", …),
    ("separation", …), ("lost", …), ("energy", T₁); every value with its unit in
    ``system``."""
    A, B = struck
    found = dict(checks)
    result: list[Assumption] = []

    def value(key: str) -> float | None:
        return real_value(found[key], values) if key in found else None

    def length(metres: float) -> str:
        return with_unit(metres, "length", system)

    closing = value("approach")
    if closing is not None:
        result.append(
            Assumption(
                f"approach in stage {k}",
                closing > 0,
                f"before the impact (v_{A} − v_P)·n = {with_unit(closing, 'velocity', system)}"
                + (
                    " > 0"
                    if closing > 0
                    else f": {A} does not strike {B} (the line points from {A} toward {B})"
                ),
            )
        )
    apart = value("separation") if not embeds else None  # 0 if it embeds
    if apart is not None:
        scale = abs(closing or 0.0) or 1.0
        holds = apart >= -1e-9 * scale
        shown = 0.0 if abs(apart) <= 1e-9 * scale else apart
        result.append(
            Assumption(
                f"separation in stage {k}",
                holds,
                f"after the impact (v_P − v_{A})·n = {with_unit(shown, 'velocity', system)}"
                + (" ≥ 0" if holds else f" < 0: {A} would pass through {B}"),
            )
        )
    lost = value("lost")
    if lost is not None:
        scale = max(abs(value("energy") or 0.0), 1e-300)
        holds = lost >= -1e-9 * scale
        result.append(
            Assumption(
                f"energy lost in stage {k}",
                holds,
                f"T{k} − T{k + 1} = "
                f"{with_unit(0.0 if abs(lost) <= 1e-9 * scale else lost, 'energy', system)}"
                + (" ≥ 0" if holds else " < 0: the impact would create energy"),
            )
        )
    within = value("reach")
    if "reach" in found and within is not None:
        inside = within >= -1e-9 * max(abs(within), 1.0)
        result.append(
            Assumption(
                f"{A} on {B} in stage {k}",
                inside,
                f"{A} strikes {B} where it is placed, within {B}'s reach from the pin {pin}: "
                + ("|r_G| + half-size − |r_A| = " + f"{length(max(within, 0.0))} ≥ 0" if inside else
                   f"{length(-within)} beyond it: place {A} where it strikes {B}"),
            )
        )  # fmt: skip
    else:
        result.append(
            Assumption.undecided(
                f"{A} on {B} in stage {k}",
                f"{B} has no size to check it against: {A} is taken to strike {B} where placed",
            )
        )
    result.append(
        Assumption(
            f"impact in stage {k}",
            True,
            f"stated: {A} strikes {B}, which turns about the pin {pin}; angular momentum about "
            f"{pin} conserved (the pin's impulse acts there)"
            + (f"; {A} embeds (e = 0)" if embeds else "; smooth contact"),
        )
    )
    return result


@dataclass(frozen=True)
class Spin:
    """One equation of angular momentum kept about an axis, and the motion after it."""

    equation: Equation
    omega: sympy.Symbol  # the common (or new) ω after, ccw positive
    velocities: Mapping[str, Vec]  # v_G after
    lost: sympy.Expr  # T₁ − T₂
    energy: sympy.Expr  # T₁


def clutch(
    rotors: tuple[Body, Body],
    pin: tuple[str, Vec],
    omegas: tuple[sympy.Expr, sympy.Expr],
    state: int,
) -> Spin:
    """Two rotors on one axis (the pin) locked by a clutch: no external moment about the
    axis, so I_A ω_A1 + I_B ω_B1 = (I_A + I_B) ω₂, each I about the axis.

    >>> from dynsolve.model.scene import Body
    >>> z = sympy.Integer(0)
    >>> A = Body("A", sympy.Integer(2), sympy.Integer(3), (0, 0), (0, 0), "", (), {}, False,
    ...          "", 0, 0)
    >>> B = Body("B", sympy.Integer(2), sympy.Integer(1), (0, 0), (0, 0), "", (), {}, False,
    ...          "", 0, 0)
    >>> found = clutch((A, B), ("O", (0, 0)), (sympy.Integer(10), z), 2)
    >>> sympy.solve(found.equation.residual, found.omega), found.lost.subs(found.omega, 7.5)
    ([15/2], 37.5000000000000)
    """
    name, at = pin
    inertia = []
    for body in rotors:
        r = (body.G[0] - at[0], body.G[1] - at[1])
        inertia.append(body.I_G + body.mass * dot(r, r))
    A, B = (body.name for body in rotors)
    omega = sympy.Symbol(f"omega_{state}_{A}", real=True)
    before = inertia[0] * omegas[0] + inertia[1] * omegas[1]
    equation = Equation(
        before,
        (inertia[0] + inertia[1]) * omega,
        "momentum",
        1,
        f"angular momentum of {A} and {B} about the axis {name} kept as the clutch locks them "
        f"(no external moment about it; the clutch's moments are internal): "
        f"I_{A} ω_{A}1 + I_{B} ω_{B}1 = (I_{A} + I_{B}) ω₂",
    )
    T_1 = (inertia[0] * omegas[0] ** 2 + inertia[1] * omegas[1] ** 2) / 2
    T_2 = (inertia[0] + inertia[1]) * omega**2 / 2
    velocities = {
        body.name: turning(omega, (body.G[0] - at[0], body.G[1] - at[1])) for body in rotors
    }
    return Spin(equation, omega, velocities, tidy(T_1 - T_2), tidy(T_1))


def reshape(
    body: Body,
    I_2: sympy.Expr,
    pin: tuple[str, Vec] | None,
    v_G: Vec,
    omega_1: sympy.Expr,
    state: int,
) -> Spin:
    """A body that changes its moment of inertia about G from I₁ to I₂ by internal forces
    (a diver tucking, a skater pulling in the arms): H about G (free: the weight acts
    through G) or about its pin (the pin's force acts there) kept, I₁ ω₁ = I₂ ω₂; a free
    body's v_G is kept (the change taken as short).

    >>> from dynsolve.model.scene import Body
    >>> diver = Body("diver", sympy.Integer(70), sympy.Integer(14), (0, 0), (0, 0), "", (),
    ...              {}, False, "", 0, 0)
    >>> found = reshape(diver, sympy.Integer(4), None, (0, 0), sympy.Integer(2), 2)
    >>> sympy.solve(found.equation.residual, found.omega)
    [7]
    """
    name, at = pin if pin is not None else ("G", body.G)
    r = (body.G[0] - at[0], body.G[1] - at[1])
    I_1 = body.I_G + body.mass * dot(r, r)
    I_2 = I_2 + body.mass * dot(r, r)
    omega = sympy.Symbol(f"omega_{state}_{body.name}", real=True)
    about = f"its pin {name} (the pin's force acts there)" if pin else "G (the weight acts at G)"
    equation = Equation(
        I_1 * omega_1,
        I_2 * omega,
        "momentum",
        1,
        f"angular momentum of {body.name} about {about} kept while internal forces change "
        f"its inertia: I_{name}1 ω₁ = I_{name}2 ω₂",
    )
    after = turning(omega, r) if pin is not None else v_G
    T_1 = body.mass * dot(v_G, v_G) / 2 + body.I_G * omega_1**2 / 2
    T_2 = body.mass * dot(after, after) / 2 + (I_2 - body.mass * dot(r, r)) * omega**2 / 2
    return Spin(equation, omega, {body.name: after}, tidy(T_1 - T_2), tidy(T_1))


def spin_checks(
    k: int,
    event: Clutch | Reshape,
    checks: tuple[tuple[str, sympy.Expr], ...],
    values: Mapping[sympy.Symbol, sympy.Expr],
    system: str,
) -> list[Assumption]:
    """A clutch loses energy (T₁ − T₂ ≥ 0, checked); a change of inertia's energy is the
    internal forces' work (shown, not checked: a diver tucking gains energy); each stated,
    with its unit in ``system``."""
    found = dict(checks)
    lost = real_value(found["lost"], values)
    energy = real_value(found["energy"], values)
    result: list[Assumption] = []
    if isinstance(event, Clutch):
        if lost is not None:
            scale = max(abs(energy or 0.0), 1e-300)
            holds = lost >= -1e-9 * scale
            shown = 0.0 if abs(lost) <= 1e-9 * scale else lost
            result.append(
                Assumption(
                    f"energy lost in stage {k}",
                    holds,
                    f"T{k} − T{k + 1} = {with_unit(shown, 'energy', system)}"
                    + (" ≥ 0 (the clutch slips until they turn as one)" if holds else " < 0"),
                )
            )
        result.append(
            Assumption(
                f"clutch in stage {k}",
                True,
                f"stated: {event.body} and {event.other} turn on one axis and no external "
                "moment about it acts while the clutch engages (the bearings are smooth)",
            )
        )
        return result
    if lost is not None:
        result.append(
            Assumption(
                f"change of inertia in stage {k}",
                True,
                f"stated: internal forces only; T{k + 1} − T{k} = "
                f"{with_unit(-lost, 'energy', system)} is their work "
                f"(not checked: {event.body} may gain or lose energy)",
            )
        )
    return result
