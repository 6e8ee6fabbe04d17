"""Rectilinear particle kinematics: from a(t), a(v), a(x) or x(t) to every other relation.

The seed notes' §1.4 procedure: v(t) = v₀ + ∫a dt and x(t) = x₀ + ∫v dt for a(t);
t(v) = t₀ + ∫dv/a and x(v) = x₀ + ∫v dv/a for a(v); v² = v₀² + 2∫a dx and
t(x) = t₀ + ∫dx/v for a(x); derivatives for x(t). Inverse relations are solved for,
keeping the branch that meets the initial condition.

>>> import sympy
>>> k, v0 = sympy.symbols("k v_0", positive=True)
>>> motion = integrate_motion(-k * V, "a(v)", sympy.Integer(0), sympy.Integer(0), v0)
>>> motion.formulas["v(t)"], motion.formulas["x(v)"]
(v_0*exp(-k*t), -v/k + v_0/k)
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from dynsolve.numbers import tidy

T, X, V = sympy.symbols("t x v", real=True)
KINDS = ("a(t)", "a(v)", "a(x)", "x(t)", "v(t)")


@dataclass(frozen=True)
class Motion:
    """Every relation found, and the textbook steps that gave them."""

    given: str  # which relation the spec gives: "a(v)", …
    formulas: dict[str, sympy.Expr]  # "v(t)" → expression in t, "x(v)" → in v, …
    steps: tuple[tuple[str, str], ...]  # (relation, how it was found)


def integrate_motion(
    expr: sympy.Expr, kind: str, t0: sympy.Expr, x0: sympy.Expr, v0: sympy.Expr
) -> Motion:
    """All of v(t), x(t), a(t) and, where they exist, t(v), x(v), v(x), t(x), a(x), a(v)."""
    u = sympy.Dummy("u", real=True)
    found: dict[str, sympy.Expr] = {}
    steps: list[tuple[str, str]] = []

    def keep(name: str, value: sympy.Expr | None, how: str) -> None:
        if value is not None and name not in found:
            found[name] = tidy(value)
            steps.append((name, how))

    if kind == "a(t)":
        keep("a(t)", expr, "given")
        keep("v(t)", v0 + sympy.integrate(expr.subs(T, u), (u, t0, T)), "v = v₀ + ∫ a dt")
        keep("x(t)", x0 + sympy.integrate(found["v(t)"].subs(T, u), (u, t0, T)), "x = x₀ + ∫ v dt")
    elif kind in ("x(t)", "v(t)"):
        if kind == "x(t)":
            keep("x(t)", expr, "given")
            keep("v(t)", sympy.diff(expr, T), "v = dx/dt")
        else:
            keep("v(t)", expr, "given")
            keep("x(t)", x0 + sympy.integrate(expr.subs(T, u), (u, t0, T)), "x = x₀ + ∫ v dt")
        keep("a(t)", sympy.diff(found["v(t)"], T), "a = dv/dt")
    elif kind == "a(v)":
        keep("a(v)", expr, "given")
        keep("t(v)", t0 + sympy.integrate(1 / expr.subs(V, u), (u, v0, V)), "t = t₀ + ∫ dv/a")
        keep("x(v)", x0 + sympy.integrate(u / expr.subs(V, u), (u, v0, V)), "x = x₀ + ∫ v dv/a")
        keep("v(t)", _invert(found["t(v)"], V, T, t0, v0), "v(t) by inverting t(v)")
        keep("v(x)", _invert(found["x(v)"], V, X, x0, v0), "v(x) by inverting x(v)")
        if "v(t)" in found:
            keep("x(t)", found["x(v)"].subs(V, found["v(t)"]), "x(t) = x(v(t))")
            keep("a(t)", expr.subs(V, found["v(t)"]), "a(t) = a(v(t))")
    elif kind == "a(x)":
        keep("a(x)", expr, "given")
        squared = v0**2 + 2 * sympy.integrate(expr.subs(X, u), (u, x0, X))
        # the branch of v: the sense of v₀, or from rest the sense of a at x₀
        start = v0 if not v0.is_zero else expr.subs(X, x0)
        sign = -1 if start.is_negative else 1
        keep("v(x)", sign * sympy.sqrt(squared), "v² = v₀² + 2 ∫ a dx")
        keep(
            "t(x)",
            t0 + sympy.integrate(1 / found["v(x)"].subs(X, u), (u, x0, X)),
            "t = t₀ + ∫ dx/v",
        )
        keep("x(t)", _invert(found["t(x)"], X, T, t0, x0), "x(t) by inverting t(x)")
        if "x(t)" in found:
            keep("v(t)", sympy.diff(found["x(t)"], T), "v = dx/dt")
            keep("a(t)", sympy.diff(found["v(t)"], T), "a = dv/dt")
    else:
        raise ValueError(f"unknown kind of motion {kind!r}; one of {', '.join(KINDS)}")
    return Motion(kind, found, tuple(steps))


def _invert(
    relation: sympy.Expr,
    variable: sympy.Symbol,
    argument: sympy.Symbol,
    at: sympy.Expr,
    value: sympy.Expr,
) -> sympy.Expr | None:
    """Solve ``argument = relation(variable)`` for ``variable``; the branch through
    (``at``, ``value``). None when sympy cannot invert it."""
    if relation.has(sympy.Integral):
        return None
    try:
        roots = sympy.solve(sympy.Eq(argument, relation), variable)
    except (NotImplementedError, ValueError):
        return None
    for root in roots:
        start = tidy(root.subs(argument, at) - value)
        if start == 0:
            return root
    return roots[0] if len(roots) == 1 else None
