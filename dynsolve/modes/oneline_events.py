"""Events of one-line motion as finds: t_at, x_at, max/min and the distance travelled.

``t_at(q, q_1)`` is the first time after t₀ at which q (x, v or a) equals q₁
(``t_at(q, q_1, n)`` the n-th); ``x_at(q, q_1)`` the position then (for an a(x) law,
``x_at(v, 0)`` is the turning point, where v(x) = 0); ``max(q)``/``min(q)`` the extreme
at a stationary point after t₀ (``max(q, t_2)``: the largest value over t₀ … t₂,
end points included); ``distance(t_2)`` (or ``distance(t_1, t_2)``) the total distance
travelled, ∫|v| dt, split where v = 0. Each gives an :class:`Event`: the value, the rule
and the roots set aside.

>>> import sympy
>>> from dynsolve.principles.rectilinear import integrate_motion
>>> zero = sympy.Integer(0)
>>> motion = integrate_motion(T**3 - 6 * T**2 + 9 * T, "x(t)", zero, zero, zero)
>>> event = find_event("distance", (sympy.Integer(5),), motion, zero, {})
>>> event.expr, event.rule.split(";")[0]
(28, 's = Σ |x(tᵢ₊₁) − x(tᵢ)| over t₀ … t₂, split where v = 0 (t = 1, 3)')
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import sympy

from dynsolve.numbers import real_value, tidy
from dynsolve.principles.rectilinear import (
    Crossings,
    Motion,
    T,
    V,
    X,
    _sign,
    crossing_times,
    extreme_time,
)
from dynsolve.shown import formula_text

EVENTS = ("t_at", "x_at", "max", "min", "distance")
QUANTITIES = ("x", "v", "a")
Values = Mapping[sympy.Symbol, sympy.Expr]


@dataclass(frozen=True)
class Event:
    """A found event: its value, the rule that gave it, roots set aside and when it occurs."""

    expr: sympy.Expr
    rule: str
    discarded: tuple[tuple[sympy.Expr, str], ...] = ()
    time: sympy.Expr | None = None


def find_event(
    function: str,
    args: Sequence[object],
    motion: Motion,
    t0: sympy.Expr,
    values: Values,
    x0: sympy.Expr | None = None,
) -> Event:
    """The event ``function(*args)``: ``args`` are already resolved (a quantity name
    ``"x"``, ``"v"``, ``"a"``; levels and times as sympy expressions; an int n for the
    n-th root); ``x0`` the start's position (0 when None). A ValueError explains why it
    cannot be found.

    >>> import sympy
    >>> from dynsolve.principles.rectilinear import integrate_motion
    >>> zero, b, v0 = sympy.Integer(0), sympy.Integer(5), sympy.Integer(25)
    >>> motion = integrate_motion(-b + 0 * T, "a(t)", zero, zero, v0)  # braking car
    >>> find_event("t_at", ("v", zero), motion, zero, {}).expr
    5
    >>> find_event("x_at", ("v", zero), motion, zero, {}).expr
    125/2
    """
    x0 = sympy.Integer(0) if x0 is None else x0
    if function in ("t_at", "x_at"):
        quantity, level = args[0], args[1]
        n = int(args[2]) if len(args) > 2 else 1  # type: ignore[call-overload]
        assert isinstance(quantity, str) and isinstance(level, sympy.Expr)
        if function == "t_at":
            return _time_at(quantity, level, n, motion, (t0, x0), values)
        return _position_at(quantity, level, n, motion, (t0, x0), values)
    if function in ("max", "min"):
        quantity = args[0]
        assert isinstance(quantity, str)
        end = args[1] if len(args) > 1 else None
        largest = function == "max"
        return _extreme(quantity, largest, end, motion, (t0, x0), values)  # type: ignore[arg-type]
    if function == "distance":
        start, end = (t0, args[0]) if len(args) == 1 else (args[0], args[1])
        return _distance(start, end, motion, values)  # type: ignore[arg-type]
    raise ValueError(f"'{function}' is not an event of the motion; one of {', '.join(EVENTS)}")


def _law(motion: Motion, quantity: str) -> sympy.Expr | None:
    return motion.formulas.get(f"{quantity}(t)")


def _ordinal(n: int) -> str:
    return {1: "first", 2: "second", 3: "third"}.get(n, f"{n}th")


def _crossings(
    q: sympy.Expr, level: sympy.Expr, t0: sympy.Expr, values: Values, count: int = 1
) -> Crossings:
    """crossing_times (``count`` crossings sought), with a numeric check (when the givens
    have values) that no crossing between t₀ and the last root kept was missed (sympy may
    return only some roots of a law it cannot see is periodic)."""
    found = crossing_times(q, level, t0, values, count=count)
    numeric = (q - level).xreplace(dict(values))
    start = real_value(t0, values)
    if not found.times or numeric.free_symbols - {T} or start is None:
        return found
    last = real_value(found.times[-1], values)
    if last is None:
        return found
    f = sympy.lambdify(T, numeric, "math")
    kept = [real_value(t, values) for t in found.times]
    samples = 4000
    step = (last - start) / samples
    previous = f(start + step / 2)
    for i in range(1, samples):
        here = start + step / 2 + i * step
        value = f(here)
        if previous * value < 0 and not any(
            k is not None and abs(k - here) <= 2 * step for k in kept
        ):
            raise ValueError(
                f"{q} = {level} has a root near t = {here:.6g}, between t₀ and the roots sympy "
                "returned: cannot number the roots"
            )
        previous = value
    return found


Start = tuple[sympy.Expr, sympy.Expr]  # (t₀, x₀)


def _time_at(
    quantity: str, level: sympy.Expr, n: int, motion: Motion, start: Start, values: Values
) -> Event:
    t0 = start[0]
    law = _law(motion, quantity)
    if law is not None:
        try:
            found = _crossings(law, level, t0, values, n)
        except ValueError:
            numeric = _scan_roots(law - level, t0, n, values)
            if numeric is None:
                raise
            time, horizon = numeric
            rule = (  # sympy's own message, its equation in Python's **, is not the reader's
                f"sympy could not solve {quantity}(t) = value; the {_ordinal(n)} sign "
                f"change of {quantity}(t) − value after t₀, found by scanning t₀ … t₀ + "
                f"{horizon:g} s and bisection, is taken (later roots not sought)"
            )
            return Event(time, rule, (), time)
        if len(found.times) < n:
            times = len(found.times)
            raise ValueError(
                f"{quantity} equals the value {times} time{'s' * (times != 1)} after t₀, not {n}"
                if times
                else f"{quantity} never equals the value after t₀"
            )
        time = found.times[n - 1]
        others = tuple(
            (t, "an earlier root" if i < n - 1 else "a later root")
            for i, t in enumerate(found.times)
            if i != n - 1
        )
        rule = f"{quantity}(t) = value solved for t; the {_ordinal(n)} root after t₀ is taken"
        return Event(time, rule, (*found.discarded, *others), time)
    if n != 1:
        raise ValueError(f"{quantity}(t) is not known as a formula: only the first time is found")
    if motion.given == "a(v)" and quantity == "v" and "t(v)" in motion.formulas:
        time = tidy(motion.formulas["t(v)"].subs(V, level))
        rule = "t = t(v) at the value (v is monotonic under an a(v) law)"
        return Event(_after(time, t0, values, quantity), rule, (), time)
    if motion.given == "a(x)" and "t(x)" in motion.formulas and quantity in ("x", "v"):
        place = level if quantity == "x" else _turning_x(level, motion, start[1], values).expr
        time = tidy(motion.formulas["t(x)"].subs(X, place))
        rule = "t = t(x) at the position" + ("" if quantity == "x" else " where v(x) = value")
        return Event(_after(time, t0, values, quantity), rule, (), time)
    raise ValueError(f"{quantity}(t) could not be found from {motion.given}")


def _scan_roots(
    q: sympy.Expr, t0: sympy.Expr, n: int, values: Values
) -> tuple[sympy.Expr, float] | None:
    """The n-th sign change of ``q`` (in T) after t₀, by scanning windows of doubling
    length (up to 2²⁰ time units) and bisecting: (the root, the scanned length), or None
    when q has symbols left or no n-th sign change is found.

    >>> import sympy
    >>> time, _ = _scan_roots(sympy.cos(T) - T, sympy.Integer(0), 1, {})  # cos t = t
    >>> round(float(time), 9)
    0.739085133
    """
    numeric = q.xreplace(dict(values))
    start = real_value(t0, values)
    if numeric.free_symbols - {T} or start is None:
        return None
    f = sympy.lambdify(T, numeric, "math")
    horizon, samples = 1.0, 4000
    while horizon <= 2.0**20:
        step = horizon / samples
        changes: list[tuple[float, float]] = []
        previous_t, previous = start + step / 2, f(start + step / 2)
        for i in range(1, samples + 1):
            here = start + step / 2 + i * step
            value = f(here)
            if previous * value <= 0 and previous != 0:
                changes.append((previous_t, here))
            previous_t, previous = here, value
        if len(changes) >= n:
            return _bisected(f, *changes[n - 1]), horizon
        horizon *= 2
    return None


def _scanned_stops(
    v: sympy.Expr, start: sympy.Expr, end: sympy.Expr, values: Values, samples: int = 4000
) -> list[sympy.Expr] | None:
    """Every sign change of ``v`` (in T) strictly between ``start`` and ``end``, by scanning
    ``samples`` steps and bisecting each; None when symbols remain.

    >>> [round(float(t), 9) for t in _scanned_stops(sympy.cos(T), sympy.Integer(0),
    ...                                              sympy.Integer(5), {})]  # π/2, 3π/2
    [1.570796327, 4.71238898]
    """
    numeric = v.xreplace(dict(values))
    low_end, high_end = real_value(start, values), real_value(end, values)
    if numeric.free_symbols - {T} or low_end is None or high_end is None:
        return None
    f = sympy.lambdify(T, numeric, "math")
    step = (high_end - low_end) / samples
    found: list[sympy.Expr] = []
    previous_t, previous = low_end + step / 2, f(low_end + step / 2)
    for i in range(1, samples):
        here = low_end + step / 2 + i * step
        value = f(here)
        if previous * value <= 0 and previous != 0:
            found.append(_bisected(f, previous_t, here))
        previous_t, previous = here, value
    return found


def _bisected(f: Callable[[float], float], low: float, high: float) -> sympy.Float:
    """The sign change of ``f`` between ``low`` and ``high``, by 80 bisections.

    >>> round(float(_bisected(lambda t: t * t - 2, 1.0, 2.0)), 12)
    1.414213562373
    """
    for _ in range(80):
        middle = (low + high) / 2
        if f(low) * f(middle) <= 0:
            high = middle
        else:
            low = middle
    return sympy.Float((low + high) / 2, 15)


def _after(time: sympy.Expr, t0: sympy.Expr, values: Values, quantity: str) -> sympy.Expr:
    """``time`` when it is a finite real time after t₀; a ValueError otherwise."""
    if time.has(sympy.oo, -sympy.oo, sympy.zoo, sympy.nan):
        raise ValueError(f"{quantity} never reaches the value: the time is infinite")
    sign = _sign(time - t0, values)
    if sign is None:
        raise ValueError(f"{quantity} never reaches the value (the time is not real)")
    if sign < 0:
        raise ValueError(f"{quantity} takes the value only before t₀ on this branch")
    return time


def _turning_x(
    level: sympy.Expr, motion: Motion, x0: sympy.Expr, values: Values, back: bool = False
) -> Event:
    """The position where v(x) = level for an a(x) law, in the motion's sense from x₀:
    the nearest root ahead of x₀ (``back``: behind it, where the motion turns again)."""
    law = motion.formulas["v(x)"]
    squared = tidy(law**2)
    roots = [tidy(r) for r in sympy.solve(sympy.Eq(squared, level**2), X, simplify=False)]
    sense = _sign(law.subs(X, x0), values) or _sign(motion.formulas["a(x)"].subs(X, x0), values)
    if not sense:
        raise ValueError("the particle starts at rest where a = 0: it never moves")
    if back:
        sense, law = -sense, -law
    ahead: list[sympy.Expr] = []
    discarded: list[tuple[sympy.Expr, str]] = []
    for root in (tidy(r) for r in roots):
        side = _sign(root - x0, values)
        if side == sense and _sign(law.subs(X, root) - level, values) == 0:
            ahead.append(root)
        else:
            discarded.append((root, "behind x₀ or on the other branch"))
    if not ahead:
        raise ValueError("v(x) never takes the value ahead of x₀")
    best = ahead[0]
    for root in ahead[1:]:
        if _sign(sense * (root - best), values) == -1:
            discarded.append((best, "farther from x₀"))
            best = root
        else:
            discarded.append((root, "farther from x₀"))
    rule = "v(x) = value solved for x; the nearest root ahead of x₀ in the motion's sense"
    return Event(best, rule, tuple(discarded))


def _position_at(
    quantity: str, level: sympy.Expr, n: int, motion: Motion, start: Start, values: Values
) -> Event:
    if motion.given == "a(x)" and quantity == "v" and n == 1:
        return _turning_x(level, motion, start[1], values)
    if motion.given == "a(v)" and quantity == "v" and "x(v)" in motion.formulas and n == 1:
        if "t(v)" in motion.formulas:  # reached after t₀ in a finite time
            _time_at(quantity, level, n, motion, start, values)
        place = tidy(motion.formulas["x(v)"].subs(V, level))
        return Event(place, "x = x(v) at the value", ())
    x_law = _law(motion, "x")
    if x_law is None:
        raise ValueError(f"x(t) could not be found from {motion.given}")
    event = _time_at(quantity, level, n, motion, start, values)
    assert event.time is not None
    place = tidy(x_law.subs(T, event.time))
    return Event(place, event.rule + "; x = x(t) then", event.discarded, event.time)


def _extreme(
    quantity: str,
    largest: bool,
    end: sympy.Expr | None,
    motion: Motion,
    start: Start,
    values: Values,
) -> Event:
    t0, x0 = start
    word = "largest" if largest else "smallest"
    law = _law(motion, quantity)
    if law is None:
        if motion.given == "a(x)" and quantity == "x" and end is None:
            return _swing(largest, motion, x0, values)
        if motion.given == "a(x)" and quantity == "v" and end is None:
            return _speed_extreme(largest, motion, x0, values)
        raise ValueError(f"{quantity}(t) could not be found from {motion.given}")
    if end is None:
        found = extreme_time(law, t0, values, largest)
        time = found.times[0]
        rule = (
            f"{quantity} is {word} where d{quantity}/dt = 0 and d²{quantity}/dt² "
            f"{'<' if largest else '>'} 0 (an extreme after t₀, not a limit as t grows)"
        )
        return Event(tidy(law.subs(T, time)), rule, found.discarded, time)
    if _sign(end - t0, values) != 1:
        raise ValueError("the end of the interval is not after t₀")
    stationary = crossing_times(sympy.diff(law, T), sympy.Integer(0), t0, values, until=end)
    inside = [t for t in stationary.times if _sign(end - t, values) == 1]
    candidates = [t0, *inside, end]
    best = candidates[0]
    discarded: list[tuple[sympy.Expr, str]] = list(stationary.discarded)
    discarded += [(t, "after the interval") for t in stationary.times if t not in inside]
    sense = 1 if largest else -1
    for time in candidates[1:]:
        gap = _sign(law.subs(T, time) - law.subs(T, best), values)
        if gap == sense:
            discarded.append((best, f"not the {word} value"))
            best = time
        else:
            discarded.append((time, f"not the {word} value"))
    rule = (
        f"{quantity} is {word} over t₀ … end at an end point or where d{quantity}/dt = 0; "
        "the candidates compared"
    )
    return Event(tidy(law.subs(T, best)), rule, tuple(discarded), best)


def _swing(largest: bool, motion: Motion, x0: sympy.Expr, values: Values) -> Event:
    """x's largest or smallest value under an a(x) law, from v² = f(x) alone: the motion
    stays where f ≥ 0, between the nearest roots of f on either side of x₀. The turning
    point ahead of x₀ is one extreme; the particle comes back (when a there points back)
    to the nearest root behind x₀, the other."""
    word = "largest" if largest else "smallest"
    ahead = _turning_x(sympy.Integer(0), motion, x0, values)
    forward = _sign(ahead.expr - x0, values)
    rule = f"v² = f(x) ≥ 0 between turning points; x's {word} value is a turning point (v = 0)"
    if forward == (1 if largest else -1):
        return Event(ahead.expr, f"{rule} ahead of x₀; " + ahead.rule, ahead.discarded)
    pull = _sign(motion.formulas["a(x)"].subs(X, ahead.expr), values)
    if pull != -forward:
        raise ValueError(
            f"x has no {word} value found: at the turning point a does not point back, "
            "so the particle need not return"
        )
    behind = _turning_x(sympy.Integer(0), motion, x0, values, back=True)
    rule += " behind x₀, reached after turning back (a points back at the first turn)"
    return Event(behind.expr, rule, (*ahead.discarded, *behind.discarded))


def _speed_extreme(largest: bool, motion: Motion, x0: sympy.Expr, values: Values) -> Event:
    """v's largest or smallest value under an a(x) law, from v² = f(x) alone (when x(t)
    is not known as a formula): v is stationary where a(x) = 0 (dv/dt = a), a maximum
    where also d²v/dt² = a'(x) v < 0 (a minimum where > 0). Each such point is passed in
    the senses the motion has there: the start's, from x₀ to the turning point ahead (or
    for ever); the other, coming back when a at that turning point points back, as far as
    the turning point behind (or for ever); both, between two turning points.

    >>> k = sympy.Integer(4)
    >>> from dynsolve.principles.rectilinear import integrate_motion
    >>> zero = sympy.Integer(0)
    >>> motion = integrate_motion(-k * X, "a(x)", zero, sympy.Integer(1), zero, invert=False)
    >>> _speed_extreme(True, motion, sympy.Integer(1), {}).expr  # v = ω x₀ at x = 0
    2
    """
    from dynsolve.solver.blocks import BudgetExceeded, time_budget

    a = motion.formulas["a(x)"]
    squared = tidy(motion.formulas["v(x)"] ** 2)
    sense = _sign(motion.formulas["v(x)"].subs(X, x0), values) or _sign(a.subs(X, x0), values)
    if not sense:
        raise ValueError("the particle starts at rest where a = 0: it never moves")
    segments = _passes(motion, x0, sense, values)
    try:
        with time_budget(0.5):
            roots = [tidy(r) for r in sympy.solve(a, X, simplify=False)]
    except (NotImplementedError, BudgetExceeded):
        raise ValueError("sympy cannot solve a(x) = 0 for the stationary points of v") from None
    slope = sympy.diff(a, X)
    word = "largest" if largest else "smallest"
    wanted = -1 if largest else 1  # the sign of d²v/dt² = a'(x) v at the extreme
    candidates: list[sympy.Expr] = []
    discarded: list[tuple[sympy.Expr, str]] = []
    for root in roots:
        if _sign(root, values) is None:
            discarded.append((root, "not real"))
            continue
        senses = [segment[0] for segment in segments if _between(root, segment, values)]
        if not senses:
            discarded.append((root, "a = 0 where the motion never goes"))
        for each in dict.fromkeys(senses):
            speed = tidy(each * sympy.sqrt(squared.subs(X, root)))
            if _sign(slope.subs(X, root) * each, values) == wanted:
                candidates.append(speed)
            else:
                discarded.append((speed, f"not a {'maximum' if largest else 'minimum'} of v"))
    if not candidates:
        raise ValueError(
            f"v has no {word} value after t₀ (no point where a = 0 is passed with "
            f"d²v/dt² {'<' if largest else '>'} 0)"
        )
    best = candidates[0]
    for speed in candidates[1:]:
        if _sign(speed - best, values) == -wanted:
            discarded.append((best, f"not the {word}"))
            best = speed
        else:
            discarded.append((speed, f"not the {word}"))
    rule = (
        f"v is {word} where a(x) = 0 and d²v/dt² = a'(x) v {'<' if largest else '>'} 0, "
        "v = ±√(v₀² + 2 ∫ a dx) there, in the sense the motion passes it"
    )
    return Event(best, rule, tuple(discarded))


Segment = tuple[int, sympy.Expr, sympy.Expr | None]  # (sense, from, to; None: for ever)


def _passes(motion: Motion, x0: sympy.Expr, sense: int, values: Values) -> list[Segment]:
    """The stretches of x an a(x) motion covers after t₀, each with its sense: from x₀ to
    the turning point ahead; back to the turning point behind when a points back at the
    first; forward again between the two when a points back at both (an oscillation)."""
    a = motion.formulas["a(x)"]
    try:
        ahead = _turning_x(sympy.Integer(0), motion, x0, values).expr
    except ValueError:
        return [(sense, x0, None)]
    segments: list[Segment] = [(sense, x0, ahead)]
    if _sign(a.subs(X, ahead), values) != -sense:
        return segments  # it stops at the turning point (or a does not bring it back)
    try:
        behind = _turning_x(sympy.Integer(0), motion, x0, values, back=True).expr
    except ValueError:
        return [*segments, (-sense, ahead, None)]
    segments.append((-sense, ahead, behind))
    if _sign(a.subs(X, behind), values) == sense:
        segments.append((sense, behind, ahead))
    return segments


def _between(point: sympy.Expr, segment: Segment, values: Values) -> bool:
    """Whether ``point`` lies strictly inside ``segment``, going from its start in its
    sense (to its end, or for ever when it has none)."""
    sense, start, end = segment
    if _sign(point - start, values) != sense:
        return False
    return end is None or _sign(end - point, values) == sense


def _distance(start: sympy.Expr, end: sympy.Expr, motion: Motion, values: Values) -> Event:
    x_law, v_law = _law(motion, "x"), _law(motion, "v")
    if x_law is None or v_law is None:
        raise ValueError(f"x(t) could not be found from {motion.given}: the distance needs it")
    if _sign(end - start, values) == -1:
        raise ValueError("the interval ends before it starts")
    scanned = False
    try:
        stops = crossing_times(v_law, sympy.Integer(0), start, values, until=end)
    except ValueError as error:
        if "at every time" in str(error):
            stops = Crossings((), ())  # at rest throughout
        elif "sympy cannot solve" in str(error):
            found = _scanned_stops(v_law, start, end, values)  # x = 6t² − 8 + 40 cos πt
            if found is None:
                raise
            stops, scanned = Crossings(tuple(found), ()), True
        else:
            raise
    inside = [t for t in stops.times if _sign(end - t, values) == 1]
    discarded = (
        *stops.discarded,
        *(
            (t, "at the end of the interval" if _sign(end - t, values) == 0 else "after it")
            for t in stops.times[len(inside) :]
        ),
    )
    bounds = [start, *inside, end]
    total = sympy.Integer(0)
    for a, b in itertools.pairwise(bounds):
        piece = tidy(x_law.subs(T, b) - x_law.subs(T, a))
        sign = _sign(piece, values)
        total += -piece if sign == -1 else piece
    total = tidy(total)
    _check_quadrature(total, v_law, start, end, inside, values)
    shown = ", ".join(_number(t, values) for t in inside) or "none inside"
    how = " (sympy could not solve v = 0: found by scanning v(t) and bisection)" * scanned
    rule = (
        f"s = Σ |x(tᵢ₊₁) − x(tᵢ)| over t₀ … t₂, split where v = 0 (t = {shown}){how}; "
        "checked against ∫|v| dt by quadrature"
    )
    return Event(total, rule, discarded)


def _number(expr: sympy.Expr, values: Values) -> str:
    """A time as a number when the givens have values, else as a formula."""
    number = real_value(expr, values)
    return f"{number:.6g}" if number is not None else formula_text(expr)


def _check_quadrature(
    total: sympy.Expr,
    v_law: sympy.Expr,
    start: sympy.Expr,
    end: sympy.Expr,
    stops: list[sympy.Expr],
    values: Values,
) -> None:
    """Compare the distance with ∫|v| dt by mpmath's quadrature, when the givens have
    values; a disagreement (a stop missed) is a ValueError, never a silent answer."""
    import mpmath

    law = v_law.xreplace(dict(values))
    points = [real_value(p, values) for p in (start, *stops, end)]
    expected = real_value(total, values)
    if law.free_symbols - {T} or None in points or expected is None:
        return
    speed = sympy.lambdify(T, sympy.Abs(law), "mpmath")
    integral = float(mpmath.quad(speed, points))  # type: ignore[arg-type]
    if abs(integral - expected) > 1e-6 * max(1.0, abs(expected)):
        raise ValueError(
            f"the distance {expected:.6g} disagrees with ∫|v| dt = {integral:.6g}: "
            "a stop was missed"
        )
