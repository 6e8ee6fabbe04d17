"""A point moving along a path at constant speed (scene mode: `path`, `moves`, `assume`)."""

import math
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dynsolve.errors import DimensionError, SpecError
from dynsolve.pipeline import solve_file

PATH = """\
given:
  v = 12 m/s
  c = 8 m
  R = 30 m
scene:
  path P: {path}
  moves car: along P, speed v
find: a_max = a_max(car), a_min = a_min(car)
"""


def solve(tmp_path: Path, path: str, **replace: str):
    text = PATH.format(path=path)
    for old, new in replace.items():
        text = text.replace(old, new)
    file = tmp_path / "path.dyn"
    file.write_text(text)
    return solve_file(file)


def test_a_parabola_bends_most_at_its_vertex(tmp_path):
    # y = x²/(2c): y' = x/c, y'' = 1/c, κ = (1/c)/(1 + x²/c²)^(3/2): largest 1/c at x = 0,
    # tending to 0 far out. a_max = v²/c = 144/8 = 18 m/s², a_min = 0 (at infinity)
    solution = solve(tmp_path, "y = x^2/(2*c)")
    a_max, a_min = solution.answers
    assert a_max.value == pytest.approx(18.0, rel=1e-12)
    assert a_min.value == pytest.approx(0.0, abs=1e-12)
    note = next(c.detail for c in solution.checks if c.name == "car along P")
    assert "at (0, 0)" in note


def test_a_circle_has_the_same_acceleration_everywhere(tmp_path):
    # κ = 1/R: a = v²/R = 144/30 = 4.8 m/s² at every point
    solution = solve(tmp_path, "x^2 + y^2 = R^2")
    assert [a.value for a in solution.answers] == pytest.approx([4.8, 4.8], rel=1e-12)


def test_the_ellipse_in_either_orientation(tmp_path):
    # x²/R² + y²/c² = 1 with R = 30 > c = 8: κ = R/c² at x = ±R, c/R² at y = ±c
    solution = solve(tmp_path, "x^2/R^2 + y^2/c^2 = 1")
    a_max, a_min = solution.answers
    assert a_max.value == pytest.approx(144 * 30 / 64, rel=1e-12)
    assert a_min.value == pytest.approx(144 * 8 / 900, rel=1e-12)
    # swapped axes, same curve turned 90°: the same extremes
    turned = solve(tmp_path, "x^2/c^2 + y^2/R^2 = 1")
    assert [a.value for a in turned.answers] == pytest.approx([a_max.value, a_min.value])


def test_symbolic_extremes_need_an_assumption_when_the_order_depends_on_the_givens(tmp_path):
    text = PATH.format(path="x^2/R^2 + y^2/c^2 = 1")
    text = (
        text.replace("v = 12 m/s", "v: m/s").replace("c = 8 m", "c: m").replace("R = 30 m", "R: m")
    )
    file = tmp_path / "path.dyn"
    file.write_text(text)
    with pytest.raises(SpecError) as caught:
        solve_file(file)
    assert "depends on the givens" in caught.value.message
    assert "assume" in caught.value.hint
    assert caught.value.position.line == 8  # the find line that asks for a_max
    file.write_text(text.replace("  moves car", "  assume R > c\n  moves car"))
    solution = solve_file(file)
    # κ = R/c² at x = ±R is the larger when R > c: a_max = v² R/c²
    assert solution.answers[0].formula.replace(" ", "") in ("R*v**2/c**2", "R*v^2/c^2")


@pytest.mark.parametrize(
    ("path", "replace", "error", "message"),
    [
        # a length added to an area
        ("x^2 + y = R^2", {}, DimensionError, "cannot be added"),
        ("x^2 + y^2 > R^2", {}, SpecError, "a path is an equation"),
        ("x^2 + y^2 = R^2", {"along P": "along Q"}, SpecError, "there is no path 'Q'"),
        ("x^2 + y^2 = r^2", {}, SpecError, "'r' in the scene is not a given"),
        ("x^2 + y^2 = R^2", {"speed v": "speed c"}, DimensionError, "must be a velocity"),
    ],
)
def test_bad_paths_are_reported_at_their_line(tmp_path, path, replace, error, message):
    with pytest.raises(error) as caught:
        solve(tmp_path, path, **replace)
    assert message in caught.value.message
    assert caught.value.position.line in (6, 7)


def test_the_curvature_formula_holds_at_the_vertex_of_a_steep_parabola(tmp_path):
    # y = x²/(2c) with c = 0.5 m: ρ = c = 0.5 m at the vertex, a = v²/ρ = 288 m/s²
    solution = solve(tmp_path, "y = x^2/(2*c)", **{"c = 8 m": "c = 0.5 m"})
    assert solution.answers[0].value == pytest.approx(144 / 0.5, rel=1e-12)
    assert math.isfinite(solution.answers[1].value)


HUMP = """\
given:
  m = 1200 kg
  v = 15 m/s
  c = 50 m
  x_1 = {x_1}
scene:
  path road: y = -x^2/(2*c)
  body car: particle, mass m, at (x_1, -x_1^2/(2*c))
  moves car: along road, speed v
  gravity
find: N = N_road [N], a = a_G(car) [m/s^2]
"""


@pytest.mark.parametrize("x_1", [0.0, 20.0])
def test_a_car_over_a_hump_in_normal_and_tangential_components(tmp_path, x_1):
    # y = −x²/(2c): slope y' = −x/c, κ = (1/c)/(1 + y'²)^(3/2), the centre of curvature below.
    # ΣF_n = m v² κ: m g cos θ − N = m v² κ, cos θ = 1/sqrt(1 + y'²);
    # ΣF_t = m a_t: a_t = g sin θ (downhill), sin θ = |y'|/sqrt(1 + y'²).
    # At the top (x = 0): N = 1200(9.81 − 225/50) = 6372 N, a = 4.5 m/s² down.
    # At x = 20 m: y' = −0.4, N = 1200(9.81/√1.16 − 225(0.02)/1.16^1.5) = 6607.8 N.
    file = tmp_path / "hump.dyn"
    file.write_text(HUMP.format(x_1=f"{x_1} m"))
    solution = solve_file(file)
    slope = -x_1 / 50
    root = math.sqrt(1 + slope**2)
    a_n = 15**2 * (1 / 50) / root**3
    a_t = 9.81 * abs(slope) / root
    N, a = solution.answers
    assert N.value == pytest.approx(1200 * (9.81 / root - a_n), rel=1e-12)
    assert N.direction == "up" or x_1 != 0
    assert a.value == pytest.approx(math.hypot(a_n, a_t), rel=1e-12)
    notes = [e.note for e in solution.equations]
    if x_1 == 0:  # level at the top: x–y, with y along n
        assert any("on the curved path road" in note for note in notes)
    else:  # on the slope: the textbook's n–t axes, two equations in a_t and N
        assert notes == [
            "ΣF_t = m a_t (car)",
            "ΣF_n = m a_n, a_n = v²/ρ toward the centre of curvature (car)",
        ]


def test_a_body_on_a_path_must_be_on_it(tmp_path):
    file = tmp_path / "hump.dyn"
    file.write_text(HUMP.format(x_1="20 m").replace("at (x_1, -x_1^2/(2*c))", "at (x_1, 0)"))
    with pytest.raises(SpecError, match="not on the path road"):
        solve_file(file)


@settings(
    max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(
    x_1=st.floats(min_value=-40, max_value=40).filter(lambda x: abs(x) > 0.5),
    v=st.floats(min_value=1, max_value=25),
)
def test_n_t_axes_on_the_hump_agree_with_the_closed_form(tmp_path, x_1, v):
    # the hump y = −x²/(2c) on its n–t axes, anywhere on the slope, either side of the top:
    # a_t = g sin β, N = m (g cos β − v²/ρ), tan β = |x|/c, 1/ρ = (1/c) cos³ β (by hand)
    file = tmp_path / "hump.dyn"
    file.write_text(HUMP.format(x_1=f"{x_1!r} m").replace("v = 15 m/s", f"v = {v!r} m/s"))
    solution = solve_file(file)
    beta = math.atan(abs(x_1) / 50)
    N, a = solution.answers
    a_n = v**2 * math.cos(beta) ** 3 / 50
    assert N.value == pytest.approx(abs(1200 * (9.81 * math.cos(beta) - a_n)), rel=1e-9)
    assert a.value == pytest.approx(math.hypot(9.81 * math.sin(beta), a_n), rel=1e-9)
    assert solution.equations[1].note.startswith("ΣF_n = m a_n")


CONSTANT = (Path(__file__).parent.parent / "problems" / "scenes" / "path_hump_nt.dyn").read_text()


def test_a_car_at_constant_speed_is_held_to_it_by_a_force_along_the_road(tmp_path):
    # newcomer report: 'moves … speed v' was solved as a coasting car (a_t = g sin β) where the
    # statement says constant speed. With ', constant': a_t = 0, F = −m g sin β along t,
    # N = m (g cos β − v²/ρ), a = a_n = v²/ρ (hand derivation in path_hump_nt.dyn)
    file = tmp_path / "hump.dyn"
    file.write_text(CONSTANT)
    N, F, a = solve_file(file).answers
    beta = math.atan(0.4)
    a_n = 15**2 * math.cos(beta) ** 3 / 50
    assert N.value == pytest.approx(1200 * (9.81 * math.cos(beta) - a_n), rel=1e-12)
    assert F.value == pytest.approx(1200 * 9.81 * math.sin(beta), rel=1e-12)
    assert a.value == pytest.approx(a_n, rel=1e-12)


def test_a_car_too_fast_over_the_hump_is_told_the_road_would_have_to_pull_it(tmp_path):
    # newcomer report: at 30 m/s, N = m (g cos β − v²/ρ) = 1200 (9.108 − 14.41) = −6359 N (by
    # hand): the two-sided path holds the car down, which no road can; said, not silent
    file = tmp_path / "hump.dyn"
    file.write_text(CONSTANT.replace("v   = 15 m/s", "v   = 30 m/s").split("answers:")[0])
    solution = solve_file(file)
    (held,) = [a for a in solution.assumptions if "holds car down" in a.name]
    assert "a road or surface under it cannot" in held.detail and "-6359 N" in held.detail
    slow = tmp_path / "slow.dyn"
    slow.write_text(CONSTANT.split("answers:")[0])
    assert not [a for a in solve_file(slow).assumptions if "holds" in a.name]


def test_a_path_with_a_bare_coefficient_is_told_to_give_it_a_unit(tmp_path):
    # newcomer report: 'y = 0.0025*x^2' was refused with "a missing moment arm (length)?"
    file = tmp_path / "dip.dyn"
    file.write_text(HUMP.format(x_1="20 m").replace("y = -x^2/(2*c)", "y = 0.0025*x^2"))
    with pytest.raises(DimensionError) as error:
        solve_file(file)
    assert "a path's coefficients carry units" in error.value.hint
    assert "k = 0.0025 1/m" in error.value.hint


def test_the_newcomers_car_through_a_dip_at_constant_speed():
    # newcomer report (hand derivation in problems/scenes/path_dip_constant_speed.dyn):
    # N = m (g cos β + v²/ρ) = 17 453.7 N, F = m g sin β = 2182.8 N, a = v²/ρ = 1.93435 m/s²;
    # coasting it had a = 2.42 m/s² with every check green
    path = Path(__file__).parent.parent / "problems" / "scenes" / "path_dip_constant_speed.dyn"
    N, F, a = solve_file(path).answers
    beta = math.atan(0.15)
    a_n = 400 * math.cos(beta) ** 3 / 200
    assert N.value == pytest.approx(1500 * (9.81 * math.cos(beta) + a_n), rel=1e-12)
    assert F.value == pytest.approx(1500 * 9.81 * math.sin(beta), rel=1e-12)
    assert a.value == pytest.approx(a_n, rel=1e-12)


def test_the_radius_of_curvature_is_shown_before_a_n(tmp_path):
    # the textbook computes ρ = [1 + (dy/dx)²]^(3/2) / |d²y/dx²| first (Hibbeler 13.5), then
    # a_n = v²/ρ: for y = −x²/(2c) at x_1 = 20 m, c = 50 m, ρ = c (1 + (x_1/c)²)^(3/2)
    # = 50 · 1.16^1.5 = 62.47 m and a_n = 15²/62.47 = 3.602 m/s² (hand)
    file = tmp_path / "hump.dyn"
    file.write_text(CONSTANT)
    solution = solve_file(file)
    rows = {row.name: row for row in solution.givens}
    assert "rho" in rows and "a_n" in rows
    names = [row.name for row in solution.givens]
    assert names.index("rho") < names.index("a_n")
    assert rows["rho"].base.startswith("62.47 m")
    assert rows["a_n"].written.startswith("= v^2/ρ = 15^2/62.47")
    assert math.isclose(50 * (1 + 0.4**2) ** 1.5, 62.47, abs_tol=5e-3)
