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

import itertools
import math
import warnings
from collections.abc import Mapping

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
    a value is symbolic, a force is unknown or the particle does not get there. The
    forces are written with the numbers put in (λ the fraction of the path run) and
    integrated in floats, split where a spring's force turns or an elastic cord's kinks."""
    rule = dict(values)
    body = scene.bodies[body_name]
    travel = scene.travels[body_name]
    step = particle_shift(scene, travel)
    if step is None:
        return None
    m = real_value(body.mass, values)
    s = real_value(sympy.sqrt(dot(step, step)), values)
    v1 = scene.velocities.get(body_name, (0, 0))
    v1_squared = real_value(dot(v1, v1), values)
    if m is None or s is None or v1_squared is None:
        return None
    if s == 0:  # no travel, no work: the speed is the starting speed
        return v1_squared**0.5
    path = _Path(scene, body_name, _in_numbers(step, rule), rule)
    F_t = path.tangential({name: _in_numbers(value, rule) for name, value in symbols.items()})
    if F_t is None or F_t.has(sympy.nan) or F_t.free_symbols - {LAMBDA}:
        return None
    work = _integral(F_t, path.nodes())
    if work is None:  # a singular force on the path: no second method
        return None
    squared = v1_squared + 2 * work * s / m
    return None if squared < 0 else squared**0.5


LAMBDA = sympy.Symbol("lambda_", real=True)  # the fraction of the straight path run


def _in_numbers(item: object, rule: Mapping[sympy.Symbol, sympy.Expr]) -> object:
    """An expression, or a pair of them, with the values put in."""
    if isinstance(item, tuple):
        return tuple(_in_numbers(part, rule) for part in item)
    return (sympy.Integer(0) + item).xreplace(rule)  # type: ignore[operator]


class _Path:
    """A particle's straight path from G₁ by ``step`` (numbers), and the forces along it."""

    def __init__(self, scene: Scene, name: str, step: Vec, rule: Mapping[sympy.Symbol, sympy.Expr]):
        self.scene, self.name, self.step, self.rule = scene, name, step, rule
        self.G1 = _in_numbers(scene.bodies[name].G, rule)
        self.inner: set[float] = set()  # λ where a spring's force turns or an elastic cord kinks

    def tangential(self, symbols: Mapping[str, sympy.Expr]) -> sympy.Expr | None:
        """F_t(λ) of the weight, springs from their current length, constant forces and
        kinetic friction (N from the balance across the surface); None where a force is
        not known."""
        from dynsolve.simulate.equations import root

        scene, step = self.scene, self.step
        P = (self.G1[0] + LAMBDA * step[0], self.G1[1] + LAMBDA * step[1])
        forces: list[Vec] = []
        if scene.gravity is not None:
            weight = _in_numbers(scene.bodies[self.name].mass, self.rule) * symbols["g"]
            forces.append((weight * scene.gravity[0], weight * scene.gravity[1]))
        for spring in scene.springs:
            if spring.body != self.name or spring.other:
                continue
            E = _in_numbers(spring.other_point, self.rule)
            k, free = _in_numbers(spring.k, self.rule), _in_numbers(spring.unstretched, self.rule)
            to_end = (E[0] - P[0], E[1] - P[1])
            anchor = (E[0] - self.G1[0], E[1] - self.G1[1])
            self._add(dot(anchor, step) / dot(step, step))  # the force turns there
            current = root(dot(to_end, to_end))
            pull = k * (current - free) / current
            if spring.tension_only:  # an elastic cord pulls only while stretched
                pull = sympy.Piecewise((pull, current > free), (0, True))
                self._kinks(dot(to_end, to_end) - free**2)  # zero where it tightens
            elif spring.compression_only:  # a spring pushes only while compressed
                pull = sympy.Piecewise((pull, current < free), (0, True))
                self._kinks(dot(to_end, to_end) - free**2)  # where it is left
            forces.append((pull * to_end[0], pull * to_end[1]))
        for load in scene.loads:
            if load.body == self.name and load.kind == "force":
                if load.name not in symbols:
                    return None
                size, d = symbols[load.name], _in_numbers(load.direction, self.rule)
                forces.append((size * d[0], size * d[1]))
        length = sympy.sqrt(dot(step, step))
        tangent = (step[0] / length, step[1] / length)
        F_t = sympy.Add(*(dot(f, tangent) for f in forces))
        for support in scene.supports:
            if support.body != self.name or support.smooth:
                continue
            if support.mu_k is None:
                return None
            n = _in_numbers(support.normal, self.rule)
            across = sympy.Add(*(dot(f, n) for f in forces))
            F_t -= _in_numbers(support.mu_k, self.rule) * _magnitude(across)  # against the motion
        return sympy.Integer(0) + F_t

    def _add(self, fraction: sympy.Expr) -> None:
        value = real_value(fraction)
        if value is not None:
            self.inner.add(value)

    def _kinks(self, squared: sympy.Expr) -> None:
        """The real λ where ``squared`` (a polynomial in λ) is 0."""
        polynomial = sympy.Poly(squared, LAMBDA)
        self.inner |= {float(sympy.re(r)) for r in polynomial.nroots() if abs(sympy.im(r)) < 1e-12}

    def nodes(self) -> list[float]:
        """0, the places inside the path where the force has a corner, and 1."""
        return [0.0, *sorted(n for n in self.inner if 0 < n < 1), 1.0]


def _magnitude(across: sympy.Expr) -> sympy.Expr:
    """|N| written as it is: sympy's evaluation of ``Abs`` asks the sign of a spring's
    force along the path (signsimp, assumptions), a third of the method's time."""
    return sympy.Abs(across, evaluate=False)


def _integral(F_t: sympy.Expr, nodes: list[float]) -> float | None:
    """∫₀¹ F_t dλ in floats, piece by piece between the nodes; None where the force is
    singular or not real on the path."""
    from scipy.integrate import quad

    from dynsolve.simulate.compiled import float_scalar

    force = float_scalar([LAMBDA], F_t)
    total = 0.0
    try:
        with warnings.catch_warnings():  # a rough piece is judged by the comparison itself
            warnings.simplefilter("ignore")
            for a, b in itertools.pairwise(nodes):
                piece, _ = quad(force, a, b, epsabs=0, epsrel=1e-13, limit=200)
                total += piece
    except (ArithmeticError, ValueError, TypeError):
        return None
    return total if math.isfinite(total) else None


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
