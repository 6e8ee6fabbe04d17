"""Angular velocity composed of turns (precession, nutation, spin) and its checks.

A 3D scene's body turns through a chain (Hibbeler 20.1–20.3): the frame that ``rotates``
about a fixed axis K at φ̇ (precession), the body's axis that ``nutates`` about i' at θ̇
(carried by that frame), and the body that ``spins`` about its own axis k at ψ̇ (carried by
the frame before it). Each turn's axis is turned by the frames before it, so

    ω = φ̇ K + θ̇ i' + ψ̇ k,
    α = φ̈ K + (θ̈ i' + φ̇ K × θ̇ i') + (ψ̈ k + Ω × ψ̇ k),   Ω = φ̇ K + θ̇ i',

and a point carried by the last frame moves as v = v_P + ω × r, a = a_P + α × r + ω × (ω × r)
from a point P of its axis (Hibbeler 20.4). A second method recomputes ω, α and a_G by
differentiating the chain of rotations R(t) = R_K(φ(t)) R_i'(θ(t)) R_k(ψ(t)) in time
(ω from Ṙ Rᵀ); the textbook's Ω-frame form of Ḣ_G, (Ḣ_G)_xyz + Ω × H_G with
(Ḣ_G)_xyz = I_G (α − Ω × ω), is set against Euler's form I_G α + ω × H_G.

>>> from dynsolve.rigid3d.model import Body3D, Scene3D, Spin, SpinOf
>>> z, one = sympy.Integer(0), sympy.Integer(1)
>>> disk = Body3D("d", one, (z, z, z), sympy.eye(3), (one,) * 3, ((one, z, z),) * 3, "")
>>> turn = Spin((z, one, z), (z, z, z), 5 * one, 4 * one)
>>> nutation = SpinOf((z, z, one), 3 * one, 2 * one, (z, z, z))
>>> s = sympy.sqrt(3) / 2
>>> spin = SpinOf((s, one / 2, z), 10 * one, 6 * one)
>>> chain = compose(Scene3D("top.dyn", disk, turn, (), None, spin_of=spin, nutation=nutation))
>>> [sympy.nsimplify(c) for c in chain.omega]  # Hibbeler 12e Example 20.2, scene axes
[5*sqrt(3), 10, 3]
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import sympy

from dynsolve.rigid3d.inertia import Vec3, cross, in_body_axes
from dynsolve.rigid3d.model import Scene3D, SpinOf
from dynsolve.trig import vanishes

ZERO3: Vec3 = (sympy.Integer(0),) * 3  # type: ignore[assignment]


@dataclass(frozen=True)
class Composition:
    """The body's ω and α (absolute), v_G and a_G, and the rate Ω of the frame that
    carries the spin axis (ω without the spin; None when the body does not spin in it)."""

    omega: Vec3
    alpha: Vec3
    v_G: Vec3
    a_G: Vec3
    frame: Vec3 | None


def turns(scene: Scene3D) -> tuple[SpinOf, ...]:
    """The turns relative to the precessing frame, outermost first: nutation, then spin."""
    return tuple(t for t in (scene.nutation, scene.spin_of) if t is not None)


def compose(scene: Scene3D) -> Composition:
    """ω, α, v_G, a_G of the scene's body from its chain of turns (the module's formulas)."""
    spin, body = scene.spin, scene.body
    omega = _scaled(spin.omega, spin.axis)
    alpha = _scaled(spin.alpha, spin.axis)
    point, v_P, a_P = spin.through, ZERO3, ZERO3
    frame = None
    for turn in turns(scene):
        P = turn.through or body.G
        r = _minus(P, point)
        v_P = _plus(v_P, cross(omega, r))
        a_P = _plus(a_P, cross(alpha, r), cross(omega, cross(omega, r)))
        relative = _scaled(turn.omega, turn.axis)
        frame = omega if turn is scene.spin_of else frame
        alpha = _plus(alpha, _scaled(turn.alpha, turn.axis), cross(omega, relative))
        omega = _plus(omega, relative)
        point = P
    r = _minus(body.G, point)
    v_G = _plus(v_P, cross(omega, r))
    a_G = _plus(a_P, cross(alpha, r), cross(omega, cross(omega, r)))
    return Composition(omega, alpha, v_G, a_G, frame)


def by_rotations(
    scene: Scene3D, values: Mapping[sympy.Symbol, sympy.Expr]
) -> tuple[Vec3, Vec3, Vec3]:
    """ω, α and a_G by differentiating the chain of rotations at t = 0, with ``values``
    put in first: each turn k through its angle q_k(t) = ω_k t + α_k t²/2 about its axis
    (as drawn, in the frame before it), G(t) = T_0(T_1(T_2(G))) with
    T_k(x) = P_k + R_k(t)(x − P_k), and ω = vee(Ṙ Rᵀ), α = d/dt vee(Ṙ Rᵀ) for
    R = R_0 R_1 R_2.

    Only the first two derivatives at t = 0 are needed, so each rotation is taken to second
    order in t, R_k = E + q K + q²/2 K² (Rodrigues, sin q K + (1 − cos q) K², expanded),
    that is R_k = E + ω_k K t + (α_k K + ω_k² K²) t²/2, and the chain is multiplied as
    polynomials in t cut after t²: R(t) = E + R_1 t + R_2 t², with Ṙ(0) = R_1 and
    R̈(0) = 2 R_2. As R(0) = E, ω = vee(R_1) and α = vee(R̈ + Ṙ Ṙᵀ) = vee(2 R_2 + R_1 R_1ᵀ)
    (d/dt (Ṙ Rᵀ) = R̈ Rᵀ + Ṙ Ṙᵀ); a_G = G̈(0), twice G's t² term."""
    spin, body = scene.spin, scene.body
    chain = [(spin.axis, spin.through, spin.omega, spin.alpha)]
    chain += [(u.axis, u.through or body.G, u.omega, u.alpha) for u in turns(scene)]
    R_1, R_2 = sympy.zeros(3), sympy.zeros(3)
    G = [_column(body.G, values), sympy.zeros(3, 1), sympy.zeros(3, 1)]
    for axis, P, w, a in reversed(chain):  # the innermost turn first
        K = _skew(_column(axis, values))
        w, a = _number(w, values), _number(a, values)
        A_1, A_2 = w * K, (a * K + w**2 * K * K) / 2
        arm = G[0] - _column(P, values)
        G = [G[0], G[1] + A_1 * arm, G[2] + A_1 * G[1] + A_2 * arm]
        R_1, R_2 = A_1 + R_1, A_2 + A_1 * R_1 + R_2  # (E + A_1 t + A_2 t²)(E + R_1 t + R_2 t²)
    change = 2 * R_2 + R_1 * R_1.T
    return _vee(R_1), _vee(change), tuple(2 * G[2])  # type: ignore[return-value]


def _column(
    vector: Sequence[sympy.Expr], values: Mapping[sympy.Symbol, sympy.Expr]
) -> sympy.Matrix:
    """``vector`` with ``values`` put in, as a column of numbers (:func:`_number`)."""
    return sympy.Matrix([_number(c, values) for c in vector])


def _number(expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with ``values`` put in, evaluated to 30 digits (a letter left stays one)."""
    return sympy.N((sympy.Integer(0) + expr).xreplace(values), 30)


def _skew(u: sympy.Matrix) -> sympy.Matrix:
    """[u]×: the matrix of u × ."""
    return sympy.Matrix([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])


def _vee(W: sympy.Matrix) -> Vec3:
    """The vector of the skew matrix W (W x = w × x)."""
    return (W[2, 1], W[0, 2], W[1, 0])


def frame_form(scene: Scene3D, chain: Composition) -> Vec3 | None:
    """Ḣ_G = (Ḣ_G)_xyz + Ω × H_G in the frame that carries the spin axis (Hibbeler 21.4),
    with (Ḣ_G)_xyz = I_G (α − Ω × ω); None when the body does not spin in a frame or is not
    symmetric about its spin axis (then I_G is not constant in that frame)."""
    if chain.frame is None or scene.spin_of is None or not _symmetric_about(scene):
        return None
    I_G = scene.body.I_G
    H = I_G * sympy.Matrix(chain.omega)
    relative = sympy.Matrix(chain.alpha) - sympy.Matrix(cross(chain.frame, chain.omega))
    return _plus(tuple(I_G * relative), cross(chain.frame, tuple(H)))  # type: ignore[arg-type]


def _symmetric_about(scene: Scene3D) -> bool:
    """Whether I_G commutes with [s]× for the spin axis s, I_G [s]× = [s]× I_G (the body is
    symmetric about s: I_G is constant in a frame turning about s). Tested in body axes,
    J [u]× = [u]× J with u = Rᵀ s the spin axis's body components: I_G = R J Rᵀ and
    [s]× = R [u]× Rᵀ (R a rotation), so the one holds exactly when the other does, and
    J's entries are the given moments, not the scene's turned ones."""
    body = scene.body
    assert scene.spin_of is not None
    u = sympy.Matrix(
        [sum(a * b for a, b in zip(axis, scene.spin_of.axis, strict=True)) for axis in body.axes]
    )
    J = in_body_axes(body.principal, body.products)
    return all(vanishes(c) for c in J * _skew(u) - _skew(u) * J)


def filled(
    vectors: Sequence[Sequence[sympy.Expr]], values: Mapping[sympy.Symbol, sympy.Expr]
) -> dict[sympy.Symbol, sympy.Expr]:
    """``values`` and a random positive number for each other symbol in ``vectors`` (a
    symbolic problem: the identity is then tested at a point)."""
    rng = random.Random(7)
    left = set().union(
        *((sympy.Integer(0) + c).xreplace(values).free_symbols for v in vectors for c in v)
    )
    extra = {s: sympy.Float(rng.uniform(0.5, 2.0)) for s in sorted(left, key=str)}
    # a solved value may hold the symbols left (a symbolic angle): put them in it too
    return {**{k: (sympy.Integer(0) + v).xreplace(extra) for k, v in values.items()}, **extra}


def agree(
    first: Sequence[sympy.Expr],
    second: Sequence[sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> float | None:
    """The largest difference of two vectors relative to their size, with ``values`` put
    in (any symbol left takes a random positive value: the identity is tested); None if
    they cannot be evaluated."""
    rng = random.Random(7)
    pairs = [
        ((sympy.Integer(0) + a).xreplace(values), (sympy.Integer(0) + b).xreplace(values))
        for a, b in zip(first, second, strict=True)
    ]
    left = set().union(*(a.free_symbols | b.free_symbols for a, b in pairs))
    extra = {symbol: sympy.Float(rng.uniform(0.5, 2.0)) for symbol in left}
    try:
        numbers = [
            (complex(sympy.N(a.xreplace(extra), 20)), complex(sympy.N(b.xreplace(extra), 20)))
            for a, b in pairs
        ]
    except TypeError:
        return None
    worst = max(abs(a - b) for a, b in numbers)
    scale = max(max(abs(a), abs(b)) for a, b in numbers)
    return worst / scale if scale else 0.0


def _scaled(size: sympy.Expr, axis: Vec3) -> Vec3:
    return tuple(size * c for c in axis)  # type: ignore[return-value]


def _minus(a: Sequence[sympy.Expr], b: Sequence[sympy.Expr]) -> Vec3:
    return tuple(x - y for x, y in zip(a, b, strict=True))  # type: ignore[return-value]


def _plus(*vectors: Sequence[sympy.Expr]) -> Vec3:
    return tuple(sum(c, sympy.Integer(0)) for c in zip(*vectors, strict=True))  # type: ignore[return-value]
