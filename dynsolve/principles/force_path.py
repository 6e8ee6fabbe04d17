"""Second methods for a speed between two states: F = m a integrated along the path.

Along the straight path from G₁ to G₂ the tangential part of F = m a reads
m v dv/ds = F_t(s), so v₂² = v₁² + (2/m) ∫ F_t ds. The forces are taken as they act at
each point of the path (the weight, springs from their current length, constant forces,
kinetic friction with N from the balance across a straight surface) and the integral is
done numerically (``mpmath.quad``), independently of the closed-form work terms of
:mod:`dynsolve.principles.work_energy`. A single rigid body rolling or sliding on a flat
surface under constant loads has a constant α from the Newton–Euler equations at state 1,
so ω₂² = ω₁² + 2 α Δθ. Both are used as cross-checks of the work–energy result.

>>> import sympy
>>> from dynsolve.model.scene import Scene, Body, Travel
>>> ball = Body("ball", sympy.Integer(2), sympy.Integer(0), (0, 5), (0, 5), "particle", (),
...             {}, True, "", 0, 0)
>>> scene = Scene({"ball": ball}, {}, (), (), (), (0, -1), {},
...               travels={"ball": Travel("ball", "to", position=(0, 0))})
>>> round(speed_by_integration(scene, "ball", {"g": sympy.Float(9.81)}, {}), 6)  # √(2 g h)
9.904544
"""

from __future__ import annotations

from collections.abc import Mapping

import mpmath
import sympy

from dynsolve.model.scene import Scene, Vec
from dynsolve.model.states import particle_shift
from dynsolve.numbers import real_value
from dynsolve.principles.newton_euler import dot


def speed_by_integration(
    scene: Scene,
    body_name: str,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> float | None:
    """v₂ of a travelling particle from m v dv = F_t ds along its straight path; None when
    a value is symbolic, a force is unknown or the particle does not get there."""
    body = scene.bodies[body_name]
    travel = scene.travels[body_name]
    G1 = body.G
    step = particle_shift(scene, travel)
    if step is None:
        return None
    lam = sympy.Symbol("lambda_", real=True)
    length = sympy.sqrt(dot(step, step))
    P = (G1[0] + lam * step[0], G1[1] + lam * step[1])
    forces: list[Vec] = []
    nearest: list[sympy.Expr] = []  # where the path passes closest to a spring's anchor
    kinks: list[sympy.Expr] = []  # zero where an elastic cord goes taut or slack
    if scene.gravity is not None:
        weight = body.mass * symbols["g"]
        forces.append((weight * scene.gravity[0], weight * scene.gravity[1]))
    for spring in scene.springs:
        if spring.body != body_name or spring.other:
            continue
        to_end = (spring.other_point[0] - P[0], spring.other_point[1] - P[1])
        anchor = (spring.other_point[0] - G1[0], spring.other_point[1] - G1[1])
        nearest.append(dot(anchor, step) / dot(step, step))
        current = sympy.sqrt(dot(to_end, to_end))
        pull = spring.k * (current - spring.unstretched) / current
        if spring.tension_only:  # an elastic cord pulls only while stretched
            pull = sympy.Piecewise((pull, current > spring.unstretched), (0, True))
            taut = dot(to_end, to_end) - spring.unstretched**2  # zero where it tightens
            kinks.append(taut)
        elif spring.compression_only:  # a spring pushes only while compressed
            pull = sympy.Piecewise((pull, current < spring.unstretched), (0, True))
            kinks.append(dot(to_end, to_end) - spring.unstretched**2)  # where it is left
        forces.append((pull * to_end[0], pull * to_end[1]))
    for load in scene.loads:
        if load.body == body_name and load.kind == "force":
            if load.name not in symbols:
                return None
            size = symbols[load.name]
            forces.append((size * load.direction[0], size * load.direction[1]))
    tangent = (step[0] / length, step[1] / length)
    F_t = sympy.Add(*(dot(f, tangent) for f in forces))
    for support in scene.supports:
        if support.body != body_name or support.smooth:
            continue
        if support.mu_k is None:
            return None
        across = sympy.Add(*(dot(f, support.normal) for f in forces))
        F_t -= support.mu_k * sympy.Abs(across)  # kinetic friction opposes the motion
    m = real_value(body.mass, values)
    s = real_value(length, values)
    v1 = scene.velocities.get(body_name, (0, 0))
    v1_squared = real_value(dot(v1, v1), values)
    integrand = sympy.Integer(0) + F_t.xreplace(dict(values))
    if m is None or s is None or v1_squared is None:
        return None
    if s == 0:  # no travel, no work: the speed is the starting speed
        return v1_squared**0.5
    if F_t.has(sympy.nan) or integrand.free_symbols - {lam}:
        return None
    force = sympy.lambdify(lam, integrand, "mpmath")
    # the spring force turns where the path passes its anchor: split the integral there
    # so no node falls on that point
    inner = {real_value(n, values) for n in nearest} - {None}
    for kink in kinks:  # a node where each elastic cord tightens: the force has a corner
        polynomial = sympy.Poly((sympy.Integer(0) + kink).xreplace(dict(values)), lam)
        inner |= {float(sympy.re(r)) for r in polynomial.nroots() if abs(sympy.im(r)) < 1e-12}
    nodes = [0.0, *sorted(n for n in inner if 0 < n < 1), 1.0]  # type: ignore[operator]
    try:
        work = float(mpmath.quad(force, nodes)) * s
    except (ArithmeticError, ValueError):  # a singular force on the path: no second method
        return None
    squared = v1_squared + 2 * work / m
    return None if squared < 0 else squared**0.5


def omega_by_constant_alpha(
    scene: Scene,
    body_name: str,
    turn: sympy.Expr,
    symbols: Mapping[str, sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> float | None:
    """|ω₂| = sqrt(ω₁² + 2 α Δθ) with α from ΣF = m a_G, ΣM = I α at state 1, for one body
    on flat supports (rolling or a base) under constant loads; None when that does not hold.

    >>> import sympy
    >>> from dynsolve.model.scene import Body, Load, Support
    >>> wheel = Body("wheel", 2, 1, (0, 1), (0, 1), "disk", (1,), {}, False, "", 0, 0)
    >>> rolls = Support("rolls", "C", "wheel", (0, 0), (0, 1))
    >>> pull = Load("force", "P", "wheel", (0, 1), "G", (1, 0))
    >>> scene = Scene({"wheel": wheel}, {}, (rolls,), (), (pull,), None, {})
    >>> omega_by_constant_alpha(scene, "wheel", -2, {"P": 3}, {})  # α = −P r/(I + m r²) = −1
    2.0
    """
    from dynsolve.principles.newton_euler import formulate

    constant = (
        len(scene.bodies) == 1
        and not scene.springs
        and not scene.links
        and not scene.cords
        and scene.supports
        and all(s.kind in ("rolls", "base") for s in scene.supports)
    )
    if not constant:
        return None
    formulation = formulate(scene, symbols)
    # a numeric check: floating-point coefficients keep the (linear) solve fast
    residuals = [sympy.N((e.lhs - e.rhs).xreplace(dict(values))) for e in formulation.equations]
    unknowns = list(formulation.unknowns)
    found = sympy.linsolve(residuals, unknowns)
    if len(found) != 1:
        return None
    (solution,) = tuple(found)
    if any(v.free_symbols for v in solution):
        return None
    alpha = real_value(
        formulation.kinematics[body_name].alpha.xreplace(
            dict(zip(unknowns, solution, strict=True))
        ),
        values,
    )
    omega_1 = real_value(scene.omegas.get(body_name, 0), values)
    theta = real_value(turn, values)
    if alpha is None or omega_1 is None or theta is None:
        return None
    squared = omega_1**2 + 2 * alpha * theta
    return None if squared < 0 else squared**0.5
