"""Rectilinear particle kinematics: from a(t), a(v), a(x) or x(t) to every other relation.

The seed notes' §1.4 procedure: v(t) = v₀ + ∫a dt and x(t) = x₀ + ∫v dt for a(t);
t(v) = t₀ + ∫dv/a and x(v) = x₀ + ∫v dv/a for a(v); v² = v₀² + 2∫a dx and
t(x) = t₀ + ∫dx/v for a(x); derivatives for x(t). Inverse relations are solved for,
keeping the branch that meets the initial condition. ``crossing_times`` and
``extreme_time`` find when a coordinate of a motion takes a value or its largest
(smallest) value.

>>> import sympy
>>> k, v0 = sympy.symbols("k v_0", positive=True)
>>> motion = integrate_motion(-k * V, "a(v)", sympy.Integer(0), sympy.Integer(0), v0)
>>> motion.formulas["v(t)"], motion.formulas["x(v)"]
(v_0*exp(-k*t), -v/k + v_0/k)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from functools import cmp_to_key

import sympy
from sympy.core.cache import cacheit

from dynsolve.numbers import probe_point, real_value, tidy

T, X, V = sympy.symbols("t x v", real=True)
KINDS = ("a(t)", "a(v)", "a(x)", "x(t)", "v(t)")
INVERT_BUDGET = 3.0  # seconds for sympy to invert a relation before it is left uninverted
CROSSING_BUDGET = 0.5  # CPU seconds for sympy to solve q(t) = q₁ before a numerical scan
Values = Mapping[sympy.Symbol, sympy.Expr]


@dataclass(frozen=True)
class Motion:
    """Every relation found, and the textbook steps that gave them."""

    given: str  # which relation the spec gives: "a(v)", …
    formulas: dict[str, sympy.Expr]  # "v(t)" → expression in t, "x(v)" → in v, …
    steps: tuple[tuple[str, str], ...]  # (relation, how it was found)
    inverted: bool = True  # False: no relation was inverted (only values were asked)


def integrate_motion(
    expr: sympy.Expr,
    kind: str,
    t0: sympy.Expr,
    x0: sympy.Expr,
    v0: sympy.Expr,
    invert: bool = True,
    in_time_only: bool = False,
    quick: bool = False,
    values: Values | None = None,
) -> Motion:
    """All of v(t), x(t), a(t) and, where they exist, t(v), x(v), v(x), t(x), a(x), a(v).

    With ``invert=False`` no relation is inverted (sympy's inversion may take seconds and
    fail): what only an inversion gives is left out, for the caller to integrate
    numerically when it only needs values. With ``in_time_only`` a motion given in t
    gives v(t), x(t) and a(t) only (a component of plane motion, read in t alone).
    ``quick`` (numeric mode): a relation is inverted by peeling its operations where that
    finds one branch through the start (:func:`peeled_roots`), else by sympy's solve.
    The sense of v(x) (the sign of v₀, or from rest that of a at x₀) is read at
    ``values``, the givens' values (else from the symbols' signs).
    """
    u = sympy.Dummy("u", real=True)
    found: dict[str, sympy.Expr] = {}
    steps: list[tuple[str, str]] = []

    def _invert(*args: sympy.Expr) -> sympy.Expr | None:
        return _inverse(*args, quick=quick) if invert else None

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
        squared = v0**2 + 2 * _definite(expr.subs(X, u), u, x0, X)
        sign = _start_sense(v0, expr.subs(X, x0), values or {})
        keep("v(x)", sign * sympy.sqrt(squared), "v² = v₀² + 2 ∫ a dx")
        closed = _time_of_x(squared, sign, x0, values or {})
        if closed is not None:
            keep("t(x)", t0 + closed, "t = t₀ + ∫ dx/v")
        else:  # left as the integral: its values come by quadrature
            xi = sympy.Symbol("ξ", real=True)  # shown as the integral's variable
            integral = sympy.Integral(sign / sympy.sqrt(squared.subs(X, xi)), (xi, x0, X))
            keep("t(x)", t0 + integral, QUADRATURE)
        keep("x(t)", _invert(found["t(x)"], X, T, t0, x0), "x(t) by inverting t(x)")
        if "x(t)" in found:
            keep("v(t)", sympy.diff(found["x(t)"], T), "v = dx/dt")
            keep("a(t)", sympy.diff(found["v(t)"], T), "a = dv/dt")
    else:
        raise ValueError(f"unknown kind of motion {kind!r}; one of {', '.join(KINDS)}")
    if kind in ("a(t)", "x(t)", "v(t)") and not in_time_only:
        a = expr if kind == "a(t)" else None
        _time_inverses(found, keep, a, t0, invert, quick, values or {})
    return Motion(kind, found, tuple(steps), invert)


QUADRATURE = (
    "t = t₀ + ∫ dx/v: no closed form within the budget, so its values come by quadrature "
    "(mpmath's tanh-sinh, which takes the 1/√ ends at turning points)"
)
INTEGRATE_BUDGET = 0.5  # CPU seconds for sympy to integrate a(x) or 1/v(x) in closed form
_ELEMENTARY = (
    sympy.exp, sympy.log, sympy.sin, sympy.cos, sympy.tan, sympy.asin, sympy.acos, sympy.atan,
    sympy.sinh, sympy.cosh, sympy.tanh, sympy.asinh, sympy.acosh, sympy.atanh,
)  # fmt: skip


def _definite(
    integrand: sympy.Expr, u: sympy.Symbol, low: sympy.Expr, high: sympy.Expr
) -> sympy.Expr:
    """∫ integrand du from ``low`` to ``high``: sympy's closed form within
    :data:`INTEGRATE_BUDGET` CPU seconds, else the integral itself (valued by quadrature).

    >>> u = sympy.Dummy("u", real=True)
    >>> _definite(-4 * u, u, sympy.Integer(0), X)
    -2*x**2
    """
    from dynsolve.solver.blocks import BudgetExceeded, time_budget

    try:
        with time_budget(INTEGRATE_BUDGET):
            found = sympy.integrate(integrand, (u, low, high))
    except (BudgetExceeded, NotImplementedError, ValueError, TypeError):
        return sympy.Integral(integrand, (u, low, high))
    return found if _elementary(found) else sympy.Integral(integrand, (u, low, high))


def _elementary(expr: sympy.Expr) -> bool:
    """Whether ``expr`` is a closed form built of powers and elementary functions only
    (no Integral, Piecewise, polar_lift, hypergeometric or imaginary unit)."""
    if expr.has(sympy.I) or expr.has(sympy.Integral):
        return False
    return all(isinstance(f, _ELEMENTARY) for f in expr.atoms(sympy.Function))


def _time_of_x(
    squared: sympy.Expr, sense: int, x0: sympy.Expr, values: Values
) -> sympy.Expr | None:
    """t − t₀ = ∫ dx/v from x₀ to x in closed form, where v² = ``squared`` and v has the
    sign ``sense``; None when sympy finds none of elementary functions within
    :data:`INTEGRATE_BUDGET` CPU seconds (the caller leaves the integral for quadrature).

    v² is first written as a ratio of polynomials in x whose coefficients are stand-ins
    of known sign (m a = −k x gives k/m, which sympy integrates to asin only when it
    sees a positive coefficient; at 1e-9 kg its floats would cost it tens of seconds).

    >>> k, m, x_0 = sympy.symbols("k m x_0", positive=True)
    >>> _time_of_x(k / m * (x_0**2 - X**2), -1, x_0, {})
    sqrt(m)*(-asin(x/x_0) + pi/2)/sqrt(k)
    """
    from dynsolve.solver.blocks import BudgetExceeded, time_budget

    u = sympy.Dummy("u", real=True)
    canonical, back = _signed_stand_ins(squared.subs(X, u), u, values)
    try:
        with time_budget(INTEGRATE_BUDGET):
            antiderivative = sympy.integrate(1 / sympy.sqrt(canonical), u)
    except (BudgetExceeded, NotImplementedError, ValueError, TypeError):
        return None
    if not _elementary(antiderivative):
        return None
    antiderivative = antiderivative.xreplace(back)
    closed = tidy(sense * (antiderivative.subs(u, X) - antiderivative.subs(u, x0)))
    return closed if _matches_quadrature(closed, squared, sense, x0, values) else None


def _matches_quadrature(
    closed: sympy.Expr, squared: sympy.Expr, sense: int, x0: sympy.Expr, values: Values
) -> bool:
    """Whether the closed form of t − t₀ agrees (to 1e-9) with the quadrature of ∫ dx/v at a
    point just ahead of x₀ where v² > 0, the givens' ``values`` put in: a closed form on
    another branch (a √x taken for x < 0, an asin past its range) is never used. True when
    symbols remain (nothing to compare) or no such point is found.

    >>> x_0 = sympy.Rational(1, 10)
    >>> f = 4 * (x_0**2 - X**2)  # v² of a = −4x from rest at x₀; v < 0 moving in
    >>> right = (sympy.pi / 2 - sympy.asin(X / x_0)) / 2  # −½ ∫ dx/√(x₀² − x²) from x₀
    >>> _matches_quadrature(right, f, -1, x_0, {}), _matches_quadrature(-right, f, -1, x_0, {})
    (True, False)
    """
    from dynsolve.numbers import quadratures

    rule = dict(values)
    f, law, start = (e.xreplace(rule) for e in (squared, closed, sympy.Integer(0) + x0))
    if (f.free_symbols | law.free_symbols) - {X} or start.free_symbols:
        return True
    at_start = real_value(start) or 0.0
    reach = abs(at_start) or 1.0
    xi = sympy.Symbol("ξ", real=True)
    for halving in range(60):
        point = sympy.Float(at_start + sense * reach / 2 ** (halving + 1), 30)
        speed_squared = real_value(f.xreplace({X: point}))
        if speed_squared is None or speed_squared <= 0:
            continue
        found = real_value(law.xreplace({X: point}))
        integral = sympy.Integral(sense / sympy.sqrt(f.xreplace({X: xi})), (xi, start, point))
        expected = real_value(quadratures(integral))
        if found is None or expected is None:
            return False
        return abs(found - expected) <= 1e-9 * max(abs(expected), 1e-300)
    return True


def _signed_stand_ins(
    f: sympy.Expr, u: sympy.Symbol, values: Values
) -> tuple[sympy.Expr, dict[sympy.Symbol, sympy.Expr]]:
    """``f`` as a ratio of polynomials in ``u`` with each coefficient c replaced by ±p, p a
    positive stand-in, the sign that of c at ``values`` (by assumptions without them);
    and the stand-ins' values. ``f`` as it is (no stand-ins) when it is not such a ratio
    or a sign cannot be told.

    >>> k, m = sympy.symbols("k m", positive=True)
    >>> u = sympy.Symbol("u")
    >>> canonical, back = _signed_stand_ins(1 - k * u**2 / m, u, {})  # (m − k u²)/m
    >>> sorted(back.values(), key=str), canonical.xreplace(back)
    ([k, m, m], (-k*u**2 + m)/m)
    """
    numerator, denominator = sympy.fraction(sympy.together(f))
    try:
        polys = [sympy.Poly(numerator, u), sympy.Poly(denominator, u)]
    except sympy.PolynomialError:
        return f, {}
    back: dict[sympy.Symbol, sympy.Expr] = {}
    sides = []
    for poly in polys:
        side = sympy.Integer(0)
        for (power,), coefficient in poly.terms():
            try:
                sign = _sign(coefficient, values)
            except ValueError:
                return f, {}
            if not sign:
                return f, {}
            stand_in = sympy.Dummy("p", positive=True)
            back[stand_in] = sign * coefficient
            side += sign * stand_in * u**power
        sides.append(side)
    return sides[0] / sides[1], back


def _time_inverses(
    found: dict[str, sympy.Expr],
    keep: Callable[[str, sympy.Expr | None, str], None],
    a: sympy.Expr | None,
    t0: sympy.Expr,
    invert: bool = True,
    quick: bool = False,
    values: Values | None = None,
) -> None:
    """t(v), x(v), v(x), t(x) of a motion known in t: the constant-acceleration formulas
    when a is a constant, else v(t) inverted on the branch through t₀ (when sympy can).

    >>> b, v0 = sympy.symbols("b v_0", positive=True)
    >>> m = integrate_motion(-b + 0 * T, "a(t)", sympy.Integer(0), sympy.Integer(0), v0)
    >>> m.formulas["t(v)"], m.formulas["x(v)"]
    (-(v - v_0)/b, (-v**2 + v_0**2)/(2*b))
    """
    v0, x0 = tidy(found["v(t)"].subs(T, t0)), tidy(found["x(t)"].subs(T, t0))
    if a is not None and not a.has(T) and not a.is_zero:
        keep("t(v)", t0 + (V - v0) / a, "t = t₀ + (v − v₀)/a (constant a)")
        keep("x(v)", x0 + (V**2 - v0**2) / (2 * a), "v² = v₀² + 2 a (x − x₀) (constant a)")
        sign = _start_sense(v0, a, values or {})
        keep(
            "v(x)",
            sign * sympy.sqrt(v0**2 + 2 * a * (X - x0)),
            "v² = v₀² + 2 a (x − x₀), the sense of the start (before any turning point)",
        )
        keep("t(x)", found["t(v)"].subs(V, found["v(x)"]), "t(x) = t(v(x)) (constant a)")
        return
    if not invert:
        return
    how = "t(v) by inverting v(t) (branch through t₀)"
    keep("t(v)", _inverse(found["v(t)"], T, V, v0, t0, quick), how)
    if "t(v)" in found:
        keep("x(v)", found["x(t)"].subs(T, found["t(v)"]), "x(v) = x(t(v))")


def _start_sense(v0: sympy.Expr, a0: sympy.Expr, values: Values) -> int:
    """The sense of the motion at the start (+1 or −1): that of v₀, or from rest that of a₀,
    read at the givens' ``values`` (a given's symbol has no sign of its own).

    >>> v_0, k = sympy.symbols("v_0 k")
    >>> _start_sense(v_0, -k, {v_0: sympy.Integer(0), k: sympy.Integer(4)})
    -1
    >>> _start_sense(v_0, -k, {v_0: sympy.Float(-0.2), k: sympy.Integer(4)})
    -1
    """
    moving = _sign(v0, values)
    if moving is None:
        raise ValueError(f"the start's velocity {v0} is not real")
    if moving != 0:
        return moving
    pushed = _sign(a0, values)
    if not pushed:
        raise ValueError(
            "from rest with no acceleration at the start the sense of v(x) is undecided"
        )
    return pushed


@dataclass(frozen=True)
class Crossings:
    """The times after t₀ at which a coordinate takes a value, and the roots set aside."""

    times: tuple[sympy.Expr, ...]  # after t₀, earliest first
    discarded: tuple[tuple[sympy.Expr, str], ...]  # (root, why it was set aside)


def crossing_times(
    q: sympy.Expr,
    level: sympy.Expr,
    t0: sympy.Expr,
    values: Values | None = None,
    *,
    count: int = 1,
    until: sympy.Expr | None = None,
) -> Crossings:
    """Times t > t₀ at which ``q`` (an expression in ``T``) equals ``level``, earliest first.

    The roots are placed by their values at ``values`` (the givens' values), or, for
    symbolic givens, by the symbols' assumptions. When ``q − level`` is periodic in t
    (``sympy.periodicity``) and the givens have values, the roots sympy's ``solve``
    returns (one period's) are repeated by whole periods so that the times cover
    t₀ … ``until`` (when given) or ``count`` periods after t₀, which hold at least ``count``
    crossings when there is one; a symbolic periodic law gets sympy's roots only. A
    ValueError says when sympy cannot solve ``q = level`` for t, cannot place a root, or
    when the periods asked would hold more than :data:`MAX_CROSSINGS` roots.

    >>> import sympy
    >>> y = 10 * T - sympy.Rational(981, 200) * T**2  # y = v_y0 t - g t²/2
    >>> found = crossing_times(y, sympy.Integer(0), sympy.Integer(0))
    >>> found.times, found.discarded
    ((2000/981,), ((0, 'not after t₀'),))
    >>> # sin t = 0 at whole multiples of π; two periods after t₀ = 4 reach 4 + 4π = 16.57
    >>> crossing_times(sympy.sin(T), sympy.Integer(0), sympy.Integer(4), count=2).times
    (2*pi, 3*pi, 4*pi, 5*pi)
    """
    values = dict(values or {})
    if tidy(q - level) == 0:
        raise ValueError(f"{q} equals {level} at every time")
    solved = _roots_in_t(q - level)
    if solved is None:
        raise ValueError(f"sympy cannot solve {q} = {level} for t")
    roots = [tidy(r) for r in solved]
    period = _period(q - level, values)
    if period is not None:
        roots = _every_period(roots, period, t0, until, count, values)
    kept: list[sympy.Expr] = []
    discarded: list[tuple[sympy.Expr, str]] = []
    for root in dict.fromkeys(tidy(r) for r in roots):
        after = _sign(root - t0, values)
        if after is None:
            discarded.append((root, "not real"))
        elif after > 0:
            kept.append(root)
        else:
            discarded.append((root, "not after t₀"))
    ordered = sorted(kept, key=cmp_to_key(lambda a, b: _sign(a - b, values) or 0))
    return Crossings(tuple(ordered), tuple(discarded))


@cacheit
def _roots_in_t(expr: sympy.Expr) -> tuple[sympy.Expr, ...] | None:
    """sympy's roots of ``expr`` = 0 in t, or None when it cannot solve it within
    :data:`CROSSING_BUDGET` CPU seconds (12 t = 40π sin πt: sympy spends 7 s to give up; the
    roots it finds in the bundled problems take under 0.03 s);
    remembered per solve, since t_at, max and distance may ask the same.

    >>> _roots_in_t(T**2 - 4)
    (-2, 2)
    """
    from dynsolve.solver.blocks import BudgetExceeded, time_budget

    if any(_kepler_like(factor) for factor in sympy.Mul.make_args(sympy.factor_terms(expr))):
        return None  # no closed form: not worth sympy's search (nor waiting out the budget)
    try:
        with time_budget(CROSSING_BUDGET):
            return tuple(sympy.solve(expr, T, simplify=False))
    except (NotImplementedError, BudgetExceeded):
        return None


def _kepler_like(expr: sympy.Expr) -> bool:
    """Whether t appears in ``expr`` both inside a trigonometric function and outside any
    (12 t − 40π sin πt, Kepler's M = E − e sin E): such an equation has no closed-form root.

    >>> _kepler_like(12 * T - 40 * sympy.pi * sympy.sin(sympy.pi * T))
    True
    >>> _kepler_like(sympy.sin(T) - sympy.Rational(1, 2)), _kepler_like(T**2 - 4)
    (False, False)
    """
    trig = expr.atoms(sympy.sin, sympy.cos, sympy.tan, sympy.cot, sympy.sec, sympy.csc)
    inside = {f: sympy.Dummy() for f in trig if f.has(T)}
    return bool(inside) and expr.xreplace(inside).has(T)


MAX_CROSSINGS = 1000  # roots of a periodic law listed at most (one per period and family)


def _period(expr: sympy.Expr, values: Values) -> sympy.Expr | None:
    """The period in t of ``expr`` (positive where the givens' values tell), or None when it
    is not periodic or sympy cannot tell."""
    trig = expr.atoms(sympy.sin, sympy.cos, sympy.tan, sympy.cot, sympy.sec, sympy.csc)
    trig = {f for f in trig if f.has(T)}
    if not trig:
        return None  # periodicity's search costs 0.1 s on a projectile's polynomial
    period = _harmonic_period(expr, trig)
    if period is None:
        try:
            period = sympy.periodicity(expr, T)
        except (NotImplementedError, ValueError, TypeError):
            return None
        if period is None or period.has(T) or period == 0:
            return None
    number = real_value(sympy.Integer(0) + period, values)
    return tidy(-period if number is not None and number < 0 else period)


def _harmonic_period(expr: sympy.Expr, trig: set[sympy.Expr]) -> sympy.Expr | None:
    """2π/ω when ``expr`` is c₀ + Σ cᵢ sin or cos(ω t + φᵢ), one ω, the c's free of t (a
    harmonic motion: R sin(ω t + φ) + c₀ has that fundamental period); ``trig`` holds its
    trigonometric functions of t. None otherwise, for ``sympy.periodicity`` (which takes a
    second on a spring's solved law).

    >>> w, A = sympy.symbols("w A", positive=True)
    >>> _harmonic_period(A * sympy.sin(w * T + 1) - 3, {sympy.sin(w * T + 1)})
    2*pi/w
    >>> _harmonic_period(sympy.sin(T) ** 2, {sympy.sin(T)}) is None
    True
    """
    if not trig or any(type(f) not in (sympy.sin, sympy.cos) for f in trig):
        return None
    rates = {tidy(sympy.diff(f.args[0], T)) for f in trig}
    if len(rates) != 1:
        return None
    (rate,) = rates
    if rate == 0 or rate.has(T):
        return None
    slots = {f: sympy.Dummy() for f in trig}
    linear = expr.xreplace(slots)
    if linear.has(T) or not all(
        sympy.diff(linear, u).free_symbols.isdisjoint(slots.values()) for u in slots.values()
    ):
        return None
    return 2 * sympy.pi / rate


def _every_period(
    roots: Sequence[sympy.Expr],
    period: sympy.Expr,
    t0: sympy.Expr,
    until: sympy.Expr | None,
    count: int,
    values: Values,
) -> list[sympy.Expr]:
    """Each root of one period repeated by whole periods over t₀ … ``until`` (or ``count``
    periods; a repeat within rounding of either end is kept, for the exact test of the
    caller); sympy's own roots are kept as they are, for the caller to discard those
    before t₀."""
    start, step = real_value(t0, values), real_value(period, values)
    end = real_value(until, values) if until is not None else None
    if start is None or step is None or (until is not None and end is None):
        if count == 1 and until is None:
            return list(roots)  # the first crossing: among the roots sympy returns
        missing = ", ".join(sorted(map(str, period.free_symbols | t0.free_symbols)))
        raise ValueError(
            f"the law repeats every {period}: its later crossings are counted with values "
            f"for {missing or 'the givens'}"
        )
    if end is None:
        end = start + max(count, 1) * step
    if (end - start) / step * max(len(roots), 1) > MAX_CROSSINGS:
        raise ValueError(
            f"the periodic law repeats every {step:.6g} s: over {end - start:.6g} s it would "
            f"cross more than {MAX_CROSSINGS} times (ask for a shorter interval)"
        )
    slack = 1e-9 * step  # a repeat this close to t₀ or the end is decided exactly later
    repeated: list[sympy.Expr] = []
    for root in roots:
        repeated.append(root)
        at = real_value(root, values)
        if at is None:
            continue  # complex: discarded by the caller as "not real"
        first = math.floor((start - at) / step)  # the last repeat at or before t₀
        last = math.floor((end - at) / step) + 1
        repeated += [
            tidy(root + k * period)
            for k in range(first, last + 1)
            if k != 0 and start - slack <= at + k * step <= end + slack
        ]
    return repeated  # the caller tidies and drops repeats


def extreme_time(
    q: sympy.Expr, t0: sympy.Expr, values: Values | None = None, largest: bool = True
) -> Crossings:
    """When after t₀ ``q`` (in ``T``) is largest (``largest``) or smallest: dq/dt = 0 with
    d²q/dt² < 0 (> 0); of several such times the one with the largest (smallest) q.

    ``times`` holds that one time; ``discarded`` the other stationary times and why.
    A ValueError when there is none, or when it cannot be decided (see ``crossing_times``).

    >>> import sympy
    >>> found = extreme_time(10 * T - 5 * T**2, sympy.Integer(0))  # dy/dt = 10 - 10 t
    >>> found.times, found.discarded
    ((1,), ())
    """
    values = dict(values or {})
    rate = sympy.diff(q, T)
    stationary = crossing_times(rate, sympy.Integer(0), t0, values)
    sense = -1 if largest else 1
    curvature = sympy.diff(rate, T)
    candidates: list[sympy.Expr] = []
    discarded = list(stationary.discarded)
    for time in stationary.times:
        bend = _sign(curvature.subs(T, time), values)
        if bend == sense:
            candidates.append(time)
        else:
            word = "a minimum" if bend == 1 else "a maximum" if bend == -1 else "no extreme"
            discarded.append((time, word))
    if not candidates:
        word = "largest" if largest else "smallest"
        raise ValueError(f"{q} has no {word} value after t₀ (no time where dq/dt = 0 fits)")
    best = candidates[0]
    for time in candidates[1:]:
        gap = _sign(q.subs(T, time) - q.subs(T, best), values)
        if gap == -sense:
            discarded.append((best, "a smaller extreme" if largest else "a larger extreme"))
            best = time
        elif gap == 0:
            discarded.append((time, "the same extreme, later"))
        else:
            discarded.append((time, "a smaller extreme" if largest else "a larger extreme"))
    return Crossings((best,), tuple(discarded))


def _size(expr: sympy.Expr, values: Values) -> float:
    """The sum of the magnitudes of ``expr``'s terms at ``values``: the scale a zero is judged on,
    so a problem scaled by 10^k decides its signs the same way."""
    total = 0.0
    for term in sympy.Add.make_args(expr):
        number = real_value(tidy(sympy.Integer(0) + term).xreplace(values))
        total += abs(number) if number is not None else 0.0
    return total


def _sign(expr: sympy.Expr, values: Values) -> int | None:
    """The sign of ``expr`` (−1, 0, 1) at ``values``, or by assumptions when symbols remain;
    None when it is not real. ValueError when it cannot be decided."""
    at = tidy(sympy.Integer(0) + expr).xreplace(values)
    if not at.free_symbols:
        number = real_value(at)
        if number is None:
            return None
        return 0 if abs(number) <= 1e-12 * _size(expr, values) else (1 if number > 0 else -1)
    if at.is_real is False:
        return None
    if at.is_zero:
        return 0
    if at.is_positive:
        return 1
    if at.is_negative:
        return -1
    missing = ", ".join(sorted(map(str, at.free_symbols)))
    raise ValueError(f"cannot tell the sign of {expr}; give values for {missing}")


def _inverse(
    relation: sympy.Expr,
    variable: sympy.Symbol,
    argument: sympy.Symbol,
    at: sympy.Expr,
    value: sympy.Expr,
    quick: bool = False,
) -> sympy.Expr | None:
    """Solve ``argument = relation(variable)`` for ``variable``; the branch through
    (``at``, ``value``). None when sympy cannot invert it.

    ``quick``: first by :func:`peeled_roots`, taken when exactly one of its roots passes
    through the start (the branch sympy's solve would give: it returns the same
    inverses of each operation); otherwise sympy's solve decides, as without ``quick``."""
    from dynsolve.solver.blocks import BudgetExceeded, time_budget

    if relation.has(sympy.Integral):
        return None
    if quick:
        peeled = peeled_roots(relation, variable, argument)
        if peeled is not None:
            tidied = (tidy(root, light=False) for root in peeled)  # small forms: cheap
            through = [r for r in tidied if _passes(r, argument, at, value)]
            if len(through) == 1:
                return through[0]
    try:
        with time_budget(INVERT_BUDGET):
            roots = [
                tidy(r) for r in sympy.solve(sympy.Eq(argument, relation), variable, simplify=False)
            ]
    except (NotImplementedError, ValueError, BudgetExceeded):
        return None
    through = [root for root in roots if _passes(root, argument, at, value)]
    if len(through) > 1 and variable == T:  # t = ±√(2 (v − v₀)/c) from rest: t ≥ t₀
        return _forward(through, relation, argument, value)
    if through:
        return through[0]
    return roots[0] if len(roots) == 1 else None


def _forward(
    branches: Sequence[sympy.Expr], relation: sympy.Expr, argument: sympy.Symbol, t0: sympy.Expr
) -> sympy.Expr | None:
    """Of several branches t(q) through the start, the one the motion takes after t₀: it
    gives back t₀ + h from q(t₀ + h), for the first h (from 1e-3 s up) at which exactly one
    does, at a point of the letters' domain (:func:`~dynsolve.numbers.probe_point`); None
    (no t(q) shown, never a wrong one) where none decides.

    >>> v0, c = sympy.symbols("v_0 c", positive=True)
    >>> _forward([-sympy.sqrt(2 * (V - v0) / c), sympy.sqrt(2 * (V - v0) / c)],
    ...          v0 + c * T**2 / 2, V, sympy.Integer(0))
    sqrt(2*v - 2*v_0)/sqrt(c)
    """
    for h in (sympy.Rational(1, 1000), sympy.Rational(1, 10), sympy.Integer(1), sympy.Integer(10)):
        later = t0 + h
        q = relation.xreplace({T: later})
        back = [b for b in branches if _gives_back(b.xreplace({argument: q}), later)]
        if len(back) == 1:
            return back[0]
    return None


def _gives_back(time: sympy.Expr, later: sympy.Expr) -> bool:
    """``time`` equals ``later`` (to 1e-9 of its size) at a point of the letters' domain."""
    point = probe_point(time - later)
    if point is None:
        return False
    found = real_value(time.xreplace(point))
    wanted = real_value(later.xreplace(point))
    return found is not None and wanted is not None and abs(found - wanted) <= 1e-9 * abs(wanted)


def _passes(root: sympy.Expr, argument: sympy.Symbol, at: sympy.Expr, value: sympy.Expr) -> bool:
    """Whether the branch ``root`` (in ``argument``) takes ``value`` at ``at`` (identically)."""
    return tidy(root.subs(argument, at) - value) == 0


_UNDO: dict[type, Callable[[sympy.Expr], list[sympy.Expr]]] = {
    sympy.exp: lambda y: [sympy.log(y)],
    sympy.log: lambda y: [sympy.exp(y)],
    sympy.sin: lambda y: [sympy.pi - sympy.asin(y), sympy.asin(y)],
    sympy.cos: lambda y: [2 * sympy.pi - sympy.acos(y), sympy.acos(y)],
    sympy.tan: lambda y: [sympy.atan(y)],
    sympy.sinh: lambda y: [sympy.asinh(y)],
    sympy.cosh: lambda y: [-sympy.acosh(y), sympy.acosh(y)],
    sympy.tanh: lambda y: [sympy.atanh(y)],
    sympy.asin: lambda y: [sympy.sin(y)],
    sympy.acos: lambda y: [sympy.cos(y)],
    sympy.atan: lambda y: [sympy.tan(y)],
    sympy.asinh: lambda y: [sympy.sinh(y)],
    sympy.acosh: lambda y: [sympy.cosh(y)],
    sympy.atanh: lambda y: [sympy.tanh(y)],
}
_UNDO_POWER: dict[sympy.Rational, Callable[[sympy.Expr], list[sympy.Expr]]] = {
    sympy.Integer(2): lambda y: [-sympy.sqrt(y), sympy.sqrt(y)],
    sympy.Integer(-1): lambda y: [1 / y],
    sympy.Integer(-2): lambda y: [-sympy.sqrt(1 / y), sympy.sqrt(1 / y)],
    sympy.Rational(1, 2): lambda y: [y**2],
    sympy.Rational(-1, 2): lambda y: [y**-2],
}


def peeled_roots(
    relation: sympy.Expr, variable: sympy.Symbol, argument: sympy.Expr
) -> list[sympy.Expr] | None:
    """The roots of ``argument = relation(variable)`` for ``variable``, found by undoing the
    relation's operations from the outside in, when ``variable`` occurs once in it: a sum
    or product less its other terms or factors, then each function's inverses as sympy's
    solve gives them (sin: asin and π − asin; x²: ±√), down to ``variable``. None when it
    occurs more than once or an operation has no listed inverse.

    >>> k, v_0 = sympy.symbols("k v_0", positive=True)
    >>> peeled_roots((1 / V - 1 / v_0) / k, V, T)  # t(v) of a = -k v²
    [1/(k*t + 1/v_0)]
    >>> peeled_roots(sympy.asin(sympy.sqrt(k) * X / v_0) / sympy.sqrt(k), X, T)
    [v_0*sin(sqrt(k)*t)/sqrt(k)]
    >>> peeled_roots(V**2 + V, V, T) is None
    True
    """
    inner, sides = sympy.Integer(0) + relation, [sympy.Integer(0) + argument]
    while inner != variable:
        if inner.is_Add or inner.is_Mul:
            holding = [a for a in inner.args if a.has(variable)]
            if len(holding) != 1:
                return None
            rest = inner.func(*(a for a in inner.args if a is not holding[0]))
            sides = [y - rest if inner.is_Add else y / rest for y in sides]
            inner = holding[0]
        elif inner.is_Pow and not inner.exp.has(variable) and inner.exp in _UNDO_POWER:
            sides = [x for y in sides for x in _UNDO_POWER[inner.exp](y)]
            inner = inner.base
        elif type(inner) in _UNDO and len(inner.args) == 1:
            sides = [x for y in sides for x in _UNDO[type(inner)](y)]
            inner = inner.args[0]
        else:
            return None
    return sides


@cacheit  # x(t_1) and v(t_1) from one integration (sympy's cache, cleared with it)
def integrate_numerically(
    a: sympy.Expr, kind: str, t0: float, x0: float, v0: float, t1: float
) -> tuple[float, float]:
    """(x, v) at t1 by integrating x' = v, v' = a(t, x or v) numerically (mpmath's
    Taylor-series ODE solver): the values when a relation could not be inverted. The
    result is kept for the same law, start and time (asked for x and for v at t_1).

    >>> x, v = integrate_numerically(-V, "a(v)", 0.0, 0.0, 2.0, 1.0)  # v = 2 e^(−t)
    >>> round(v, 10), round(x, 10)
    (0.7357588823, 1.2642411177)
    """
    import mpmath

    from dynsolve.budget import step

    variable = {"a(t)": T, "a(v)": V, "a(x)": X}[kind]
    rate = sympy.lambdify(variable, a, "mpmath")

    def slopes(t: object, state: list[object]) -> list[object]:
        x, v = state
        return [v, rate({"a(t)": t, "a(v)": v, "a(x)": x}[kind])]

    with step("checking the motion stays finite (scipy ODE)"):
        escape = escape_time(a, kind, t0, x0, v0, t1)
    if escape is not None:
        raise MotionBlowsUp(escape)
    with step("integrating the motion numerically (mpmath ODE)"):
        solution = mpmath.odefun(slopes, t0, [x0, v0])
        x, v = solution(t1)
    return float(x), float(v)


class MotionBlowsUp(ArithmeticError):
    """x or v grows without bound before the time asked for; ``time`` is where it does."""

    def __init__(self, time: float) -> None:
        super().__init__(f"the motion blows up at t = {time:.6g}")
        self.time = time


BLOW_UP_FACTOR = 1e12  # x or v this many times its natural scale: taken as unbounded


def escape_time(
    a: sympy.Expr, kind: str, t0: float, x0: float, v0: float, t1: float
) -> float | None:
    """The time before ``t1`` at which the motion leaves every finite bound, or None.

    A float64 integration (scipy's ``solve_ivp``, DOP853) from t₀ that stops when x or v
    exceeds ``BLOW_UP_FACTOR`` times its natural scale, or when the step size collapses:
    mpmath's Taylor solver would otherwise creep towards the singularity forever.

    >>> escape_time(V**2, "a(v)", 0.0, 0.0, 1.0, 2.0)  # v = 1/(1 − t)
    1.0
    >>> escape_time(-V, "a(v)", 0.0, 0.0, 2.0, 1.0) is None
    True
    """
    import numpy as np
    from scipy.integrate import solve_ivp

    variable = {"a(t)": T, "a(v)": V, "a(x)": X}[kind]
    rate = sympy.lambdify(variable, a, "numpy")
    span = t1 - t0
    a0 = float(rate({"a(t)": t0, "a(v)": v0, "a(x)": x0}[kind]))
    v_scale = max(abs(v0), abs(a0) * span, abs(x0) / span, 1e-300)
    x_scale = max(abs(x0), v_scale * span)

    def slopes(t: float, state: np.ndarray) -> list[float]:
        x, v = state
        return [v, rate({"a(t)": t, "a(v)": v, "a(x)": x}[kind])]

    def unbounded(t: float, state: np.ndarray) -> float:
        return BLOW_UP_FACTOR - max(abs(state[0]) / x_scale, abs(state[1]) / v_scale)

    unbounded.terminal = True  # type: ignore[attr-defined]
    with np.errstate(all="ignore"):
        run = solve_ivp(
            slopes,
            (t0, t1),
            [x0, v0],
            method="DOP853",
            rtol=1e-10,
            atol=[1e-12 * x_scale, 1e-12 * v_scale],
            events=unbounded,
        )
    if run.status == 1 or (run.status == -1 and run.t[-1] < t1):
        return float(round(run.t[-1], 6 - int(np.floor(np.log10(abs(run.t[-1]) or 1.0)))))
    return None
