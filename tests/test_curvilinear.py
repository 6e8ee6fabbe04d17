"""Curvilinear kinematics: curvature, n–t and r–θ components, extremes, projectiles.

Every expected number is derived by hand in the comment beside its assertion.
"""

import math

import pytest
import sympy
from hypothesis import given
from hypothesis import strategies as st

from dynsolve.principles.curvilinear import (
    ExplicitPath,
    ImplicitPath,
    ParametricPath,
    acceleration_extremes,
    conic_parametrisation,
    kappa,
    nt_acceleration,
    polar_components,
    projectile,
    rho,
)

x, y, u = sympy.symbols("x y u", real=True)
t = sympy.Symbol("t", nonnegative=True)
a, b, c, v, R = sympy.symbols("a b c v R", positive=True)
ELLIPSE = ImplicitPath(x**2 / a**2 + y**2 / b**2 - 1, x, y)


def points(extreme) -> set[tuple[float, float]]:
    return {(float(px), float(py)) for px, py in extreme.points}


def test_ellipse_extremes_with_numbers():
    # (a cos u, b sin u): x'y'' − y'x'' = ab sin²u + ab cos²u = ab and
    # x'² + y'² = a² sin²u + b² cos²u, so κ = ab/(a² sin²u + b² cos²u)^(3/2).
    # u = 0, π (x = ±a): κ = ab/b³ = a/b², ρ = b²/a = 100²/150 = 66.667 m,
    #   a_n = v²/ρ = 400/66.667 = 6.0 m/s².
    # u = π/2, 3π/2 (y = ±b): κ = ab/a³ = b/a², ρ = a²/b = 150²/100 = 225 m,
    #   a_n = 400/225 = 1.7777778 m/s².
    path = ImplicitPath(x**2 / 150**2 + y**2 / 100**2 - 1, x, y)
    found = acceleration_extremes(path, sympy.Integer(20))
    assert float(found.maximum.a) == pytest.approx(6.0)
    assert float(found.maximum.rho) == pytest.approx(66.6666667)
    assert points(found.maximum) == {(150.0, 0.0), (-150.0, 0.0)}
    assert float(found.minimum.a) == pytest.approx(1.7777778)
    assert float(found.minimum.rho) == pytest.approx(225.0)
    assert points(found.minimum) == {(0.0, 100.0), (0.0, -100.0)}
    assert not found.constant


def test_ellipse_extremes_with_symbols_follow_the_sample_ordering():
    # Same κ as above: a/b² at x = ±a and b/a² at y = ±b; a/b² > b/a² ⇔ a³ > b³ ⇔ a > b.
    wide = acceleration_extremes(ELLIPSE, v, order_by={a: 3, b: 2})  # stands for a > b
    assert sympy.simplify(wide.maximum.a - v**2 * a / b**2) == 0
    assert sympy.simplify(wide.minimum.a - v**2 * b / a**2) == 0
    assert set(wide.maximum.points) == {(a, 0), (-a, 0)}
    assert set(wide.minimum.points) == {(0, b), (0, -b)}
    tall = acceleration_extremes(ELLIPSE, v, order_by={a: 2, b: 3})  # stands for a < b
    assert sympy.simplify(tall.maximum.a - v**2 * b / a**2) == 0
    assert set(tall.maximum.points) == {(0, b), (0, -b)}
    # the symbolic answer at the book's numbers: 20²·150/100² = 6, 20²·100/150² = 16/9
    book = {a: 150, b: 100, v: 20}
    assert float(wide.maximum.a.subs(book)) == pytest.approx(6.0)
    assert float(wide.minimum.a.subs(book)) == pytest.approx(1.7777778)


def test_symbolic_givens_without_sample_values_are_refused():
    with pytest.raises(ValueError, match="sample values"):
        acceleration_extremes(ELLIPSE, v)


def test_ellipse_conic_parametrisation():
    # x²/a² + y²/b² = 1 is centred at the origin with semi-axes a and b.
    found = conic_parametrisation(ELLIPSE)
    assert (found.x_u, found.y_u) == (a * sympy.cos(found.u), b * sympy.sin(found.u))
    assert found.closed


def test_circle_curvature_is_one_over_R_everywhere():
    # F = x² + y² − R²: F_x = 2x, F_y = 2y, F_xx = F_yy = 2, F_xy = 0, so
    # κ = (4y²·2 + 4x²·2)/(4x² + 4y²)^(3/2) = 8R²/(8R³) = 1/R on the circle.
    implicit = kappa(ImplicitPath(x**2 + y**2 - R**2, x, y))
    on_circle = implicit.subs({x: R * sympy.cos(u), y: R * sympy.sin(u)})
    assert sympy.simplify(on_circle - 1 / R) == 0
    # (R cos u, R sin u): x'y'' − y'x'' = R², x'² + y'² = R², κ = R²/R³ = 1/R
    assert kappa(ParametricPath(R * sympy.cos(u), R * sympy.sin(u), u)) == 1 / R
    found = acceleration_extremes(ImplicitPath(x**2 + y**2 - R**2, x, y), v)
    # constant speed on a circle: a = a_n = v²/R at every point
    assert found.constant
    assert found.maximum.a == v**2 / R == found.minimum.a


def test_parabola_radius_of_curvature_at_the_vertex():
    # y = x²/(2c): y' = x/c, y'' = 1/c; at x = 0, κ = (1/c)/(1 + 0)^(3/2) = 1/c, ρ = c.
    parabola = ExplicitPath(x**2 / (2 * c), x)
    assert rho(parabola).subs(x, 0) == c
    assert kappa(parabola).subs(x, 0) == 1 / c
    # κ = (1/c)/(1 + x²/c²)^(3/2) falls from 1/c at the vertex to 0 as x → ±oo
    found = acceleration_extremes(parabola, v, order_by={c: 1})
    assert found.maximum.a == v**2 / c and found.maximum.points == ((0, 0),)
    assert found.minimum.a == 0 and found.minimum.rho == sympy.oo
    assert set(found.minimum.points) == {(-sympy.oo, sympy.oo), (sympy.oo, sympy.oo)}
    # the same parabola written as F = y − x²/(2c) = 0 gives the same answer
    implicit = acceleration_extremes(ImplicitPath(y - x**2 / (2 * c), x, y), v, {c: 1})
    assert implicit.maximum.a == v**2 / c


def test_sine_arch_on_a_closed_interval():
    # y = sin x on [0, π]: κ = |sin x|/(1 + cos²x)^(3/2): κ = 1/1 = 1 at x = π/2,
    # κ = 0 at both ends (sin 0 = sin π = 0).
    found = acceleration_extremes(ExplicitPath(sympy.sin(x), x, (sympy.Integer(0), sympy.pi)), v)
    assert found.maximum.kappa == 1 and found.maximum.points == ((sympy.pi / 2, 1),)
    assert found.minimum.kappa == 0 and set(found.minimum.points) == {(0, 0), (sympy.pi, 0)}


def test_rotated_ellipse_by_lagrange_multipliers():
    # x² − xy + y² = 1; with ξ = (x + y)/√2, η = (x − y)/√2: xy = (ξ² − η²)/2, so
    # ξ²/2 + 3η²/2 = 1: semi-axes √2 along ξ (the line y = x) and √(2/3) along η.
    # κ_max = a/b² = √2/(2/3) = 3/√2 = 2.1213 at ξ = ±√2, η = 0: (x, y) = ±(1, 1);
    # κ_min = b/a² = √(2/3)/2 = 1/√6 = 0.40825 at ξ = 0, η = ±√(2/3): ±(1/√3, −1/√3).
    found = acceleration_extremes(ImplicitPath(x**2 - x * y + y**2 - 1, x, y), v)
    assert float(found.maximum.kappa) == pytest.approx(2.1213203)
    assert points(found.maximum) == {(1.0, 1.0), (-1.0, -1.0)}
    assert float(found.minimum.kappa) == pytest.approx(0.4082483)
    s = 1 / math.sqrt(3)  # 0.57735
    flat = [coordinate for point in sorted(points(found.minimum)) for coordinate in point]
    assert flat == pytest.approx([-s, s, s, -s])


def test_hyperbola_vertex_and_the_ends_at_infinity():
    # x²/a² − y²/b² = 1, branch (a cosh u, b sinh u): at u = 0, x' = 0, y' = b, x'' = a,
    # y'' = 0: |x'y'' − y'x''| = ab, (x'² + y'²)^(3/2) = b³, κ = a/b² at (±a, 0);
    # far out the branches straighten along their asymptotes: κ → 0.
    found = acceleration_extremes(
        ImplicitPath(x**2 / a**2 - y**2 / b**2 - 1, x, y), v, {a: 3, b: 2}
    )
    assert sympy.simplify(found.maximum.a - v**2 * a / b**2) == 0
    assert set(found.maximum.points) == {(a, 0), (-a, 0)}
    assert found.minimum.a == 0


# the upper half of x²/a² + y²/b² = 1 in the three forms, as plain float functions
EXPLICIT = sympy.lambdify((a, b, x), kappa(ExplicitPath(b * sympy.sqrt(1 - x**2 / a**2), x)))
IMPLICIT = sympy.lambdify((a, b, x, y), kappa(ELLIPSE))
PARAMETRIC = sympy.lambdify((a, b, u), kappa(ParametricPath(a * sympy.cos(u), b * sympy.sin(u), u)))


@given(
    st.floats(min_value=1, max_value=200),
    st.floats(min_value=1, max_value=200),
    st.floats(min_value=0.05, max_value=math.pi - 0.05),
)
def test_explicit_implicit_and_parametric_forms_agree(semi_a, semi_b, angle):
    # κ = ab/(a² sin²u + b² cos²u)^(3/2) at (a cos u, b sin u) (derived above)
    sin, cos = math.sin(angle), math.cos(angle)
    by_hand = semi_a * semi_b / (semi_a**2 * sin**2 + semi_b**2 * cos**2) ** 1.5
    px, py = semi_a * cos, semi_b * sin
    assert EXPLICIT(semi_a, semi_b, px) == pytest.approx(by_hand, rel=1e-7)
    assert IMPLICIT(semi_a, semi_b, px, py) == pytest.approx(by_hand, rel=1e-7)
    assert PARAMETRIC(semi_a, semi_b, angle) == pytest.approx(by_hand, rel=1e-7)


def test_polar_components_by_hand():
    # r = 2t, θ = t²: ṙ = 2, r̈ = 0, θ̇ = 2t, θ̈ = 2. At t = 1 s: r = 2 m, θ̇ = 2 rad/s:
    # v_r = ṙ = 2 m/s, v_θ = rθ̇ = 2·2 = 4 m/s,
    # a_r = r̈ − rθ̇² = 0 − 2·2² = −8 m/s², a_θ = rθ̈ + 2ṙθ̇ = 2·2 + 2·2·2 = 12 m/s².
    found = polar_components(2 * t, t**2, t)
    at_1 = {t: 1}
    assert found.v_r.subs(at_1) == 2
    assert found.v_theta.subs(at_1) == 4
    assert found.a_r.subs(at_1) == -8
    assert found.a_theta.subs(at_1) == 12


def test_normal_and_tangential_with_a_tangential_acceleration():
    # At the end of the ellipse's major axis ρ = b²/a = 100²/150 = 200/3 m; v = 20 m/s:
    # a_n = 400/(200/3) = 6 m/s²; with a_t = 8 m/s², |a| = √(8² + 6²) = √100 = 10 m/s².
    found = nt_acceleration(sympy.Integer(20), sympy.Rational(200, 3), sympy.Integer(8))
    assert (found.a_t, found.a_n, found.a) == (8, 6, 10)
    # constant speed: a_t = 0 and |a| = a_n
    steady = nt_acceleration(v, R)
    assert steady.a_t == 0 and steady.a == v**2 / R == steady.a_n


def test_projectile_on_level_ground():
    # v0 = 20 m/s at 30°: v_x = 20 cos 30° = 17.3205 m/s, v_y = 20 sin 30° = 10 m/s.
    # y = 10 t − 4.905 t² = 0 ⇒ t = 10/4.905 = 2.03874 s;
    # range = 17.3205 · 2.03874 = 35.3119 m; apex at t = 10/9.81 = 1.01937 s,
    # h_max = v_y²/(2g) = 100/19.62 = 5.09684 m.
    found = projectile(sympy.Integer(20), sympy.pi / 6, sympy.Float(9.81))
    assert float(found.t_flight) == pytest.approx(2.03874, rel=1e-5)
    assert float(found.x_range) == pytest.approx(35.3119, rel=1e-5)
    assert float(found.h_max) == pytest.approx(5.09684, rel=1e-5)
    assert float(found.t_apex) == pytest.approx(1.01937, rel=1e-5)
    assert float(found.y_land) == 0


def test_projectile_landing_below_and_at_a_distance():
    # Landing 10 m below: 10 t − 4.905 t² = −10 ⇒ 4.905 t² − 10 t − 10 = 0,
    # t = (10 + √(100 + 196.2))/9.81 = (10 + 17.21046)/9.81 = 2.77375 s (the later root;
    # the other is negative); x = 17.3205 · 2.77375 = 48.0427 m.
    below = projectile(sympy.Integer(20), sympy.pi / 6, sympy.Float(9.81), landing_height=-10)
    assert float(below.t_flight) == pytest.approx(2.77375, rel=1e-5)
    assert float(below.x_range) == pytest.approx(48.0427, rel=1e-5)
    # A wall 30 m away: t = 30/17.3205 = 1.73205 s, y = 10·1.73205 − 4.905·3 = 2.6055 m.
    wall = projectile(sympy.Integer(20), sympy.pi / 6, sympy.Float(9.81), distance=30)
    assert float(wall.t_flight) == pytest.approx(1.73205, rel=1e-5)
    assert float(wall.y_land) == pytest.approx(2.6055, rel=1e-4)
    # 10 m up is above the apex (5.097 m): never reached
    with pytest.raises(ValueError, match="never reaches"):
        projectile(sympy.Integer(20), sympy.pi / 6, sympy.Float(9.81), landing_height=10)
