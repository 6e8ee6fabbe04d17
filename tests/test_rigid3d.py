"""Rigid bodies in 3D scenes (issue 11, part 2): a body turning about a fixed axis on its
bearings, ΣF = m a_G and ΣM_G = Ḣ_G = I_G α + ω × H_G with I_G rotated into the scene.

Expected numbers: the seed notes' hand derivations (kept in the equation-mode versions
under problems/equations/, solved here side by side) and hand derivations below.
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

PROBLEMS = Path(__file__).parent.parent / "problems"


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


@pytest.mark.parametrize("example", ["3d_seed_tilted_gear", "3d_seed_plate_diagonal"])
def test_scene_and_equation_mode_agree(example):
    scene = solve_file(PROBLEMS / "seed" / f"{example}.dyn")
    equations = solve_file(PROBLEMS / "equations" / f"{example}.dyn")
    assert scene.mode == "3D scene" and scene.passed
    assert equations.mode == "equations" and equations.passed
    by_name = answers(equations)
    for answer in scene.answers:
        other = by_name[answer.name]
        assert answer.value == pytest.approx(other.value, rel=1e-9, abs=1e-9), answer.name
    assert any(c.name.startswith("second moment point") and c.passed for c in scene.checks)


ECCENTRIC = """\
given:
  m = 4 kg
  r = 0.1 m
  e = 2 mm
  L = 0.15 m
  w = 100 rad/s
  a = {alpha}
scene:
  body disk: mass m, disk r, at (0, e, 0)
  axis disk: (1, 0, 0)
  rotates disk: about (1, 0, 0), through (0, 0, 0), omega w, alpha a
  bearing A: at (-L, 0, 0), thrust
  bearing B: at (L, 0, 0), journal
{extra}
find: {find}
"""


def test_eccentric_disk_loads_each_bearing_with_half_the_rotating_force():
    """G a distance e off the shaft (at +y): a_G = ω × (ω × r) = −ω² e ŷ; the disk's axis
    is the shaft, so ω × H_G = 0 and Ḣ_G = 0. By hand: ΣF_y: A_y + B_y = −m e ω²;
    ΣM_G,z: L (B_y − A_y) + e A_x = 0 with A_x = 0 (ΣF_x), so each bearing pulls the
    shaft with m e ω²/2 toward −y (the rotating unbalance load)."""
    text = ECCENTRIC.format(alpha="0 rad/s^2", extra="", find="A_y, B_y, A_x")
    found = answers(solve_text(text, "eccentric.dyn"))
    expected = -4 * 0.002 * 100**2 / 2
    assert found["A_y"].value == pytest.approx(expected, rel=1e-12)
    assert found["B_y"].value == pytest.approx(expected, rel=1e-12)
    assert found["A_x"].value == pytest.approx(0, abs=1e-12)


def test_an_angular_acceleration_needs_a_driving_torque():
    text = ECCENTRIC.format(alpha="5 rad/s^2", extra="", find="A_y")
    with pytest.raises(SpecError) as error:
        solve_text(text, "no_torque.dyn")
    assert "driving torque is missing" in str(error.value)


def test_the_driving_torque_is_the_axial_moment_of_inertia_times_alpha():
    """By hand, moments about the shaft (the x axis through the bearings, where their
    reactions have no moment): M = I_shaft α, with I_shaft = m r²/2 + m e² by the
    parallel-axis theorem."""
    text = ECCENTRIC.format(alpha="5 rad/s^2", extra="  torque M on disk", find="M")
    found = answers(solve_text(text, "torque.dyn"))
    m, r, e = 4.0, 0.1, 0.002
    assert found["M"].value == pytest.approx((m * r**2 / 2 + m * e**2) * 5, rel=1e-12)


def test_a_body_without_symmetry_needs_both_axes():
    text = """\
given:
  M = 6 kg
  a = 0.4 m
  b = 0.2 m
  w = 30 rad/s
scene:
  body plate: mass M, plate a by b, at (0, 0, 0)
  axis plate: (0, 0, 1)
  rotates plate: about (1, 0, 0), through (0, 0, 0), omega w
  bearing C: at (-a, 0, 0), thrust
  bearing D: at (a, 0, 0), journal
find: T = T(plate)
"""
    with pytest.raises(SpecError) as error:
        solve_text(text, "plate.dyn")
    assert "give both of its x and y axes" in str(error.value)


def test_a_three_coordinate_body_in_a_plane_scene_is_refused():
    text = """\
given:
  m = 1 kg
scene:
  body b: particle, mass m, at (0, 0, 0)
  gravity
find: a = a_G(b)
"""
    with pytest.raises(SpecError) as error:
        solve_text(text, "plane.dyn")
    assert "3D scene" in str(error.value)


def test_cli_solves_a_3d_scene():
    result = CliRunner().invoke(app, ["solve", str(PROBLEMS / "seed" / "3d_seed_tilted_gear.dyn")])
    assert result.exit_code == 0, result.output
    assert "3D scene mode" in result.output and "ΣM_G,z" in result.output


def test_the_mode_stays_whole_under_a_long_path(tmp_path):
    # regression (CI): a checkout at a longer path folded "3D scene mode" across two lines
    folder = tmp_path / ("a_rather_long_folder_name_" * 3)
    folder.mkdir()
    spec = folder / "3d_seed_tilted_gear.dyn"
    spec.write_text((PROBLEMS / "seed" / "3d_seed_tilted_gear.dyn").read_text())
    result = CliRunner().invoke(app, ["solve", str(spec)])
    assert result.exit_code == 0, result.output
    assert "units SI · 3D scene mode" in result.output


TILTED = """\
given:
  m = 10 kg
  omega = {omega} rad/s
  L_GA = 0.2 m
  L_GB = 0.25 m
  phi = {phi} deg
  I_z = 0.1 kg*m^2
  I_x = 0.05 kg*m^2
scene:
  body gear: mass m, at (0, 0, 0)
  inertia gear: I_x, I_x, I_z
  axis gear: (cos(phi), -sin(phi), 0)
  rotates gear: about (1, 0, 0), through (0, 0, 0), omega omega
  bearing A: at (-L_GA, 0, 0), thrust
  bearing B: at (L_GB, 0, 0), journal
  gravity
find: A_y, B_y
"""


@settings(max_examples=10, deadline=None)
@given(omega=st.integers(1, 200), phi=st.integers(-80, 80))
def test_tilted_gear_reactions_follow_the_seed_formula(omega, phi):
    """Seed 002 (askew gear): A_y + B_y = m g and L_GB B_y − L_GA A_y = (I_x − I_z)
    sin φ cos φ ω², for any speed and tilt."""
    found = answers(solve_text(TILTED.format(omega=omega, phi=phi), "tilted.dyn"))
    A, B = found["A_y"].value, found["B_y"].value
    assert pytest.approx(10 * 9.81, rel=1e-9) == A + B
    t = math.radians(phi)
    expected = (0.05 - 0.1) * math.sin(t) * math.cos(t) * omega**2
    assert pytest.approx(expected, rel=1e-9, abs=1e-9) == 0.25 * B - 0.2 * A


GYRO = """\
given:
  m = 0.5 kg
  r = 40 mm
  d = 60 mm
  w_s = 300 rad/s
scene:
  body rotor: mass m, disk r, at (d, 0, 0)
  rotates rotor: about (0, 1, 0), through (0, 0, 0), omega {rate}
  spins rotor: about (1, 0, 0), omega w_s
  bearing O: at (0, 0, 0), ball
  gravity
find: {find}
"""


def test_gyroscope_steady_precession():
    """Rotor (thin disk, I_s = m r²/2) spinning at ω_s about x, G at d from the pivot O,
    precessing about y (Hibbeler 21.5): ΣM_O = Ω × H_O gives m g d = Ω I_s ω_s, so
    Ω = m g d/(I_s ω_s) = 2.4525 rad/s; the pivot pulls G round: O_x = −m Ω² d, O_y = m g."""
    solution = solve_text(GYRO.format(rate="Omega", find="Omega, O_x, O_y"), "gyro.dyn")
    assert solution.passed
    found = answers(solution)
    omega = 0.5 * 9.81 * 0.06 / (0.5 * 0.04**2 / 2 * 300)
    assert found["Omega"].value == pytest.approx(omega, rel=1e-12)
    assert found["O_x"].value == pytest.approx(-0.5 * omega**2 * 0.06, rel=1e-12)
    assert found["O_y"].value == pytest.approx(0.5 * 9.81, rel=1e-12)


def test_a_misspelt_rate_is_not_taken_for_an_unknown():
    with pytest.raises(SpecError) as error:
        solve_text(
            GYRO.format(rate="Omega", find="Omega, O_x").replace("omega w_s", "omega w_S"), "t.dyn"
        )
    assert "'w_S' is not a given" in str(error.value) and "w_s" in str(error.value)


SHAFT = """\
given:
  m = 2 kg
  L = 0.8 m
  Omega = {Omega} rad/s
  theta = {theta} deg
  theta_dot = {theta_dot} rad/s
scene:
  body bar: mass m, rod L, at (L/2*sin(theta), -L/2*cos(theta), 0)
  axis bar: (sin(theta), -cos(theta), 0)
  rotates bar: about (0, 1, 0), through (0, 0, 0), omega Omega
  spins bar: about (0, 0, 1), through (0, 0, 0), omega theta_dot, alpha theta_ddot
  bearing B: at (0, 0, 0), pin
  gravity
find: theta_ddot, B_x, B_y, B_z
"""


def test_bar_on_shaft_scene_agrees_with_the_seed_equations():
    # the seed's part (a): θ'' = Ω² sin θ cos θ − (3 g/(2 L)) sin θ = 6.391582 rad/s²,
    # written by hand in problems/seed/3d_seed_bar_shaft.dyn (equation mode)
    scene = answers(solve_file(PROBLEMS / "rigid3d" / "bar_on_shaft.dyn"))
    seed = answers(solve_file(PROBLEMS / "seed" / "3d_seed_bar_shaft.dyn"))
    assert scene["theta_ddot"].value == pytest.approx(seed["theta_ddot"].value, rel=1e-12)
    assert scene["theta_ddot"].value == pytest.approx(6.391582, rel=1e-6)


@settings(max_examples=6, deadline=None)
@given(
    Omega=st.integers(1, 12),
    theta=st.integers(5, 85),
    theta_dot=st.integers(-5, 5),
)
def test_bar_on_shaft_follows_lagrange_and_coriolis(Omega, theta, theta_dot):
    # Lagrange with T = ½ I_B (θ'² + Ω² sin²θ), V = −m g (L/2) cos θ, I_B = m L²/3:
    # θ'' = Ω² sin θ cos θ − (3 g/(2 L)) sin θ whatever θ' is. The pin's force is m a_G − W
    # with a_G from the turning frame: centripetal −Ω² (L/2) sin θ along x, the relative
    # motion θ'' (L/2)(cos, sin) − θ'² (L/2)(sin, −cos), and Coriolis
    # 2 Ω j × θ' (L/2)(cos θ, sin θ, 0) = −Ω θ' L cos θ k.
    solution = solve_text(SHAFT.format(Omega=Omega, theta=theta, theta_dot=theta_dot), "shaft.dyn")
    found = answers(solution)
    m, L, g = 2.0, 0.8, 9.81
    t = math.radians(theta)
    s, c = math.sin(t), math.cos(t)
    alpha = Omega**2 * s * c - 3 * g / (2 * L) * s
    assert found["theta_ddot"].value == pytest.approx(alpha, rel=1e-9, abs=1e-9)
    a_x = -(Omega**2) * L / 2 * s + alpha * L / 2 * c - theta_dot**2 * L / 2 * s
    a_y = alpha * L / 2 * s + theta_dot**2 * L / 2 * c
    a_z = -Omega * theta_dot * L * c
    assert found["B_x"].value == pytest.approx(m * a_x, rel=1e-9, abs=1e-9)
    assert found["B_y"].value == pytest.approx(m * g + m * a_y, rel=1e-9, abs=1e-9)
    assert found["B_z"].value == pytest.approx(m * a_z, rel=1e-9, abs=1e-9)
    assert all(check.passed for check in solution.checks)


def test_a_pin_carries_no_couple_about_its_own_axis():
    # the hinge's couple unknowns are across its axis (z): M_Bx, M_By, never M_Bz
    text = SHAFT.format(Omega=6, theta=30, theta_dot=0).replace(
        "find: theta_ddot, B_x, B_y, B_z", "find: theta_ddot, M_Bz"
    )
    with pytest.raises(SpecError, match="M_Bz"):
        solve_text(text, "shaft.dyn")


SHAFT_IN_TIME = """\
given:
  m = 2 kg
  L = 0.8 m
  Omega = 6 rad/s
  theta = {theta} rad
  w = 0 rad/s
scene:
  body bar: mass m, rod L, at (L/2*sin(theta), -L/2*cos(theta), 0)
  axis bar: (sin(theta), -cos(theta), 0)
  rotates bar: about (0, 1, 0), through (0, 0, 0), omega Omega
  spins bar: about (0, 0, 1), through (0, 0, 0), omega w, alpha theta_ddot
  bearing B: at (0, 0, 0), pin
  gravity
"""
STEADY = math.acos(3 * 9.81 / (2 * 0.8 * 36))  # the seed's part (b): 59.2737°


def shaft_history(theta: float, **options):
    from dynsolve.simulate.run import simulate_spec
    from dynsolve.spec.parser import parse_spec

    return simulate_spec(parse_spec(SHAFT_IN_TIME.format(theta=repr(theta)), "s.dyn"), **options)


def test_the_bar_on_a_shaft_stays_at_its_steady_angle():
    # part (b) of the seed, checked in time: released at cos θ_s = 3 g/(2 L Ω²) it stays
    history = shaft_history(STEADY, t_end=2.0, samples=11)
    assert max(abs(q[0]) for q in history.run.q) < 1e-9


def test_the_bar_oscillates_about_its_steady_angle_at_omega_sin_theta():
    # linearised θ'' = Ω² sin θ cos θ − (3g/2L) sin θ about θ_s: f'(θ_s) = −Ω² sin² θ_s,
    # so small oscillations have ω = Ω sin θ_s (hand derivation): period 1.2182 s
    a = 1e-3
    history = shaft_history(STEADY + a, t_end=2.0, samples=21)
    rate = 6 * math.sin(STEADY)
    for t, q in zip(history.run.t, history.run.q, strict=True):
        assert q[0] == pytest.approx(a * (math.cos(rate * t) - 1), abs=3e-3 * a)


def test_the_jacobi_integral_holds_through_a_large_swing():
    # Ω is held constant by the shaft, so T + V changes; J = T − Ω·H_O + V does not
    history = shaft_history(math.radians(30), t_end=3.0, samples=301)
    assert history.run.drift < 1e-8

    # its far turning point θ_2 has J(θ_2) = J(30°) with θ' = 0 at both (hand, bisection):
    # −½ I_B Ω² sin²θ − m g (L/2) cos θ with I_B = m L²/3
    def J(angle: float) -> float:
        return -0.5 * (2 * 0.64 / 3) * 36 * math.sin(angle) ** 2 - 2 * 9.81 * 0.4 * math.cos(angle)

    low, high = STEADY, math.pi / 2
    for _ in range(60):
        middle = (low + high) / 2
        low, high = (low, middle) if J(middle) > J(math.radians(30)) else (middle, high)
    reach = low - math.radians(30)
    swing = history.run.q[:, 0].max()
    assert reach - 1e-3 < swing <= reach + 1e-9  # sampled every 0.01 s


def test_a_3d_scene_without_a_pinned_turn_is_not_simulated():
    from dynsolve.simulate.run import simulate_spec

    with pytest.raises(SpecError, match="through"):
        simulate_spec(parse_spec_text((PROBLEMS / "rigid3d" / "gyroscope.dyn").read_text()))


def parse_spec_text(text: str):
    from dynsolve.spec.parser import parse_spec

    return parse_spec(text, "g.dyn")


def test_cli_simulates_the_bar_on_a_shaft_to_its_turning_point(tmp_path):
    # released at 30° with θ' = 0 it swings out to θ_2 and stops there (ω = 0): the start,
    # also at ω = 0, is not taken for the event; the drift is of the Jacobi integral
    spec = tmp_path / "shaft.dyn"
    spec.write_text(SHAFT_IN_TIME.format(theta="0.5235987755982988"))
    result = CliRunner().invoke(
        app, ["simulate", str(spec), "--t-end", "2 s", "--until", "omega(bar) = 0 rad/s"]
    )
    assert result.exit_code == 0, result.output
    assert "stopped by 'omega(bar) = 0 rad/s'" in result.output
    assert "|Δ(T − Ω.H_O + V)|" in result.output and "t = 0 s" not in result.output
