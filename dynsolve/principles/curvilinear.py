"""Curvilinear particle kinematics: curvature of a path, n–t and r–θ components, projectiles.

``path_components`` turns a velocity and an acceleration given in any orthonormal
components (x–y, or r–θ) into the speed and the n–t components a_t, a_n and ρ.

A path is one of three frozen forms: ``ExplicitPath`` (y = f(x)), ``ImplicitPath``
(F(x, y) = 0) or ``ParametricPath`` (x(u), y(u)). ``kappa`` and ``rho`` give its
curvature and radius of curvature; ``acceleration_extremes`` finds where the
acceleration v²κ of a particle moving along it at constant speed v is largest and
smallest. Every function builds sympy objects from sympy objects: no text is parsed.

>>> import sympy
>>> a, b, v = sympy.symbols("a b v", positive=True)
>>> x, y = sympy.symbols("x y", real=True)
>>> ellipse = ImplicitPath(x**2 / a**2 + y**2 / b**2 - 1, x, y)
>>> found = acceleration_extremes(ellipse, v, order_by={a: 3, b: 2})  # a sample with a > b
>>> found.maximum.a, found.maximum.points, found.minimum.a, found.minimum.points
(a*v**2/b**2, ((a, 0), (-a, 0)), b*v**2/a**2, ((0, b), (0, -b)))
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from dynsolve.numbers import real_value, tidy

Point = tuple[sympy.Expr, sympy.Expr]
Substitution = Mapping[sympy.Symbol, sympy.Expr | float | int]
SAME = 1e-9  # relative gap under which two candidate curvatures may be the same value


@dataclass(frozen=True)
class ExplicitPath:
    """The path y = f(x), for x from ``span[0]`` to ``span[1]`` (an open path)."""

    f: sympy.Expr
    x: sympy.Symbol
    span: tuple[sympy.Expr, sympy.Expr] = (-sympy.oo, sympy.oo)


@dataclass(frozen=True)
class ImplicitPath:
    """The path F(x, y) = 0."""

    F: sympy.Expr
    x: sympy.Symbol
    y: sympy.Symbol


@dataclass(frozen=True)
class ParametricPath:
    """The path (x(u), y(u)) for u in ``span``; ``closed`` when both ends are the same point."""

    x_u: sympy.Expr
    y_u: sympy.Expr
    u: sympy.Symbol
    span: tuple[sympy.Expr, sympy.Expr] = (sympy.Integer(0), 2 * sympy.pi)
    closed: bool = True


Path = ExplicitPath | ImplicitPath | ParametricPath


@dataclass(frozen=True)
class NormalTangential:
    """Acceleration in n–t components: a_t = dv/dt, a_n = v²/ρ, and the magnitude a."""

    a_t: sympy.Expr
    a_n: sympy.Expr
    a: sympy.Expr


@dataclass(frozen=True)
class Polar:
    """Velocity and acceleration in r–θ components, as expressions in time."""

    v_r: sympy.Expr
    v_theta: sympy.Expr
    a_r: sympy.Expr
    a_theta: sympy.Expr


@dataclass(frozen=True)
class PathComponents:
    """Speed, acceleration magnitude and n–t components of a moving particle."""

    v: sympy.Expr  # speed |v|
    a: sympy.Expr  # |a|
    a_t: sympy.Expr  # (v·a)/|v| = dv/dt
    a_n: sympy.Expr  # |v × a|/|v| = v²/ρ
    rho: sympy.Expr  # v²/a_n (oo where a_n = 0: the path is straight there)


@dataclass(frozen=True)
class Extreme:
    """One stationary value of the curvature along a path, and the points where it occurs."""

    kappa: sympy.Expr
    rho: sympy.Expr
    a: sympy.Expr  # v²κ: the acceleration's magnitude there at constant speed v
    points: tuple[Point, ...]  # (x, y); a coordinate ±oo marks a limit at an end of the path


@dataclass(frozen=True)
class AccelerationExtremes:
    """The largest and smallest acceleration along a path at constant speed."""

    maximum: Extreme
    minimum: Extreme
    candidates: tuple[Extreme, ...]  # every stationary value and end, largest first
    constant: bool  # κ is the same at every point (a circle): no particular points


@dataclass(frozen=True)
class Projectile:
    """A projectile's flight from launch to landing (launch point at the origin, y up)."""

    t_flight: sympy.Expr
    x_range: sympy.Expr  # horizontal distance travelled until landing
    y_land: sympy.Expr  # landing height relative to the launch point
    t_apex: sympy.Expr
    h_max: sympy.Expr  # apex height relative to the launch point


def kappa(path: Path) -> sympy.Expr:
    """The curvature κ of ``path`` as an expression in its variables (x; x and y; or u).

    >>> import sympy
    >>> x, y, u = sympy.symbols("x y u", real=True)
    >>> R = sympy.Symbol("R", positive=True)
    >>> kappa(ExplicitPath(x**2, x))
    2/(4*x**2 + 1)**(3/2)
    >>> kappa(ImplicitPath(x**2 + y**2 - R**2, x, y)).subs({x: R, y: 0})
    1/R
    >>> kappa(ParametricPath(R * sympy.cos(u), R * sympy.sin(u), u))
    1/R
    """
    if isinstance(path, ExplicitPath):
        d1, d2 = sympy.diff(path.f, path.x), sympy.diff(path.f, path.x, 2)
        return tidy(sympy.Abs(d2) / (1 + d1**2) ** sympy.Rational(3, 2))
    if isinstance(path, ImplicitPath):
        numerator, squared_gradient = _implicit_parts(path)
        return tidy(sympy.Abs(numerator) / squared_gradient ** sympy.Rational(3, 2))
    cross, squared_speed = _parametric_parts(path)
    return tidy(sympy.Abs(cross) / squared_speed ** sympy.Rational(3, 2))


def rho(path: Path) -> sympy.Expr:
    """The radius of curvature ρ = 1/κ of ``path`` (oo where the path is straight).

    >>> import sympy
    >>> x = sympy.Symbol("x", real=True)
    >>> c = sympy.Symbol("c", positive=True)
    >>> rho(ExplicitPath(x**2 / (2 * c), x)).subs(x, 0)
    c
    """
    return _inverse(kappa(path))


def nt_acceleration(v: sympy.Expr, rho: sympy.Expr, a_t: sympy.Expr | int = 0) -> NormalTangential:
    """The n–t acceleration components a_t (given dv/dt), a_n = v²/ρ and a = √(a_t² + a_n²).

    >>> import sympy
    >>> found = nt_acceleration(sympy.Integer(20), sympy.Integer(100), sympy.Integer(3))
    >>> found.a_t, found.a_n, found.a
    (3, 4, 5)
    """
    a_t = sympy.Integer(0) + a_t
    a_n = tidy(v**2 / rho)
    return NormalTangential(a_t=a_t, a_n=a_n, a=tidy(sympy.sqrt(a_t**2 + a_n**2)))


def path_components(
    v_1: sympy.Expr | int, v_2: sympy.Expr | int, a_1: sympy.Expr | int, a_2: sympy.Expr | int
) -> PathComponents:
    """From v = (v_1, v_2) and a = (a_1, a_2) along two orthonormal axes (x–y or r–θ):
    v = |v|, a = |a|, a_t = (v·a)/v, a_n = |v × a|/v and ρ = v²/a_n.

    >>> found = path_components(4, 3, 4, 6)  # x = 2t², y = t³ at t = 1
    >>> found.v, found.a_t, found.a_n, found.rho
    (5, 34/5, 12/5, 125/12)
    """
    v_1, v_2, a_1, a_2 = (sympy.Integer(0) + c for c in (v_1, v_2, a_1, a_2))
    speed = tidy(sympy.sqrt(v_1**2 + v_2**2))
    a_n = tidy(sympy.Abs(v_1 * a_2 - v_2 * a_1) / speed)
    return PathComponents(
        v=speed,
        a=tidy(sympy.sqrt(a_1**2 + a_2**2)),
        a_t=tidy((v_1 * a_1 + v_2 * a_2) / speed),
        a_n=a_n,
        rho=_inverse(tidy(a_n / speed**2)),
    )


def polar_components(r: sympy.Expr, theta: sympy.Expr, t: sympy.Symbol) -> Polar:
    """The r–θ components v_r = ṙ, v_θ = rθ̇, a_r = r̈ − rθ̇², a_θ = rθ̈ + 2ṙθ̇ from r(t), θ(t).

    >>> import sympy
    >>> t = sympy.Symbol("t", nonnegative=True)
    >>> found = polar_components(2 * t, t**2, t)
    >>> found.v_r, found.v_theta, found.a_r, found.a_theta
    (2, 4*t**2, -8*t**3, 12*t)
    """
    r_dot, r_ddot = sympy.diff(r, t), sympy.diff(r, t, 2)
    theta_dot, theta_ddot = sympy.diff(theta, t), sympy.diff(theta, t, 2)
    return Polar(
        v_r=tidy(r_dot),
        v_theta=tidy(r * theta_dot),
        a_r=tidy(r_ddot - r * theta_dot**2),
        a_theta=tidy(r * theta_ddot + 2 * r_dot * theta_dot),
    )


def conic_parametrisation(
    path: ImplicitPath, order_by: Substitution | None = None
) -> ParametricPath | None:
    """A parametrisation of an implicit axis-aligned conic (no xy term); else None.

    With A x² + C y² + D x + E y + F₀ = 0, centre (h, k) and semi-axes a, b: an
    ellipse (A C > 0) becomes (h + a cos u, k + b sin u) for u in [0, 2π); a
    parabola (A = 0 or C = 0) becomes (u, y(u)) or (x(u), u) for u in (−oo, oo); a
    hyperbola (A C < 0) becomes its branch (h + a cosh u, k + b sinh u) (or with
    cosh and sinh swapped), the other branch being its reflection through (h, k).
    Signs the symbols' assumptions leave open are taken at ``order_by``.

    >>> import sympy
    >>> x, y = sympy.symbols("x y", real=True)
    >>> a, b = sympy.symbols("a b", positive=True)
    >>> found = conic_parametrisation(ImplicitPath(x**2 / a**2 + y**2 / b**2 - 1, x, y))
    >>> found.x_u, found.y_u, found.span, found.closed
    (a*cos(u), b*sin(u), (0, 2*pi), True)
    """
    conic = _conic(path, order_by or {})
    return None if conic is None else conic[0]


def acceleration_extremes(
    path: Path, v: sympy.Expr, order_by: Substitution | None = None
) -> AccelerationExtremes:
    """The largest and smallest acceleration v²κ along ``path`` at constant speed ``v``.

    The candidates are the stationary points of κ (dκ/du = 0 on a parametrisation,
    or Lagrange's ∇κ² ∥ ∇F on an implicit curve that is not an axis-aligned conic)
    and, on an open path, its two ends (limits where the end is at infinity). They
    are ordered by their numeric values after substituting ``order_by``: pass the
    given values there, or for symbolic givens sample values in the region meant
    (the ellipse's a = 3, b = 2 stands for every a > b; the answer holds for every
    value in that ordering region). Key ``order_by`` by the very Symbol objects of
    the path (same assumptions); v needs no value: v² > 0 scales every candidate alike.
    A ValueError names the symbols still missing a value when the order is undecided.

    >>> import sympy
    >>> x, y = sympy.symbols("x y", real=True)
    >>> ellipse = ImplicitPath(x**2 / 150**2 + y**2 / 100**2 - 1, x, y)
    >>> found = acceleration_extremes(ellipse, sympy.Integer(20))
    >>> found.maximum.a, found.maximum.points, found.minimum.a, found.minimum.points
    (6, ((150, 0), (-150, 0)), 16/9, ((0, 100), (0, -100)))
    """
    order_by = dict(order_by or {})
    if isinstance(path, ExplicitPath):
        u = sympy.Symbol("u", real=True)
        path = ParametricPath(u, path.f.subs(path.x, u), u, path.span, closed=False)
    centre = None
    if isinstance(path, ImplicitPath):
        conic = _conic(path, order_by)
        if conic is None:
            return _rank(_lagrange_candidates(path, order_by), v, order_by, constant=False)
        path, centre = conic
    found = _parametric_candidates(path)
    if found is None:
        return _rank([(kappa(path), ())], v, order_by, constant=True)
    if centre is not None:  # a hyperbola: the other branch is the reflection through its centre
        h, k = centre
        found = [
            (value, (*points, *((2 * h - px, 2 * k - py) for px, py in points)))
            for value, points in found
        ]
    return _rank(found, v, order_by, constant=False)


def projectile(
    v0: sympy.Expr,
    theta0: sympy.Expr,
    g: sympy.Expr,
    *,
    landing_height: sympy.Expr | int = 0,
    distance: sympy.Expr | None = None,
) -> Projectile:
    """A projectile's time of flight, range and apex from x = v₀cosθ₀ t, y = v₀sinθ₀ t − g t²/2.

    It lands at ``landing_height`` (the later, positive root of y(t) = h; on level
    ground t = 2v₀sinθ₀/g, launched upward), or, when ``distance`` is given, where it
    has travelled that horizontal distance. Heights are relative to the launch point.

    >>> import sympy
    >>> v0, g = sympy.symbols("v_0 g", positive=True)
    >>> theta0 = sympy.Symbol("theta_0", positive=True)
    >>> found = projectile(v0, theta0, g)
    >>> found.t_flight, found.x_range, found.h_max
    (2*v_0*sin(theta_0)/g, v_0**2*sin(2*theta_0)/g, v_0**2*sin(theta_0)**2/(2*g))
    """
    v_x, v_y = v0 * sympy.cos(theta0), v0 * sympy.sin(theta0)
    if distance is not None:
        t_flight = distance / v_x
        y_land = v_y * t_flight - g * t_flight**2 / 2
    else:
        y_land = sympy.Integer(0) + landing_height
        discriminant = v_y**2 - 2 * g * y_land
        value = real_value(discriminant)
        if value is not None and value < 0:
            raise ValueError(f"the projectile never reaches the height {y_land}")
        # level ground: t = 2 v₀ sinθ₀ / g, written so (launched upward, θ₀ > 0)
        root = v_y if y_land == 0 else sympy.sqrt(discriminant)
        t_flight = (v_y + root) / g
    t_apex = v_y / g
    return Projectile(
        t_flight=tidy(t_flight),
        x_range=tidy(v_x * t_flight),
        y_land=tidy(y_land),
        t_apex=tidy(t_apex),
        h_max=tidy(v_y * t_apex - g * t_apex**2 / 2),
    )


def _conic(
    path: ImplicitPath, order_by: Substitution
) -> tuple[ParametricPath, Point | None] | None:
    """The conic's parametrisation; for a hyperbola also the centre swapping its branches."""
    x, y = path.x, path.y
    try:
        poly = sympy.Poly(path.F, x, y)
    except sympy.PolynomialError:
        return None
    if poly.total_degree() != 2 or poly.coeff_monomial(x * y) != 0:
        return None
    A, C = poly.coeff_monomial(x**2), poly.coeff_monomial(y**2)
    D, E, F0 = poly.coeff_monomial(x), poly.coeff_monomial(y), poly.coeff_monomial(1)
    u = sympy.Symbol("u", real=True)
    line = (-sympy.oo, sympy.oo)
    if C == 0 and E != 0:  # y = −(A x² + D x + F₀)/E
        return ParametricPath(u, tidy(-(A * u**2 + D * u + F0) / E), u, line, False), None
    if A == 0 and D != 0:  # x = −(C y² + E y + F₀)/D
        return ParametricPath(tidy(-(C * u**2 + E * u + F0) / D), u, u, line, False), None
    if A == 0 or C == 0:
        return None  # one or two straight lines
    h, k = tidy(-D / (2 * A)), tidy(-E / (2 * C))
    level = D**2 / (4 * A) + E**2 / (4 * C) - F0  # A (x − h)² + C (y − k)² = level
    along_x, along_y = _sign(level / A, order_by), _sign(level / C, order_by)
    semi_x, semi_y = tidy(sympy.sqrt(abs(level / A))), tidy(sympy.sqrt(abs(level / C)))
    if along_x > 0 and along_y > 0:  # an ellipse
        x_u, y_u = h + semi_x * sympy.cos(u), k + semi_y * sympy.sin(u)
        return ParametricPath(tidy(x_u), tidy(y_u), u), None
    if along_x > 0 > along_y:  # a hyperbola opening along x
        x_u, y_u = h + semi_x * sympy.cosh(u), k + semi_y * sympy.sinh(u)
    elif along_y > 0 > along_x:  # a hyperbola opening along y
        x_u, y_u = h + semi_x * sympy.sinh(u), k + semi_y * sympy.cosh(u)
    else:
        raise ValueError(f"{path.F} = 0 is a point, a pair of lines or has no real point")
    return ParametricPath(tidy(x_u), tidy(y_u), u, line, False), (h, k)


def _implicit_parts(path: ImplicitPath) -> tuple[sympy.Expr, sympy.Expr]:
    """F_y² F_xx − 2 F_x F_y F_xy + F_x² F_yy and F_x² + F_y² (κ = |first| / second^(3/2))."""
    F, x, y = path.F, path.x, path.y
    F_x, F_y = sympy.diff(F, x), sympy.diff(F, y)
    F_xx, F_xy, F_yy = sympy.diff(F, x, 2), sympy.diff(F, x, y), sympy.diff(F, y, 2)
    numerator = F_y**2 * F_xx - 2 * F_x * F_y * F_xy + F_x**2 * F_yy
    return sympy.expand(numerator), sympy.expand(F_x**2 + F_y**2)


def _parametric_parts(path: ParametricPath) -> tuple[sympy.Expr, sympy.Expr]:
    """x'y'' − y'x'' and x'² + y'² (κ = |first| / second^(3/2))."""
    u = path.u
    dx, dy = sympy.diff(path.x_u, u), sympy.diff(path.y_u, u)
    ddx, ddy = sympy.diff(path.x_u, u, 2), sympy.diff(path.y_u, u, 2)
    return tidy(dx * ddy - dy * ddx), tidy(dx**2 + dy**2)


def _parametric_candidates(
    path: ParametricPath,
) -> list[tuple[sympy.Expr, tuple[Point, ...]]] | None:
    """(κ, (point,)) where dκ²/du = 0 and at an open path's ends; None when κ is constant."""
    u = path.u
    cross, squared_speed = _parametric_parts(path)
    slope = sympy.diff(cross**2 / squared_speed**3, u)
    numerator = sympy.numer(sympy.together(slope))
    if tidy(numerator) == 0:
        return None
    start, end = path.span
    where = sympy.Interval.Ropen(start, end) if path.closed else sympy.Interval.open(start, end)
    roots: set[sympy.Expr] = set()
    for factor, _ in sympy.factor_list(numerator)[1]:
        if not factor.has(u):
            continue  # a factor of the givens only: assumed non-zero (the generic case)
        found = sympy.solveset(factor, u, where)
        if found is sympy.S.EmptySet:
            continue
        if not isinstance(found, sympy.FiniteSet):
            raise NotImplementedError(f"cannot solve dκ/du = 0 for u: {factor} = 0 gave {found}")
        roots |= set(found)
    curvature = kappa(path)

    def at(value: sympy.Expr) -> tuple[sympy.Expr, tuple[Point, ...]]:
        point = (tidy(path.x_u.subs(u, value)), tidy(path.y_u.subs(u, value)))
        return tidy(curvature.subs(u, value)), (point,)

    def limit(value: sympy.Expr, side: str) -> tuple[sympy.Expr, tuple[Point, ...]]:
        point = tuple(sympy.limit(c, u, value, side) for c in (path.x_u, path.y_u))
        return sympy.limit(curvature, u, value, side), (point,)

    found = [at(root) for root in sorted(roots, key=sympy.default_sort_key)]
    if not path.closed:
        found.append(limit(start, "+") if start.is_infinite else at(start))
        found.append(limit(end, "-") if end.is_infinite else at(end))
    return found


def _lagrange_candidates(
    path: ImplicitPath, order_by: Substitution
) -> list[tuple[sympy.Expr, tuple[Point, ...]]]:
    """(κ, (point,)) at the real points of F = 0 where ∇(κ²) ∥ ∇F (Lagrange multipliers)."""
    F, x, y = path.F, path.x, path.y
    N, D = _implicit_parts(path)  # κ² = N²/D³
    F_x, F_y = sympy.diff(F, x), sympy.diff(F, y)
    # ∂(N²/D³)/∂x F_y − ∂(N²/D³)/∂y F_x = 0, times D⁴/N: N = 0 (κ = 0) or the bracket
    bracket = (2 * sympy.diff(N, x) * D - 3 * N * sympy.diff(D, x)) * F_y - (
        2 * sympy.diff(N, y) * D - 3 * N * sympy.diff(D, y)
    ) * F_x
    curvature = kappa(path)
    found: list[tuple[sympy.Expr, tuple[Point, ...]]] = []
    for condition in (N, sympy.expand(bracket)):
        for solution in sympy.solve([F, condition], [x, y], dict=True):
            point = (tidy(solution.get(x, x)), tidy(solution.get(y, y)))
            if any(_is_complex(c, order_by) for c in point):
                continue
            found.append((tidy(curvature.subs({x: point[0], y: point[1]})), (point,)))
    if not found:
        raise NotImplementedError(f"no real stationary point of κ found on {F} = 0")
    return found


def _rank(
    found: list[tuple[sympy.Expr, tuple[Point, ...]]],
    v: sympy.Expr,
    order_by: Substitution,
    constant: bool,
) -> AccelerationExtremes:
    """Group equal curvatures, order them by value at ``order_by``, largest first."""
    groups: list[tuple[float, sympy.Expr, list[Point]]] = []
    for value, points in found:
        number = _number(value, order_by) if len(found) > 1 else 0.0  # one: nothing to order
        for known, known_value, known_points in groups:
            close = abs(known - number) <= SAME * max(1.0, abs(number))
            if close and (known_value == value or tidy(known_value - value) == 0):
                known_points.extend(p for p in points if p not in known_points)
                break
        else:
            groups.append((number, value, list(points)))
    groups.sort(key=lambda group: -group[0])
    ranked = tuple(
        Extreme(kappa=value, rho=_inverse(value), a=tidy(v**2 * value), points=tuple(points))
        for _, value, points in groups
    )
    return AccelerationExtremes(ranked[0], ranked[-1], ranked, constant)


def _inverse(kappa: sympy.Expr) -> sympy.Expr:
    """ρ = 1/κ, with oo (not sympy's complex infinity) where the path is straight."""
    return sympy.oo if kappa == 0 else tidy(1 / kappa)


def _number(value: sympy.Expr, order_by: Substitution) -> float:
    """``value`` at ``order_by`` as a float; ValueError naming the symbols still missing."""
    if value.is_infinite:
        return float("inf") if value.is_positive else float("-inf")
    missing = sorted(map(str, value.xreplace(dict(order_by)).free_symbols))
    if missing:
        raise ValueError(f"cannot order {value}: give sample values for {', '.join(missing)}")
    number = real_value(value, order_by)
    if number is None:
        raise ValueError(f"{value} is not real at {dict(order_by)}")
    return number


def _sign(value: sympy.Expr, order_by: Substitution | None) -> int:
    """The sign of ``value`` from its assumptions, else from its value at ``order_by``."""
    if value.is_positive:
        return 1
    if value.is_negative:
        return -1
    if value.is_zero:
        return 0
    return int(sympy.sign(_number(value, order_by or {})))


def _is_complex(coordinate: sympy.Expr, order_by: Substitution) -> bool:
    """Whether ``coordinate`` is not real (decided at ``order_by`` when assumptions do not)."""
    if coordinate.is_real is not None:
        return not coordinate.is_real
    try:
        _number(coordinate, order_by)
    except ValueError as error:
        if "sample values" in str(error):
            raise
        return True
    return False
