"""The derivation lines of a 3D body's motion and their checks, as the textbook writes them.

Notes (shown with the checks): ω composed of its turns, ω = φ̇ K + θ̇ i' + ψ̇ k; α part
by part, each axis turned by the frames that carry it; H_G = I_G ω; Ḣ_G in Euler's form
I_G α + ω × H_G (the one the moment equations use). Checks: ω, α and a_G again by
differentiating the chain of rotations in time, and Ḣ_G again in the Ω-frame form
(Ḣ_G)_xyz + Ω × H_G (Hibbeler 21.4), which must agree.

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.rigid3d.model import read_scene3d
>>> spec = parse_spec('''
... given:
...   m = 1 kg
...   r = 0.1 m
...   theta = 60 deg
...   w_p = 5 rad/s
...   w_n = 3 rad/s
...   w_s = 10 rad/s
... scene:
...   body top: mass m, disk r, at (0, 0, 0)
...   rotates top: about (0, 1, 0), through (0, 0, 0), omega w_p
...   nutates top: about (0, 0, 1), through (0, 0, 0), omega w_n
...   spins top: about (sin(theta), cos(theta), 0), omega w_s
... find: w_x = omega_x(top)
... ''', "top.dyn")
>>> scene = read_scene3d(spec)
>>> print(composition_notes(scene, scene.values, spec)[1][1])  # 15 i + (−15, 26.0, −43.3)
α = w_p K × w_n i' + (w_p K + w_n i') × w_s k = (0, 26.0, -43.3) rad/s^2
>>> [(c.name, c.passed) for c in composition_checks(scene, scene.values, spec)][1:]
[('Ḣ_G in the Ω frame', True), ("Euler's equations in the principal axes", True)]
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import sympy

from dynsolve.format import quantity as format_quantity
from dynsolve.numbers import tidy
from dynsolve.quantities import convert
from dynsolve.results import Check
from dynsolve.rigid3d.composition import (
    Composition,
    agree,
    by_rotations,
    compose,
    filled,
    frame_form,
    turns,
)
from dynsolve.rigid3d.inertia import Vec3, cross
from dynsolve.rigid3d.model import Scene3D
from dynsolve.shown import formula_text
from dynsolve.spec.ast import Spec
from dynsolve.trig import tidied
from dynsolve.units import Dim, natural_unit

TOLERANCE = 1e-9


def composition_notes(
    scene: Scene3D, values: Mapping[sympy.Symbol, sympy.Expr], spec: Spec
) -> tuple[tuple[str, str], ...]:
    """ω, α and H_G of a body that spins or nutates, each with its textbook form."""
    if scene.spin_of is None and scene.nutation is None:
        return ()
    chain = compose(scene)
    name = scene.body.name
    parts, axes = _parts(scene)
    terms = zip(parts, axes, strict=True)
    omega = " + ".join(f"{rate} {axis}" for (rate, _), axis in terms if rate != "0") or "0"
    named = zip(axes, _units(scene), strict=True)
    where = ", ".join(f"{axis} = {_direction(u)}" for axis, u in named)
    system = spec.system
    rate_unit, accel_unit = natural_unit(Dim(0, 0, -1), system), natural_unit(Dim(0, 0, -2), system)
    H = tuple(scene.body.I_G * sympy.Matrix(chain.omega))
    H_unit = natural_unit(Dim(2, 1, -1), system)
    return (
        (
            f"angular velocity of {name}",
            f"ω = {omega} ({where}) = {_vector(chain.omega, values, rate_unit, system)}",
        ),
        (
            f"angular acceleration of {name}",
            f"α = {_alpha_form(parts, axes)} = {_vector(chain.alpha, values, accel_unit, system)}",
        ),
        (
            f"angular momentum of {name}",
            f"H_G = I_G ω = {_vector(H, values, H_unit, system)}; Ḣ_G = I_G α + ω × H_G "
            "(Euler's form, in ΣM_G)",
        ),
    )


def composition_checks(
    scene: Scene3D, values: Mapping[sympy.Symbol, sympy.Expr], spec: Spec
) -> tuple[Check, ...]:
    """ω, α, a_G by differentiating the rotations; Ḣ_G in the Ω-frame form, when the body
    spins in a frame and is symmetric about its spin axis."""
    chain = compose(scene)
    spin = scene.spin
    parts = [spin.axis, spin.through, (spin.omega, spin.alpha), scene.body.G]
    parts += [(*t.axis, *(t.through or ()), t.omega, t.alpha) for t in turns(scene)]
    point = filled([*parts, chain.omega, chain.alpha, chain.a_G], values)
    omega, alpha, a_G = by_rotations(scene, point)
    kinematic = max(
        _gap(chain.omega, omega, point),
        _gap(chain.alpha, alpha, point),
        _gap(chain.a_G, a_G, point),
    )
    checks = [
        Check(
            "ω, α, a_G by differentiating the rotations",
            kinematic < TOLERANCE,
            "R(t) = product of each turn's rotation through ω t + α t²/2 about its axis; "
            f"ω = vee(Ṙ Rᵀ), α = its derivative, a_G = G̈ at t = 0 (relative difference "
            f"{kinematic:.1e})",
        )
    ]
    framed = frame_form(scene, chain)
    if framed is not None:
        checks.append(_frame_check(scene, chain, framed, values, spec))
    euler = _euler_check(scene, chain, values, point, spec)
    return tuple(checks) + euler


def _euler_check(
    scene: Scene3D,
    chain: Composition,
    values: Mapping[sympy.Symbol, sympy.Expr],
    point: Mapping[sympy.Symbol, sympy.Expr],
    spec: Spec,
) -> tuple[Check, ...]:
    """Euler's equations in the body's principal axes (Hibbeler Eq. 21-25),
    ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z and cyclic, with ω̇_x = α·x (the axes turn with the
    body), set against I_G α + ω × H_G in scene axes; none when products of inertia are
    given (the body axes are not principal)."""
    body = scene.body
    if body.products is not None and any(p != 0 for p in body.products):
        return ()
    w = [_dot(chain.omega, e) for e in body.axes]
    a = [_dot(chain.alpha, e) for e in body.axes]
    I_x, I_y, I_z = body.principal
    M = (
        I_x * a[0] - (I_y - I_z) * w[1] * w[2],
        I_y * a[1] - (I_z - I_x) * w[2] * w[0],
        I_z * a[2] - (I_x - I_y) * w[0] * w[1],
    )
    in_scene = tuple(
        sum((m * e[i] for m, e in zip(M, body.axes, strict=True)), sympy.Integer(0))
        for i in range(3)
    )
    H = tuple(body.I_G * sympy.Matrix(chain.omega))
    I_alpha = body.I_G * sympy.Matrix(chain.alpha)
    matrix = tuple(p + q for p, q in zip(I_alpha, cross(chain.omega, H), strict=True))
    gap = _gap(in_scene, matrix, point)
    unit = natural_unit(Dim(2, 1, -2), spec.system)
    return (
        Check(
            "Euler's equations in the principal axes",
            gap < TOLERANCE,
            "ΣM_x = I_x ω̇_x − (I_y − I_z) ω_y ω_z, ΣM_y = I_y ω̇_y − (I_z − I_x) ω_z ω_x, "
            "ΣM_z = I_z ω̇_z − (I_x − I_y) ω_x ω_y in the body's x, y, z = "
            f"{_vector(M, values, unit, spec.system, formulas=False)}; turned into scene "
            "axes, as "
            f"I_G α + ω × H_G (relative difference {gap:.1e})",
        ),
    )


def _dot(a: Sequence[sympy.Expr], b: Sequence[sympy.Expr]) -> sympy.Expr:
    return sum((x * y for x, y in zip(a, b, strict=True)), sympy.Integer(0))


def _frame_check(
    scene: Scene3D,
    chain: Composition,
    framed: Vec3,
    values: Mapping[sympy.Symbol, sympy.Expr],
    spec: Spec,
) -> Check:
    H = tuple(scene.body.I_G * sympy.Matrix(chain.omega))
    I_alpha = scene.body.I_G * sympy.Matrix(chain.alpha)
    euler = tuple(a + b for a, b in zip(I_alpha, cross(chain.omega, H), strict=True))
    gap = _gap(euler, framed, values)
    assert chain.frame is not None
    unit, rate = natural_unit(Dim(2, 1, -2), spec.system), natural_unit(Dim(0, 0, -1), spec.system)
    return Check(
        "Ḣ_G in the Ω frame",
        gap < TOLERANCE,
        "(Ḣ_G)_xyz + Ω × H_G with (Ḣ_G)_xyz = I_G (α − Ω × ω) and Ω = "
        f"{_vector(chain.frame, values, rate, spec.system, formulas=False)}, "
        "the frame that carries the spin axis (I_G is constant in it) = "
        f"{_vector(framed, values, unit, spec.system, formulas=False)}; Euler's I_G α + "
        "ω × H_G agrees "
        f"(relative difference {gap:.1e})",
    )


def _gap(
    first: Sequence[sympy.Expr],
    second: Sequence[sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> float:
    gap = agree(first, second, values)
    return float("inf") if gap is None else gap


def _parts(scene: Scene3D) -> tuple[list[tuple[str, str]], list[str]]:
    """Each turn's (rate, its rate of change) as written, and its axis's name: K for the
    fixed axis, i' for the nutation's, k for the spin's."""
    parts = [(_text(scene.spin.omega), _text(scene.spin.alpha))]
    axes = ["K"]
    if scene.nutation is not None:
        parts.append((_text(scene.nutation.omega), _text(scene.nutation.alpha)))
        axes.append("i'")
    if scene.spin_of is not None:
        parts.append((_text(scene.spin_of.omega), _text(scene.spin_of.alpha)))
        axes.append("k")
    return parts, axes


def _units(scene: Scene3D) -> list[Vec3]:
    units = [scene.spin.axis]
    units += [t.axis for t in (scene.nutation, scene.spin_of) if t is not None]
    return units


def _alpha_form(parts: Sequence[tuple[str, str]], axes: Sequence[str]) -> str:
    """α part by part: each rate's change along its axis, plus the frames before it
    turning that axis (Ω_k × ω_k)."""
    terms, carried = [], []
    for (rate, change), axis in zip(parts, axes, strict=True):
        if change != "0":
            terms.append(f"{change} {axis}")
        if carried and rate != "0":
            frame = " + ".join(carried)
            frame = f"({frame})" if len(carried) > 1 else frame
            terms.append(f"{frame} × {rate} {axis}")
        if rate != "0":
            carried.append(f"{rate} {axis}")
    return " + ".join(terms) or "0"


def _text(expr: sympy.Expr) -> str:
    return formula_text(tidy(sympy.Integer(0) + expr))


def _direction(u: Vec3) -> str:
    return "(" + ", ".join(formula_text(tidy(c)) for c in u) + ")"


def _vector(
    vector: Sequence[sympy.Expr],
    values: Mapping[sympy.Symbol, sympy.Expr],
    unit: str,
    system: str,
    formulas: bool = True,
) -> str:
    """A vector in numbers with its unit where the values give them, else as formulas (or
    'in letters', for a check's detail)."""
    try:
        numbers = [float(sympy.N((sympy.Integer(0) + c).xreplace(values), 15)) for c in vector]
    except TypeError:
        if not formulas:
            return "(in letters)"
        return "(" + ", ".join(formula_text(tidied(c)) for c in vector) + ")"
    shown = [format_quantity(convert(n, unit, system), unit).rsplit(" ", 1)[0] for n in numbers]
    return f"({', '.join(shown)}) {unit}"
