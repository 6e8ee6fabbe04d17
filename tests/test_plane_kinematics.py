"""Plane (curvilinear) motion in a kinematics section: x–y and r–θ components (Hibbeler ch. 12).

Expected numbers come from the hand derivations in the comments, never from dynsolve's
own output.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import sympy
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import DimensionError, SpecError
from dynsolve.modes.kinematics_mode import build_kinematics_problem
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.principles.curvilinear import path_components
from dynsolve.principles.rectilinear import T, crossing_times, extreme_time
from dynsolve.spec.parser import parse_file

ROOT = Path(__file__).resolve().parent.parent
PROJECTILE_FILE = ROOT / "problems" / "kinematics" / "projectile.dyn"
FT = 0.3048  # m per ft, exactly


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "plane.dyn"
    path.write_text(text)
    return path


def answers(tmp_path: Path, text: str) -> dict[str, float | None]:
    solution = solve_file(write(tmp_path, text))
    assert solution.mode == "kinematics"
    return {a.name: a.value for a in solution.answers}


# ---- a projectile: v_0 = 20 m/s at 30° on level ground, g = 9.81 m/s²
PROJECTILE = """\
units: {units}
given:
  v_0 = {v_0}
  theta_0 = 30 deg
  g = {g}
  y_1 = {y_1}
kinematics:
  v_x0 = v_0*cos(theta_0)
  v_y0 = v_0*sin(theta_0)
  a_x = 0
  a_y = -g
find: t_f = t_at(y, y_0), R = x(t_f), h = max(y), v_f = v(t_f), t_1 = t_at(y, y_1)
"""
# By hand: v_x0 = 20 cos 30° = 17.3205 m/s, v_y0 = 20 sin 30° = 10 m/s.
# y = v_y0 t - g t²/2 = 0 at t = 0 and t = 2 v_y0/g: the later root is the landing.
T_FLIGHT = 2 * 20 * 0.5 / 9.81  # 2.03874 s
RANGE = 20 * math.cos(math.radians(30)) * T_FLIGHT  # 17.3205 × 2.03874 = 35.3119 m
H_MAX = 10**2 / (2 * 9.81)  # v_y0²/(2g) = 5.09684 m
# y = 3 m on the way up and down: 4.905 t² - 10 t + 3 = 0,
# t = (10 ± √(100 - 4·4.905·3))/9.81 = (10 ± √41.14)/9.81; the later: 16.41405/9.81
T_AT_3M = (10 + math.sqrt(100 - 2 * 9.81 * 3)) / 9.81  # 1.67320 s


def test_projectile_in_si(tmp_path):
    text = PROJECTILE.format(units="SI", v_0="20 m/s", g="9.81 m/s^2", y_1="3 m")
    got = answers(tmp_path, text)
    assert got["t_f"] == pytest.approx(T_FLIGHT, rel=1e-12)  # 2.0387 s
    assert got["R"] == pytest.approx(RANGE, rel=1e-12)  # 35.31 m
    assert got["h"] == pytest.approx(H_MAX, rel=1e-12)  # 5.097 m
    assert got["v_f"] == pytest.approx(20.0, rel=1e-12)  # level ground: lands at launch speed
    assert got["t_1"] == pytest.approx(T_AT_3M, rel=1e-12)  # the later of the two roots


def test_projectile_in_fps_gives_the_same_answers_converted(tmp_path):
    # 20 m/s = 20/0.3048 ft/s; 9.81 m/s² = 9.81/0.3048 ft/s²; 3 m = 3/0.3048 ft.
    # Times do not change; lengths come out in ft: R = 35.3119/0.3048 = 115.853 ft,
    # h = 5.09684/0.3048 = 16.7219 ft; speed 20/0.3048 = 65.6168 ft/s.
    text = PROJECTILE.format(
        units="FPS", v_0=f"{20 / FT!r} ft/s", g=f"{9.81 / FT!r} ft/s^2", y_1=f"{3 / FT!r} ft"
    )
    solution = solve_file(write(tmp_path, text))
    got = {a.name: a for a in solution.answers}
    assert got["t_f"].value == pytest.approx(T_FLIGHT, rel=1e-9) and got["t_f"].unit == "s"
    assert got["R"].value == pytest.approx(RANGE / FT, rel=1e-9) and got["R"].unit == "ft"
    assert got["h"].value == pytest.approx(H_MAX / FT, rel=1e-9)
    assert got["v_f"].value == pytest.approx(20 / FT, rel=1e-9) and got["v_f"].unit == "ft/s"
    assert got["t_1"].value == pytest.approx(T_AT_3M, rel=1e-9)


def test_projectile_derivation_states_its_rules(tmp_path):
    text = PROJECTILE.format(units="SI", v_0="20 m/s", g="9.81 m/s^2", y_1="3 m")
    solution = solve_file(write(tmp_path, text))
    notes = [s.note for s in solution.steps]
    assert "v_y = v_y0 + ∫ a_y dt" in notes and "y = y₀ + ∫ v_y dt" in notes
    assert "v = √(v_x² + v_y²)" in notes
    landing = next(s for s in solution.steps if s.unknowns == ("t_f",))
    assert "the later root after t₀ is taken" in landing.note
    assert landing.discarded == ("t = 0 s: not after t₀",)  # y = 0 at launch too
    at_3m = next(s for s in solution.steps if s.unknowns == ("t_1",))
    # the earlier root (10 - √41.14)/9.81 = 3.58595/9.81 = 0.36554 s is set aside
    assert at_3m.discarded == ("t = 0.366 s: an earlier root",)
    assert any(c.name == "projectile" for c in solution.checks)


def test_projectile_formulas_are_exact(tmp_path):
    # y(t) = v_0 sin θ_0 t - g t²/2 and t_f = 2 v_0 sin θ_0 / g, in the givens' symbols
    text = PROJECTILE.format(units="SI", v_0="20 m/s", g="9.81 m/s^2", y_1="3 m")
    text = text.replace("find: ", "find: y_t = y(t), ")
    problem = build_kinematics_problem(parse_file(write(tmp_path, text)))
    s = problem.symbols
    exprs = {t.name: t.expr for t in problem.targets}
    v0, th, g = s["v_0"], s["theta_0"], s["g"]
    assert sympy.simplify(exprs["y_t"] - (v0 * sympy.sin(th) * T - g * T**2 / 2)) == 0
    assert sympy.simplify(exprs["t_f"] - 2 * v0 * sympy.sin(th) / g) == 0
    assert sympy.simplify(exprs["h"] - (v0 * sympy.sin(th)) ** 2 / (2 * g)) == 0


def test_symbolic_launch_velocity_keeps_the_formula(tmp_path):
    # v_y0 symbolic (positive): y = v_y0 t - g t²/2 = 0 → t = 2 v_y0/g, decided by the
    # sign of v_y0 without a value; with g = 9.81: t_f = 200 v_y0/981
    text = "given:\n  v_y0: velocity\nkinematics:\n  a_x = 0\n  a_y = -g\n"
    text += "find: t_f = t_at(y, y_0)\n"
    problem = build_kinematics_problem(parse_file(write(tmp_path, text)))
    expr = problem.targets[0].expr.xreplace(dict(problem.system.knowns))
    assert sympy.simplify(expr - sympy.Rational(200, 981) * problem.symbols["v_y0"]) == 0


def test_bundled_projectile_problem_passes():
    solution = solve_file(PROJECTILE_FILE)
    assert solution.passed, [c.detail for c in solution.checks if c.failed]


def test_cli_solves_the_bundled_projectile():
    result = CliRunner().invoke(app, ["solve", str(PROJECTILE_FILE)])
    assert result.exit_code == 0, result.output
    assert "Traceback" not in result.output and "t_f" in result.output


# ---- x = 2t², y = t³ (m) at t = 1 s
CURVE = """\
given:
  c = 2 m/s^2
  k = 1 m/s^3
  t_1 = 1 s
kinematics:
  x = c*t^2
  y = k*t^3
find: {find}
"""


def test_xy_positions_at_a_time(tmp_path):
    # v = (dx/dt, dy/dt) = (4t, 3t²) = (4, 3) → v = 5 m/s; a = (4, 6t²/t…) = (4, 6t) = (4, 6)
    # a_t = (4·4 + 3·6)/5 = 34/5 = 6.8; a_n = |4·6 - 3·4|/5 = 12/5 = 2.4;
    # ρ = v²/a_n = 25/2.4 = 10.4167 m; |a| = √(16 + 36) = √52 = 7.2111 m/s²
    find = (
        "v_x1 = v_x(t_1), v_y1 = v_y(t_1), v_1 = v(t_1), a_x1 = a_x(t_1), a_y1 = a_y(t_1), "
        "a_1 = a(t_1), a_t1 = a_t(t_1), a_n1 = a_n(t_1), rho_1 = rho(t_1), x_1 = x(t_1)"
    )
    got = answers(tmp_path, CURVE.format(find=find))
    expected = {
        "v_x1": 4.0, "v_y1": 3.0, "v_1": 5.0, "a_x1": 4.0, "a_y1": 6.0,
        "a_1": math.sqrt(52), "a_t1": 6.8, "a_n1": 2.4, "rho_1": 25 / 2.4, "x_1": 2.0,
    }  # fmt: skip
    for name, value in expected.items():
        assert got[name] == pytest.approx(value, rel=1e-12), name


def test_xy_relations_in_t(tmp_path):
    # v(t) = √(16t² + 9t⁴) (m/s); at t = 2 s: √(64 + 144) = √208
    problem = build_kinematics_problem(
        parse_file(write(tmp_path, CURVE.format(find="v_t = v(t), y_t = y(t)")))
    )
    knowns = dict(problem.system.knowns)
    v_t, y_t = (t.expr.xreplace(knowns) for t in problem.targets)
    assert float(v_t.subs(T, 2)) == pytest.approx(math.sqrt(208), rel=1e-12)
    assert sympy.simplify(y_t - T**3) == 0


def test_requested_units_and_wrong_units(tmp_path):
    # ρ = 10.4167 m = 10.4167/0.3048 ft = 34.1754 ft
    got = answers(tmp_path, CURVE.format(find="rho_1 = rho(t_1) [ft]"))
    assert got["rho_1"] == pytest.approx(25 / 2.4 / FT, rel=1e-12)
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, CURVE.format(find="rho_1 = rho(t_1) [s]")))
    assert "length" in caught.value.message


def test_tangential_component_is_undefined_at_rest(tmp_path):
    # at t = 0 the particle is at rest (v = (0, 0)): the tangent direction is undefined
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, CURVE.format(find="q = a_t(t_0)")))
    assert "speed is zero" in caught.value.message and caught.value.position.line == 8


# ---- r = 2t m, θ = t² rad at t = 1 s
POLAR = """\
given:
  c = 2 m/s
  b = 1 rad/s^2
  t_1 = 1 s
kinematics:
  r = c*t       # r = 2t
  theta = b*t^2  # θ = t²
find: {find}
"""


def test_polar_components_at_a_time(tmp_path):
    # ṙ = 2, r̈ = 0, θ̇ = 2t = 2, θ̈ = 2, r = 2 at t = 1:
    # v_r = ṙ = 2; v_θ = r θ̇ = 4; a_r = r̈ - r θ̇² = 0 - 2·4 = -8; a_θ = r θ̈ + 2 ṙ θ̇ = 4 + 8 = 12
    # v = √(4 + 16) = √20; a = √(64 + 144) = √208;
    # a_t = (2·(-8) + 4·12)/√20 = 32/√20; a_n = |2·12 - 4·(-8)|/√20 = 56/√20; θ = 1 rad
    find = (
        "v_r1 = v_r(t_1), v_th1 = v_theta(t_1), a_r1 = a_r(t_1), a_th1 = a_theta(t_1), "
        "v_1 = v(t_1), a_1 = a(t_1), a_t1 = a_t(t_1), a_n1 = a_n(t_1), th_1 = theta(t_1)"
    )
    got = answers(tmp_path, POLAR.format(find=find))
    expected = {
        "v_r1": 2.0, "v_th1": 4.0, "a_r1": -8.0, "a_th1": 12.0, "v_1": math.sqrt(20),
        "a_1": math.sqrt(208), "a_t1": 32 / math.sqrt(20), "a_n1": 56 / math.sqrt(20),
        "th_1": 1.0,
    }  # fmt: skip
    for name, value in expected.items():
        assert got[name] == pytest.approx(value, rel=1e-12), name


def test_polar_derivation_states_its_rules(tmp_path):
    solution = solve_file(write(tmp_path, POLAR.format(find="a_r1 = a_r(t_1)")))
    notes = [s.note for s in solution.steps]
    assert "a_r = d²r/dt² − r (dθ/dt)²" in notes and "v_θ = r dθ/dt" in notes
    assert [e.dimension.split(" [")[0] for e in solution.equations] == ["length", "dimensionless"]


# ---- the principles
def test_path_components_and_roots():
    # v = (4, 3), a = (4, 6): a_t = 34/5, a_n = 12/5, ρ = 25/(12/5) = 125/12
    found = path_components(4, 3, 4, 6)
    assert (found.a_t, found.a_n, found.rho) == (
        sympy.Rational(34, 5),
        sympy.Rational(12, 5),
        sympy.Rational(125, 12),
    )
    # straight motion: a ∥ v, so a_n = 0 and ρ is infinite
    assert path_components(1, 0, 2, 0).rho == sympy.oo
    # t² - 3t + 2 = 0 at t = 1 and 2; after t₀ = 1.5 only t = 2 remains
    found = crossing_times(T**2 - 3 * T + 2, sympy.Integer(0), sympy.Rational(3, 2))
    assert found.times == (2,) and found.discarded == ((1, "not after t₀"),)
    # y = t³ - 3t: dy/dt = 3t² - 3 = 0 at t = ±1; the minimum after 0 is at t = 1
    assert extreme_time(T**3 - 3 * T, sympy.Integer(0), largest=False).times == (1,)
    with pytest.raises(ValueError, match="no largest value"):
        extreme_time(T**3 - 3 * T, sympy.Integer(0), largest=True)


# ---- malformed specs: positioned errors with hints
BAD = """\
given:
  c = 2 m/s
  w = 3 rad/s
  h = 2 m
  t_1 = 1 s
kinematics:
  {first}
  {second}
find: {find}
"""


@pytest.mark.parametrize(
    ("first", "second", "find", "error", "message", "line", "column", "hint"),
    [
        # r–θ on line 8 after x–y on line 7
        ("x = c*t", "theta = w*t", "q = v(t_1)", SpecError, "mixes x–y", 8, 3, "one set"),
        ("a_y = -g", "", "q = v(t_1)", SpecError, "no partner", 7, 3, "a_x = …"),
        ("r = c*t", "", "q = v(t_1)", SpecError, "no partner", 7, 3, "theta = …"),
        # 'cc' is column 7 of "  x = cc*t"
        ("x = cc*t", "y = c*t", "q = v(t_1)", SpecError, "'cc' is neither", 7, 7, "'c'"),
        ("x = c*t", "a_z = 0", "q = v(t_1)", SpecError, "not a component", 8, 3, "'a_y'"),
        ("x = c*t", "a = 0", "q = v(t_1)", SpecError, "not a component", 8, 3, "a_x = …"),
        ("x = c*t", "a_x = 0", "q = v(t_1)", SpecError, "given twice", 8, 3, "one relation"),
        ("x = c*t", "y = c*x", "q = v(t_1)", SpecError, "'x' is neither", 8, 9, "function of t"),
        ("x = c*t", "y = c", "q = v(t_1)", DimensionError, "length", 8, 3, ""),
        # find items: column 7 is the name after "find: ", column 11 the function
        ("x = c*t", "y = c*t", "q = v_r(t_1)", SpecError, "applies to r–θ", 9, 11, "v_x"),
        ("r = c*t", "theta = w*t", "q = a_x(t_1)", SpecError, "applies to x–y", 9, 11, "v_r"),
        ("x = c*t", "y = c*t", "q = vv(t_1)", SpecError, "not a quantity", 9, 11, "did you"),
        ("x = c*t", "y = c*t", "q = v(t_2)", SpecError, "neither a given", 9, 11, "'t_1'"),
        ("x = c*t", "y = c*t", "q = v(h)", SpecError, "not a time", 9, 11, "a given time"),
        ("x = c*t", "y = c*t", "q = t_at(y, t_1)", SpecError, "time, but y", 9, 11, "length"),
        ("x = c*t", "y = c*t", "v", SpecError, "not a quantity", 9, 7, "v(t_1)"),
        ("x = c*t", "y = c*t", "q = v", SpecError, "takes one argument", 9, 11, "v(t_1)"),
        ("x = c*t", "y = c*t", "q = t(h)", SpecError, "not a quantity", 9, 11, "t_at(y, h)"),
        ("x = c*t", "y = -c*t", "q = t_at(y, h)", SpecError, "never equals", 9, 11, "signs"),
        # "  v_x0 = c*t" on line 9: t is column 12
        ("a_x = 0", "a_y = 0\n  v_x0 = c*t", "q = v(t_1)", SpecError, "depends on t", 9, 12, "t_0"),
    ],
)
def test_bad_plane_specs_get_positioned_errors(
    tmp_path, first, second, find, error, message, line, column, hint
):
    text = BAD.format(first=first, second=second, find=find)
    with pytest.raises(error) as caught:
        solve_file(write(tmp_path, text))
    assert message in caught.value.message, caught.value.message
    position = caught.value.position
    assert position is not None and (position.line, position.column) == (line, column)
    assert hint in (caught.value.hint or ""), caught.value.hint


def test_an_answer_for_a_name_not_found_is_an_error(tmp_path):
    text = CURVE.format(find="v_1 = v(t_1)") + "answers:\n  v_2 = 5 m/s\n"
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, text))
    assert "not in find" in caught.value.message and "'v_1'" in caught.value.hint


def test_a_single_position_relation_is_still_rectilinear(tmp_path):
    # x = c t alone: rectilinear motion as before, v = dx/dt = c = 2 m/s
    text = "given:\n  c = 2 m/s\n  t_1 = 1 s\nkinematics:\n  x = c*t\nfind: v_1 = v(t_1)\n"
    problem = build_kinematics_problem(parse_file(write(tmp_path, text)))
    assert problem.motion.given == "x(t)"
    assert answers(tmp_path, text)["v_1"] == pytest.approx(2.0)


ROD = """\
given:
  m = 0.5 kg
  c = 2 m/s
  b = 1 rad/s^2
  t_1 = 1 s
kinematics:
  r = c*t
  theta = b*t^2
find: {find}
"""


def test_the_resultant_force_in_polar_components(tmp_path):
    # a collar on a rod: r = 2t, θ = t²; at t = 1 s a_r = −8, a_θ = 12 (hand derivation in
    # test_polar_components_at_a_time); ΣF = m a with m = 0.5 kg:
    # F_r = −4 N (toward O), F_θ = 6 N, |F| = 0.5 √208 = 7.2111 N
    find = "F_r1 = F_r(t_1) [N], F_th1 = F_theta(t_1) [N], F_1 = F(t_1) [N]"
    got = answers(tmp_path, ROD.format(find=find))
    assert got["F_r1"] == pytest.approx(-4.0, rel=1e-12)
    assert got["F_th1"] == pytest.approx(6.0, rel=1e-12)
    assert got["F_1"] == pytest.approx(0.5 * math.sqrt(208), rel=1e-12)


def test_a_force_needs_the_mass(tmp_path):
    text = ROD.format(find="F_1 = F(t_1)").replace("  m = 0.5 kg\n", "")
    path = tmp_path / "rod.dyn"
    path.write_text(text)
    with pytest.raises(SpecError, match="needs the particle's mass"):
        solve_file(path)


def test_time_at_a_literal_zero_as_in_one_line_motion() -> None:
    # a ball thrown from a 20 m cliff at 15 m/s, 40° up (newcomer round: t_at(y, 0) was
    # refused); 0 = 20 + 9.641814 t − 4.905 t²: t = (9.641814 + √(9.641814² + 2·9.81·20))/9.81
    text = """given:
  v_0 = 15 m/s
  theta_0 = 40 deg
  y_0 = 20 m
  g = 9.81 m/s^2
kinematics:
  v_x0 = v_0*cos(theta_0)
  v_y0 = v_0*sin(theta_0)
  a_x = 0
  a_y = -g
find: t_f = t_at(y, 0)
"""
    v_y0 = 15 * math.sin(math.radians(40))
    expected = (v_y0 + math.sqrt(v_y0**2 + 2 * 9.81 * 20)) / 9.81
    (t_f,) = [float(a.value) for a in solve_text(text).answers]
    assert t_f == pytest.approx(expected, rel=1e-9)


def test_no_highest_point_after_the_start_gets_a_hint_that_fits() -> None:
    # a ball thrown 10° below the horizontal: dy/dt < 0 from the start, so max(y) has no
    # stationary point; the hint said "give values to the givens", which all had values
    text = """given:
  v_0 = 15 m/s
  theta_0 = -10 deg
  y_0 = 20 m
kinematics:
  v_x0 = v_0*cos(theta_0)
  v_y0 = v_0*sin(theta_0)
  a_x = 0
  a_y = -g
find: h = max(y)
"""
    with pytest.raises(SpecError) as info:
        solve_text(text)
    assert "no largest value after" in info.value.message
    assert "give values" not in info.value.hint and "y(t_0)" in info.value.hint
