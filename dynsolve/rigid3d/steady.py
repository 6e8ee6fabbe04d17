"""The steady angle of a body in a turning frame, from a scene drawn at a given angle.

``theta_s = steady(theta)``: the scene is written at the given angle θ (its positions use
θ), with the body's turn relative to the frame on a ``spins … through (P)`` line whose
angular acceleration is an unknown (θ̈). The steady (relative-equilibrium) angle is where
the body can stay at rest in the frame: in the moment equation about the pin that holds θ̈
alone, put θ̈ = θ̇ = 0 and θ → θ_s, an unknown angle whose root the ``assume`` lines choose
(the seed's bar on a shaft: −m g (L/2) sin θ_s = −(m L²/3) Ω² sin θ_s cos θ_s, so
cos θ_s = 3 g/(2 L Ω²)). ``onset(theta_s, Omega)`` then works on θ_s as on any unknown angle.

>>> import sympy
>>> t, ts, a, W = sympy.symbols("theta theta_s theta_ddot W", real=True)
>>> pin = Equation(-sympy.sin(t), a - W**2 * sympy.sin(t) * sympy.cos(t), "ΣM_B,z", 9, "ΣM_B,z")
>>> at_rest(pin, t, ts, a, None).rhs
-W**2*sin(theta_s)*cos(theta_s)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.rigid3d.model import Scene3D
from dynsolve.spec.ast import FindItem, Spec
from dynsolve.system import Equation

HINT = (
    "e.g. 'theta_s = steady(theta) [deg]' with theta a given angle of the positions and "
    "'spins B: about (s), through (P), omega 0, alpha theta_ddot' (theta_ddot unknown)"
)


def steady_finds(spec: Spec) -> tuple[FindItem, ...]:
    """The find items ``NAME = steady(ANGLE)``."""
    return tuple(i for i in spec.finds if i.ref is not None and i.ref.function == "steady")


@dataclass(frozen=True)
class SteadyAngle:
    """``name = steady(angle)``: the unknown angle, the given one it replaces, and the
    body's relative rate and angular acceleration on its ``spins`` line."""

    steady: sympy.Symbol
    angle: sympy.Symbol
    alpha: sympy.Expr
    rate: sympy.Expr | None  # a given relative rate to put 0 (None: written 0)
    where: Position


def steady_angles(
    spec: Spec, scene: Scene3D, unknowns: Sequence[sympy.Symbol]
) -> tuple[SteadyAngle, ...]:
    """The asked steady angles, before any equation is written; a positioned SpecError
    when the scene cannot give one."""
    found = []
    for item in steady_finds(spec):
        where = Position(spec.file, item.line, item.column)
        assert item.ref is not None
        args = item.ref.args
        if len(args) != 1 or args[0] not in scene.symbols:
            raise SpecError("steady takes one given: the angle the scene is drawn at", where, HINT)
        own = scene.spin_of
        if own is None or own.through is None or own.alpha not in set(unknowns):
            raise SpecError(
                "a steady angle needs the body's turn about a pin in the frame, with its "
                "angular acceleration unknown",
                where,
                HINT,
            )
        rate = own.omega if own.omega in scene.values else None
        if rate is None and sympy.Integer(0) + own.omega != 0:
            raise SpecError(
                "the relative rate on the spins line must be 0 or a given to leave out",
                where,
                HINT,
            )
        steady = sympy.Symbol(item.name, real=True)
        found.append(SteadyAngle(steady, scene.symbols[args[0]], own.alpha, rate, where))
    return tuple(found)


def steady_equations(
    asked: Sequence[SteadyAngle],
    equations: Sequence[Equation],
    unknowns: Sequence[sympy.Symbol],
) -> tuple[Equation, ...]:
    """The moment equation about the pin at each steady angle: the one that holds θ̈
    alone, at rest in the frame at θ → θ_s."""
    found = []
    for each in asked:
        holding = [e for e in equations if _holds_alone(e, each.alpha, unknowns)]
        if each.angle not in set().union(*(e.residual.free_symbols for e in holding)):
            raise SpecError(
                f"no moment equation holds {each.alpha} alone at the angle {each.angle}",
                each.where,
                hint="pin the body with one bearing ('bearing B: at (…), pin') so that the "
                f"moment about it leaves out the reactions; and place the body with {each.angle}",
            )
        found.append(at_rest(holding[-1], each.angle, each.steady, each.alpha, each.rate))
    return tuple(found)


def at_rest(
    equation: Equation,
    angle: sympy.Symbol,
    steady: sympy.Symbol,
    alpha: sympy.Expr,
    rate: sympy.Expr | None,
) -> Equation:
    """``equation`` with the body at rest in the frame (θ̈ = θ̇ = 0) at θ → θ_s."""
    put: Mapping[sympy.Expr, sympy.Expr] = {alpha: sympy.Integer(0), angle: steady}
    if rate is not None:
        put = {**put, rate: sympy.Integer(0)}
    note = f"{equation.note} at {steady.name}: at rest in the turning frame ({alpha} = 0)"
    return Equation(
        sympy.expand(sympy.expand_trig(equation.lhs.xreplace(put))),
        sympy.expand(sympy.expand_trig(equation.rhs.xreplace(put))),
        note,
        equation.line,
        note,
    )


def _holds_alone(equation: Equation, alpha: sympy.Expr, unknowns: Sequence[sympy.Symbol]) -> bool:
    symbols = equation.residual.free_symbols
    return alpha in symbols and not (symbols & set(unknowns)) - {alpha}
