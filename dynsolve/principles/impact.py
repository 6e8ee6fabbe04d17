"""Impact of two bodies along a line: momentum conserved along it, restitution, smooth contact.

A body striking the fixed ground keeps only the restitution equation: the ground's
impulse acts along the line, so e v_1·n = −v_2·n, and the smooth surface leaves the
component across the line unchanged.

For particles (or bodies translating through the impact) with velocities v₁ before:
m_A v_A1·n + m_B v_B1·n = m_A v_A2·n + m_B v_B2·n (no external impulse along the line of
impact), e (v_A1 − v_B1)·n = (v_B2 − v_A2)·n (coefficient of restitution), and each
body's velocity across the line unchanged (a smooth contact transmits no impulse there).

>>> import sympy
>>> from dynsolve.model.scene import Impact
>>> m, v = sympy.symbols("m v", positive=True)
>>> eqs, after = impact_equations(Impact("A", "B", sympy.Integer(1), (1, 0)),
...                               {"A": m, "B": m}, {"A": (v, 0), "B": (0, 0)})
>>> sympy.solve([e.lhs - e.rhs for e in eqs], list(after.values()))
{vn_A: 0, vn_B: v}
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from dynsolve.model.scene import Impact, Scene, Vec
from dynsolve.numbers import tidy
from dynsolve.principles.angular_momentum import angular_momentum
from dynsolve.principles.newton_euler import Formulation, bare_formulation, dot
from dynsolve.system import Equation
from dynsolve.units import Dim

ZERO: Vec = (sympy.Integer(0), sympy.Integer(0))


def impact_equations(
    impact: Impact, masses: Mapping[str, sympy.Expr], before: Mapping[str, Vec]
) -> tuple[tuple[Equation, ...], dict[str, sympy.Symbol]]:
    """The two equations of the impact and the unknown components along the line after it."""
    n = impact.line
    A, B = impact.body, impact.other
    if B not in masses:  # the fixed ground
        return _on_ground(impact, before)
    after = {body: sympy.Symbol(f"vn_{body}", real=True) for body in (A, B)}
    v_A1, v_B1 = before.get(A, ZERO), before.get(B, ZERO)
    momentum = Equation(
        masses[A] * dot(v_A1, n) + masses[B] * dot(v_B1, n),
        masses[A] * after[A] + masses[B] * after[B],
        "momentum",
        1,
        f"linear momentum of {A} and {B} conserved along the line of impact "
        "(no external impulse along it)",
    )
    restitution = Equation(
        impact.e * (dot(v_A1, n) - dot(v_B1, n)),
        after[B] - after[A],
        "restitution",
        2,
        "coefficient of restitution: e (v_A1 − v_B1)·n = (v_B2 − v_A2)·n",
    )
    return (momentum, restitution), after


def _on_ground(
    impact: Impact, before: Mapping[str, Vec]
) -> tuple[tuple[Equation, ...], dict[str, sympy.Symbol]]:
    """A body striking the fixed ground: its normal component reversed and scaled by e.

    >>> import sympy
    >>> v = sympy.Symbol("v", positive=True)
    >>> (eq,), after = _on_ground(Impact("ball", "ground", sympy.Rational(1, 2), (0, -1)),
    ...                           {"ball": (0, -v)})
    >>> sympy.solve(eq.residual, after["ball"])
    [-v/2]
    """
    A = impact.body
    along = sympy.Symbol(f"vn_{A}", real=True)
    restitution = Equation(
        impact.e * dot(before.get(A, ZERO), impact.line),
        -along,
        "restitution",
        1,
        f"{A} strikes the fixed {impact.other}: e v_1·n = −v_2·n (the {impact.other}'s impulse "
        "acts along the line of impact, so momentum along it is not conserved; the smooth "
        "surface leaves the component across it unchanged)",
    )
    return (restitution,), {A: along}


def velocity_after(impact: Impact, body: str, along: sympy.Expr, before: Mapping[str, Vec]) -> Vec:
    """A body's velocity after the impact: the solved component along the line, the one
    across it unchanged (smooth contact)."""
    n = impact.line
    t = (-n[1], n[0])
    across = dot(before.get(body, ZERO), t)
    return (along * n[0] + across * t[0], along * n[1] + across * t[1])


def impact_formulation(scene: Scene) -> Formulation:
    """The equations of every impact in ``scene`` (bodies move with their given velocities)."""
    masses = {name: body.mass for name, body in scene.bodies.items()}
    equations: list[Equation] = []
    unknowns: dict[sympy.Symbol, Dim] = {}
    after: dict[str, Vec] = {}
    for impact in scene.impacts:
        pair, along = impact_equations(impact, masses, scene.velocities)
        equations += pair
        for body, symbol in along.items():
            unknowns[symbol] = Dim.of("velocity")
            after[body] = velocity_after(impact, body, symbol, scene.velocities)
    numbered = tuple(
        Equation(e.lhs, e.rhs, f"eq. {i}", i, e.note) for i, e in enumerate(equations, start=1)
    )
    return bare_formulation(scene.bodies, equations=numbered, unknowns=unknowns, after=after)


def pivot_formulation(
    scene: Scene, given_values: Mapping[sympy.Symbol, sympy.Expr] | None = None
) -> Formulation:
    """Angular momentum about the struck point conserved through a plastic eccentric impact:
    r_G/P × m v_G1 + I_G ω₀ = I_P ω₁ (the impulse acts at P; finite forces such as the
    weight give no impulse over the short impact). ω₁ is written as its sense (that of
    the angular momentum before) times an unknown magnitude.

    >>> import sympy
    >>> from dynsolve.model.scene import Scene, Body, Pivot
    >>> cube = Body("cube", 3, sympy.Rational(1, 2), (-1, 1), (-1, 1), "block", (2, 2), {},
    ...             False, "", 0, 0)
    >>> scene = Scene({"cube": cube}, {"B": (0, 0)}, (), (), (), None, {},
    ...               velocities={"cube": (4, 0)}, pivots=(Pivot("cube", "B", (0, 0)),))
    >>> f = pivot_formulation(scene)
    >>> sympy.solve(f.equations[0].residual, list(f.unknowns)), f.after_omega  # -12 = 6.5 ω
    ([24/13], {'cube': -omega_1_cube})
    """
    from dynsolve.solver.roots import sign_of

    if any(p.normal is not None for p in scene.pivots):
        return rebound_formulation(scene)
    equations: list[Equation] = []
    unknowns: dict[sympy.Symbol, Dim] = {}
    after_omega: dict[str, sympy.Expr] = {}
    after: dict[str, Vec] = {}
    for number, pivot in enumerate(scene.pivots, start=1):
        body = scene.bodies[pivot.body]
        r = (body.G[0] - pivot.point[0], body.G[1] - pivot.point[1])
        v = scene.velocities.get(pivot.body, ZERO)
        omega_0 = scene.omegas.get(pivot.body, sympy.Integer(0))
        before = angular_momentum(body.mass, body.I_G, v, omega_0, body.G, pivot.point)
        I_P = body.I_G + body.mass * (r[0] ** 2 + r[1] ** 2)
        sense = sign_of(before, given_values or {})
        omega = sympy.Symbol(f"omega_1_{pivot.body}", positive=True)
        equations.append(
            Equation(
                before,
                I_P * sense * omega,
                f"eq. {number}",
                number,
                f"angular momentum of {pivot.body} about {pivot.name} conserved through the "
                f"impact: H_{pivot.name}1 = I_{pivot.name} ω₁ (the impulse acts at "
                f"{pivot.name}; the weight's impulse over the short impact is negligible)",
            )
        )
        unknowns[omega] = Dim(0, 0, -1)
        after_omega[pivot.body] = sense * omega
        # G turns about P afterwards: v_G2 = ω₁ k × r_G/P
        after[pivot.body] = (-sense * omega * r[1], sense * omega * r[0])
    return bare_formulation(
        scene.bodies,
        equations=tuple(equations),
        unknowns=unknowns,
        after_omega=after_omega,
        after=after,
    )


def rebound_formulation(scene: Scene) -> Formulation:
    """A rigid body striking a fixed point with restitution e along the line n (smooth):
    m (v_G2 − v_G1) = J n, I_G (ω₂ − ω₁) = r_P/G × J n, and (v_P2)·n = −e (v_P1)·n with
    v_P = v_G + ω k × r_P/G; the impulse J ≥ 0 pushes the body back along −n.

    >>> import sympy
    >>> from dynsolve.model.scene import Scene, Body, Pivot
    >>> rod = Body("rod", 2, sympy.Rational(1, 6), (0, 0), (0, 0), "rod", (1,), {}, False, "",
    ...            0, 0)
    >>> ledge = Pivot("rod", "P", (sympy.Rational(1, 2), 0), e=sympy.Rational(1, 2),
    ...               normal=(0, -1))
    >>> scene = Scene({"rod": rod}, {"P": ledge.point}, (), (), (), None, {},
    ...               velocities={"rod": (0, -3)}, pivots=(ledge,))
    >>> f = rebound_formulation(scene)
    >>> sympy.solve([e.residual for e in f.equations], list(f.unknowns))  # hand: see tests
    {J_P: 9/4, omega_2_rod: 27/4, v_2x_rod: 0, v_2y_rod: -15/8}
    """
    (pivot,) = scene.pivots
    assert pivot.normal is not None and pivot.e is not None
    name, point = pivot.body, pivot.name
    body = scene.bodies[name]
    n = pivot.normal
    r = (pivot.point[0] - body.G[0], pivot.point[1] - body.G[1])
    v1 = scene.velocities.get(name, ZERO)
    w1 = sympy.Integer(0) + scene.omegas.get(name, 0)
    v2 = (sympy.Symbol(f"v_2x_{name}", real=True), sympy.Symbol(f"v_2y_{name}", real=True))
    w2 = sympy.Symbol(f"omega_2_{name}", real=True)
    J = sympy.Symbol(f"J_{point}", nonnegative=True)
    push = (-n[0], -n[1])  # the point pushes the body back
    m, I_G = body.mass, body.I_G

    def v_P(v: Vec, w: sympy.Expr) -> sympy.Expr:
        return dot((v[0] - w * r[1], v[1] + w * r[0]), n)

    equations = [
        Equation(m * v1[i] + J * push[i], m * v2[i], f"eq. {i + 1}", i + 1,
                 f"linear impulse and momentum along {axis}: m v_G1 + J n = m v_G2 ({name})")
        for i, axis in enumerate("xy")
    ]  # fmt: skip
    equations.append(
        Equation(
            angular_momentum(m, I_G, v1, w1, body.G, body.G)
            + J * (r[0] * push[1] - r[1] * push[0]),
            angular_momentum(m, I_G, v2, w2, body.G, body.G),
            "eq. 3",
            3,
            f"angular impulse and momentum about G: I_G ω₁ + r_{point}/G × J n = I_G ω₂ ({name})",
        )
    )
    equations.append(
        Equation(
            -pivot.e * v_P(v1, w1),
            v_P(v2, w2),
            "eq. 4",
            4,
            f"restitution at {point}: (v_{point}2)·n = −e (v_{point}1)·n, v_{point} = v_G + "
            f"ω k × r_{point}/G (smooth: no impulse across the line)",
        )
    )
    return bare_formulation(
        scene.bodies,
        equations=tuple(tidy_equation(e) for e in equations),
        unknowns={v2[0]: Dim(1, 0, -1), v2[1]: Dim(1, 0, -1), w2: Dim(0, 0, -1), J: Dim(1, 1, -1)},
        after={name: v2},
        after_omega={name: w2},
        events=(
            (
                f"{name} strikes {point}",
                tidy(v_P(v1, w1)),
                f"before the impact {point} of {name} closes on the point at "
                "{value:.4g velocity} along the line",
            ),
        ),
    )


def tidy_equation(equation: Equation) -> Equation:
    from dynsolve.numbers import tidy

    return Equation(
        tidy(equation.lhs), tidy(equation.rhs), equation.label, equation.line, equation.note
    )
