"""The onset of a steady angle: the size of a given at which a nonzero angle first exists.

A body on a turning frame has a steady (relative-equilibrium) angle θ where its moment
equation about the pin, F(θ, P) = 0, holds; θ = 0 is a root for every P (the bar hanging
on the shaft's axis), and a nonzero root branches off it where F/θ → 0, i.e. at the P
with ∂F/∂θ(0, P) = 0. ``onset(theta_s, Omega)`` finds that P, the smallest positive root,
as a formula of the givens (P left as a letter; its given value is used only for the
other answers). For the seed's bar on a shaft, F = −m g (L/2) sin θ + (m L²/3) Ω² sin θ
cos θ, so ∂F/∂θ(0, Ω) = −m g L/2 + m L² Ω²/3 and Ω_min = √(3 g/(2 L)).

The answer is checked in numbers: just below the onset (0.99 P) F/sin θ keeps one sign
over 0 < θ < 180° (no nonzero steady angle), just above it (1.01 P) it changes sign.

>>> import sympy
>>> t, W = sympy.symbols("theta W", real=True)
>>> onset_value(-sympy.sin(t) + W**2 * sympy.sin(t) * sympy.cos(t) / 4, t, W, {})
2
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import mpmath.libmp
import sympy

from dynsolve.errors import Position, SpecError
from dynsolve.numbers import tidying_lightly
from dynsolve.results import Check
from dynsolve.system import Equation

SAMPLES = 360  # angles sampled over (0, 180°) by the check


@dataclass(frozen=True)
class Onset:
    """``name = onset(angle, load)``: the residual F(angle, load) of the moment equation
    that holds the angle alone, and the onset's value (a formula of the givens)."""

    name: str
    angle: sympy.Symbol
    load: sympy.Symbol
    residual: sympy.Expr
    value: sympy.Expr


def build_onset(
    name: str,
    args: Sequence[str],
    angles: Sequence[sympy.Symbol],
    givens: Mapping[str, sympy.Symbol],
    values: Mapping[sympy.Symbol, sympy.Expr],
    equations: Sequence[Equation],
    unknowns: Sequence[sympy.Symbol],
    where: Position,
) -> Onset:
    """The onset asked for by ``name = onset(angle, load)``; a positioned SpecError when
    the names or the scene do not fit."""
    hint = "e.g. 'Omega_min = onset(theta_s, Omega)': an unknown angle of the position and a given"
    if len(args) != 2:
        raise SpecError("onset takes two names: an unknown angle and a given", where, hint)
    by_name = {a.name: a for a in angles}
    if args[0] not in by_name:
        raise SpecError(
            f"'{args[0]}' is not an unknown angle of the scene's positions", where, hint
        )
    if args[1] not in givens:
        raise SpecError(f"'{args[1]}' is not a given", where, hint)
    angle, load = by_name[args[0]], givens[args[1]]
    others = set(unknowns) - {angle}
    alone = [e for e in equations if angle in e.residual.free_symbols]
    alone = [e for e in alone if not (e.residual.free_symbols & others)]
    if not alone:
        raise SpecError(
            f"no equation of the scene holds {angle.name} alone (moments about the pin)",
            where,
            hint="pin the body with one bearing ('bearing B: at (…), pin') so that the "
            "moment about it leaves out the reactions",
        )
    residual = sympy.expand(sympy.expand_trig(alone[-1].residual))
    if sympy.simplify(residual.subs(angle, 0)) != 0:
        raise SpecError(
            f"{angle.name} = 0 is not a steady angle for every {load.name}: no nonzero "
            "angle branches off it",
            where,
            hint="onset applies where the body can rest at zero angle (a bar hanging on the "
            "shaft's axis)",
        )
    value = onset_value(residual, angle, load, {s: v for s, v in values.items() if s != load})
    if value is None:
        raise SpecError(
            f"no positive {load.name} makes a nonzero {angle.name} branch off zero",
            where,
            hint=f"check that the scene depends on {load.name}",
        )
    return Onset(name, angle, load, residual, value)


def onset_value(
    residual: sympy.Expr,
    angle: sympy.Symbol,
    load: sympy.Symbol,
    values: Mapping[sympy.Symbol, sympy.Expr],
) -> sympy.Expr | None:
    """The smallest positive root P of ∂F/∂θ(0, P) = 0 (a formula of the givens); with
    symbolic givens, the one root sympy knows to be positive. None when there is none.
    In numeric mode, with every other given a number, the root in numbers (30 digits:
    :func:`_in_numbers`)."""
    slope = sympy.diff(residual, angle).subs(angle, 0)
    if tidying_lightly():
        found = _in_numbers(slope, load, values)
        if found is not None:
            return found
    slope = sympy.simplify(slope)
    roots = sympy.solve(slope, load)
    best, best_value = None, math.inf
    for root in roots:
        number = root.xreplace(dict(values))
        if number.free_symbols:
            if root.is_positive and best is None:
                best = root
            continue
        size = complex(sympy.N(number))
        if abs(size.imag) < 1e-12 and 0 < size.real < best_value:
            best, best_value = root, size.real
    return best


def _in_numbers(
    slope: sympy.Expr, load: sympy.Symbol, values: Mapping[sympy.Symbol, sympy.Expr]
) -> sympy.Expr | None:
    """The smallest positive root of ``slope`` in ``load`` with ``values`` put in, from the
    polynomial's roots to 30 digits; None when a letter is left, the slope is not a
    polynomial in the load or its roots do not converge (then the formula is solved for)."""
    numbers = sympy.expand(slope.xreplace(dict(values)))
    if numbers.free_symbols - {load}:
        return None
    try:
        roots = sympy.Poly(numbers, load).nroots(n=30)
    except (sympy.PolynomialError, mpmath.libmp.NoConvergence):
        return None
    positive = [r for r in roots if r.is_real and r > 0]
    return min(positive) if positive else None


def onset_check(onset: Onset, values: Mapping[sympy.Symbol, sympy.Expr]) -> tuple[Check, ...]:
    """No nonzero steady angle at 0.99 × the onset, one at 1.01 × (F/sin θ changes sign
    over 0 < θ < 180°); nothing to check with symbolic givens."""
    known = {s: v for s, v in values.items() if s != onset.load}
    at = onset.value.xreplace(known)
    if at.free_symbols or onset.residual.xreplace(known).free_symbols - {onset.angle, onset.load}:
        return ()
    size = float(sympy.N(at))
    reduced = sympy.lambdify(
        (onset.angle, onset.load),
        onset.residual.xreplace(known) / sympy.sin(onset.angle),
        "math",
    )

    def changes(load: float) -> int:
        signs = [
            math.copysign(1.0, reduced(math.pi * k / SAMPLES, load)) for k in range(1, SAMPLES)
        ]
        return sum(1 for a, b in itertools.pairwise(signs) if a != b)

    below, above = changes(0.99 * size), changes(1.01 * size)
    passed = below == 0 and above >= 1
    detail = (
        f"at 0.99 × {onset.name} no nonzero {onset.angle.name} in (0°, 180°) "
        f"({below} sign changes of F/sin θ); at 1.01 × {onset.name} "
        f"{'one exists' if above else 'none either'} ({above})"
    )
    return (Check(f"onset {onset.name}", passed, detail),)
