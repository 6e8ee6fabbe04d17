"""A 3D body turning relative to a frame that turns at a constant rate, in time (a bar on a shaft).

The scene is a 3D scene whose body `spins … through (P), omega W, alpha A` relative to
the frame that `rotates` at a constant Ω: W a given (the start rate), A a name that is not
a given (the angular acceleration the equations decide). The coordinate θ is the given
angle that places the body: the one for which dG/dθ = s × (G − P) and the body's axis turns
the same way (found by differentiating the scene's own expressions, so no new line is
needed). At each state (θ, θ') the scene's six equations ΣF = m a_G, ΣM_G = I_G α + ω × H_G
are linear in the reactions and A: solved numerically (numpy) for A = θ''.

Ω is held constant by whatever drives the frame, so T + V is not conserved; the Jacobi
integral J = T − Ω·H_O + V is (H_O the angular momentum about a point O of the frame's
axis), and its drift measures the integration. For the seed's bar on a shaft,
J = ½ I_B θ'² − ½ I_B Ω² sin²θ − m g (L/2) cos θ.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec('''
... given:
...   m = 2 kg
...   L = 0.8 m
...   Omega = 6 rad/s
...   theta = 30 deg
...   w = 0 rad/s
... scene:
...   body bar: mass m, rod L, at (L/2*sin(theta), -L/2*cos(theta), 0)
...   axis bar: (sin(theta), -cos(theta), 0)
...   rotates bar: about (0, 1, 0), through (0, 0, 0), omega Omega
...   spins bar: about (0, 0, 1), through (0, 0, 0), omega w, alpha a
...   bearing B: at (0, 0, 0), pin
...   gravity
... ''', "shaft.dyn")
>>> spin = spin_of(spec)
>>> spin.bars, round(spin.rates(0.0, [0.0, 0.0])[1], 6)  # the seed's theta'' at 30 deg
(('bar',), 6.391582)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace

import numpy as np
import sympy

from dynsolve.rigid3d.inertia import cross
from dynsolve.simulate.equations import NotSimulable
from dynsolve.spec.ast import FindItem, Spec


@dataclass(frozen=True)
class Spin3D:
    """The body's turn θ from the scene as drawn, ready to integrate (the interface of
    :class:`dynsolve.simulate.chain.Chain`)."""

    bars: tuple[str, ...]  # the body: its turn about the spin axis is the coordinate
    qd0: tuple[float, ...]
    system: Callable[..., tuple[object, object]]  # (θ, θ') -> (A, b) of the six equations
    column: int  # which unknown is θ''
    jacobi: Callable[..., tuple[object, object]]  # (θ, θ') -> (T − Ω·H_O, V)
    theta0: float
    joints: tuple[str, ...] = ()
    size: int = 1
    accel: Callable[[float, float], float] | None = None  # θ''(θ, θ') in closed form

    def right_hand_side(self) -> Callable[[float, Sequence[float]], list[float]]:
        """(θ', θ'') of the state (turn, rate): solve_ivp's ``fun``. θ'' from its closed
        form when there is one (the six equations solved once, symbolically, and checked
        against the numeric solve), else from the six equations solved at each state; a
        state where the closed form is not finite (a pivot that vanishes there) is solved
        numerically."""
        system, column, start, accel = self.system, self.column, self.theta0, self.accel

        def solved(theta: float, rate: float) -> float:
            A, b = system(theta, rate)
            x = np.linalg.solve(np.asarray(A, float), np.asarray(b, float).ravel())
            return float(x[column])

        if accel is None:
            return lambda _t, y: [float(y[1]), solved(start + float(y[0]), float(y[1]))]

        def rates(_t: float, y: Sequence[float]) -> list[float]:
            theta, rate = start + y[0], y[1]
            value = accel(theta, rate)
            if not math.isfinite(value):
                value = solved(float(theta), float(rate))
            return [rate, value]

        return rates

    def rates(self, t: float, y: Sequence[float]) -> list[float]:
        """(θ', θ'') at the state y = (turn, rate)."""
        return self.right_hand_side()(t, y)

    def energies(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """T − Ω·H_O and V at each column of the states ``y`` (shape 2 × samples)."""
        pairs = [self.jacobi(self.theta0 + float(q), float(w)) for q, w in zip(*y, strict=True)]
        return np.array([float(p[0]) for p in pairs]), np.array([float(p[1]) for p in pairs])

    def positions(self, q: np.ndarray) -> np.ndarray:
        """No joints: an empty table."""
        return np.zeros((0, q.shape[-1]))

    def joints_at(self, q: Sequence[float]) -> list[float]:
        """No joints."""
        return []


def spin_of(spec: Spec) -> Spin3D:
    """The spec's 3D body turning in a turning frame; NotSimulable says why not."""
    from dynsolve.rigid3d.model import read_scene3d
    from dynsolve.rigid3d.problem import build_3d_problem, motion

    rates = read_scene3d(spec).rates  # the unknown rates, asked for (as a solve would)
    asked = {f.name for f in spec.finds}
    extra = tuple(FindItem(r.name, None, 1, 1) for r in rates if r.name not in asked)
    problem = build_3d_problem(replace(spec, finds=(*spec.finds, *extra)))
    scene = problem.scene
    own = scene.spin_of
    if scene.nutation is not None:
        raise NotSimulable(
            "a nutating body is solved at an instant; a simulation follows one turn relative "
            "to the turning frame (leave out the nutates line)"
        )
    if own is None or own.through is None:
        raise NotSimulable(
            "a 3D scene is simulated when its body turns relative to the turning frame about "
            "a pin: 'spins B: about (s), through (P), omega w, alpha a' (a bar on a shaft)"
        )
    rate = own.alpha
    if not (isinstance(rate, sympy.Symbol) and rate in scene.rates):
        raise NotSimulable(
            "the relative angular acceleration is what a simulation finds: write it as a name "
            "that is not a given ('alpha theta_ddot')"
        )
    if sympy.Integer(0) + scene.spin.alpha != 0:
        raise NotSimulable("the frame must turn at a constant rate (its alpha 0) to be simulated")
    values = dict(problem.system.knowns)
    theta = _coordinate(scene, own.axis, own.through, values)
    omega = own.omega
    if not isinstance(omega, sympy.Symbol) or omega not in values:
        raise NotSimulable(
            "the relative rate must be a given (its start value): 'omega w' with w under given"
        )
    rest = {s: v for s, v in values.items() if s not in (theta, omega)}
    unknowns = list(problem.system.unknowns)
    residuals = [(e.lhs - e.rhs).xreplace(rest) for e in problem.system.equations]
    A, b = sympy.linear_eq_to_matrix(residuals, unknowns)
    if A.shape[0] != A.shape[1]:
        raise NotSimulable(
            f"{A.shape[0]} equations for {A.shape[1]} unknowns: give the loads so that the "
            "reactions and the relative angular acceleration are fixed"
        )
    system = sympy.lambdify([theta, omega], (A, b), "numpy", cse=True)
    accel = _closed_form(A, b, unknowns.index(rate), theta, omega, system, float(values[theta]))
    w, _, v_G, _ = motion(scene)
    body = scene.body
    origin = scene.spin.through
    frame = tuple(scene.spin.omega * c for c in scene.spin.axis)
    H_G = body.I_G * sympy.Matrix(w)
    arm = tuple(body.G[i] - origin[i] for i in range(3))
    H_O = [H_G[i] + body.mass * c for i, c in enumerate(cross(arm, v_G))]
    T = sum(a * h for a, h in zip(w, H_G, strict=True)) / 2
    T += body.mass * sum(v**2 for v in v_G) / 2
    J = T - sum(f * h for f, h in zip(frame, H_O, strict=True))
    V = body.mass * scene.symbols["g"] * body.G[1] if scene.gravity else sympy.Integer(0)
    jacobi = sympy.lambdify([theta, omega], (J.xreplace(rest), V.xreplace(rest)), "math")
    return Spin3D(
        (body.name,),
        (float(values[omega]),),
        system,
        unknowns.index(rate),
        jacobi,
        float(values[theta]),
        accel=accel,
    )


CLOSED_FORM_OPS = 2000  # a larger θ'' is left to the numeric solve at each state


def _closed_form(
    A: sympy.Matrix,
    b: sympy.Matrix,
    column: int,
    theta: sympy.Symbol,
    omega: sympy.Symbol,
    system: Callable[..., tuple[object, object]],
    theta0: float,
) -> Callable[[float, float], float] | None:
    """θ''(θ, θ') from the six equations solved once by LU (sympy), tidied and lambdified
    with ``math``: the same work per step as a hand-written script. It is substituted
    back: at five states it must agree with the numeric solve of the equations (relative
    1e-10), else (or when the LU needs a pivot that is zero, or the formula is large)
    None, and the equations are solved at each state."""
    from dynsolve.numbers import tidy

    try:
        x = A.LUsolve(b)
    except (ValueError, ZeroDivisionError, sympy.polys.polyerrors.PolynomialError):
        return None
    expr = x[column]
    if sympy.count_ops(expr) > CLOSED_FORM_OPS:
        return None
    expr = tidy(expr)
    accel = sympy.lambdify([theta, omega], expr, "math", cse=True)
    for shift, rate in ((0.0, 0.0), (0.37, 1.3), (-0.81, -2.2), (1.9, 0.4), (2.7, -4.1)):
        at = theta0 + shift
        A_n, b_n = system(at, rate)
        try:
            want = float(
                np.linalg.solve(np.asarray(A_n, float), np.asarray(b_n, float).ravel())[column]
            )
            got = float(accel(at, rate))
        except (np.linalg.LinAlgError, ZeroDivisionError, ValueError, OverflowError):
            return None
        if not math.isclose(got, want, rel_tol=1e-10, abs_tol=1e-12 * (1 + abs(want))):
            return None
    return accel


def _coordinate(
    scene: object, axis: Sequence[sympy.Expr], through: Sequence[sympy.Expr], values: dict
) -> sympy.Symbol:
    """The given angle θ that turns the body about the spin axis: dG/dθ = s × (G − P) and
    each body axis e turns as de/dθ = s × e, tested at the givens' values and a second angle."""
    body = scene.body  # type: ignore[attr-defined]
    candidates = sorted(
        {s for c in body.G for s in (sympy.Integer(0) + c).free_symbols if s in values}, key=str
    )
    for theta in candidates:
        if _turns(body, axis, through, theta, values):
            return theta
    raise NotSimulable(
        "no given places the body turned about its spin axis: write G (and its axis) in terms "
        "of the angle, e.g. 'at (L/2*sin(theta), -L/2*cos(theta), 0)'"
    )


def _turns(
    body: object, axis: Sequence[sympy.Expr], through: Sequence[sympy.Expr], theta: sympy.Symbol,
    values: dict,
) -> bool:  # fmt: skip
    """Whether G turns about the axis through P as θ changes, and the body's axes with it."""
    G = body.G  # type: ignore[attr-defined]
    r = tuple(G[i] - through[i] for i in range(3))
    pairs = [(r, cross(tuple(axis), r))]
    pairs += [(a, cross(tuple(axis), tuple(a))) for a in body.axes]  # type: ignore[attr-defined]
    for shift in (0.0, 0.7):
        at = {**values, theta: values[theta] + shift}
        for vector, expected in pairs:
            for i in range(3):
                d = float(sympy.diff(sympy.Integer(0) + vector[i], theta).xreplace(at))
                e = float((sympy.Integer(0) + expected[i]).xreplace(at))
                if not math.isclose(d, e, rel_tol=1e-9, abs_tol=1e-12):
                    return False
    return True
