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


@pytest.mark.parametrize(
    ("example", "second_method"),
    [
        ("3d_seed_tilted_gear", "second moment point"),
        ("3d_seed_plate_diagonal", "second moment point"),
        ("3d_seed_gear_rolling", "T about the fixed point"),
    ],
)
def test_scene_and_equation_mode_agree(example, second_method):
    scene = solve_file(PROBLEMS / "seed" / f"{example}.dyn")
    equations = solve_file(PROBLEMS / "equations" / f"{example}.dyn")
    assert scene.mode == "3D scene" and scene.passed
    assert equations.mode == "equations" and equations.passed
    by_name = answers(equations)
    for answer in scene.answers:
        other = by_name[answer.name]
        assert answer.value == pytest.approx(other.value, rel=1e-9, abs=1e-9), answer.name
    assert any(c.name.startswith(second_method) and c.passed for c in scene.checks)


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
    assert not any(check.failed for check in solution.checks)


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


@pytest.mark.parametrize("theta", [0.3, 1.1, 2.5])
def test_the_closed_form_of_theta_ddot_is_the_seed_equation(theta):
    """The six equations solved once for θ'' (the simulation's right-hand side) give the
    seed's b3 equation, I_B θ'' = I_B Ω² sin θ cos θ − m g (L/2) sin θ with I_B = m L²/3:
    θ'' = Ω² sin θ cos θ − (3 g/(2 L)) sin θ, for any θ' (the Coriolis terms load the pin
    only); the per-state numeric solve is kept as the fallback and agrees."""
    from dataclasses import replace

    from dynsolve.simulate.spin3d import spin_of
    from dynsolve.spec.parser import parse_spec

    spin = spin_of(parse_spec(SHAFT_IN_TIME.format(theta=repr(theta)), "s.dyn"))
    assert spin.accel is not None
    numeric = replace(spin, accel=None)
    for rate in (0.0, 1.7, -3.2):
        want = 36 * math.sin(theta) * math.cos(theta) - 1.5 * 9.81 / 0.8 * math.sin(theta)
        assert spin.rates(0.0, [0.0, rate])[1] == pytest.approx(want, rel=1e-12, abs=1e-12)
        assert numeric.rates(0.0, [0.0, rate])[1] == pytest.approx(want, rel=1e-12, abs=1e-12)


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


# ---- two states: a gear rolling on a fixed gear (seed 002, problem 9.1) ----

GEAR = """\
given:
  m_A = {m} kg
  R_A = {R_A} m
  R_B = {R_B} m
  M = {M} N*m
  n = {n} rev
scene:
  body A: mass m_A, disk R_A, at (R_B, 0, 0)
  axis A: (1, 0, 0)
  rotates A: about (0, 1, 0), through (0, 0, 0), omega omega_CD
  spins A: about (-1, 0, 0), omega omega_spin
  rolls A at (R_B, {below}R_A, 0)
  torque M on A
  gravity
  travel A: turns n about (0, 1, 0)
find: {find}
"""


def gear(find: str = "omega_CD, omega_spin, T = T(A), U = U(A)", **changes) -> str:
    values = {"m": 4, "R_A": 0.1, "R_B": 0.3, "M": 5, "n": 2, "below": "-"} | changes
    return GEAR.format(find=find, **values)


def test_gear_rolling_on_a_fixed_gear_by_work_and_energy():
    """By hand (problems/rigid3d/gear_rolling.dyn's header; the seed's 9.1 solution):
    rolling at H gives ω_spin R_A = ω_CD R_B; T2 = ½ m v_G² + ½ ωᵀ I_G ω
    = m (3 R_B²/4 + R_A²/8) ω_CD² = 0.275 ω_CD²; ΣU = M (2 rev) = 20π J, so
    ω_CD = √(20π/0.275) = 15.11554 rad/s, ω_spin = 3 ω_CD, T2 = ΣU."""
    solution = solve_file(PROBLEMS / "rigid3d" / "gear_rolling.dyn")
    assert solution.mode == "3D scene" and solution.passed
    found = answers(solution)
    omega_CD = math.sqrt(4 * math.pi * 5 / (4 * (0.1**2 / 8 + 3 * 0.3**2 / 4)))
    assert omega_CD == pytest.approx(15.11554, rel=1e-6)  # the seed list's value
    assert found["omega_CD"].value == pytest.approx(omega_CD, rel=1e-12)
    assert found["omega_spin"].value == pytest.approx(3 * omega_CD, rel=1e-12)
    assert found["T"].value == pytest.approx(20 * math.pi, rel=1e-12)
    assert found["U"].value == pytest.approx(20 * math.pi, rel=1e-12)
    checks = {c.name: c for c in solution.checks}
    # the seed's own form: about the fixed point C, I_xx = m R_A²/2, I_yy = m R_A²/4 + m R_B²
    assert checks["T about the fixed point"].passed
    assert "none: G keeps its height" in checks["work of the weight"].detail
    assert "62.8 J" in checks["work of the couple M"].detail


def test_the_symbolic_gear_scene_gives_the_seed_formula():
    # ω_CD = √(4π M/(m_A (R_A²/8 + 3 R_B²/4))), ω_spin = (R_B/R_A) ω_CD (the seed's 9.10):
    # the scene's key holds them, and the equation-mode spec prints the same formulas
    scene = solve_file(PROBLEMS / "seed" / "3d_seed_gear_rolling-symbolic.dyn")
    equations = solve_file(PROBLEMS / "equations" / "3d_seed_gear_rolling-symbolic.dyn")
    assert scene.passed and equations.passed
    assert {k.name for k in scene.key if k.passed} == {"omega_CD", "omega_spin"}
    by_name = answers(equations)
    for answer in scene.answers:
        assert answer.value is None and answer.formula == by_name[answer.name].formula


@settings(max_examples=8, deadline=None)
@given(
    R_A=st.integers(5, 40),
    R_B=st.integers(10, 90),
    M=st.integers(1, 50),
    n=st.integers(1, 6),
    below=st.booleans(),
)
def test_gear_rates_follow_the_hand_formula(R_A, R_B, M, n, below):
    """Any sizes, torque and turn: ω_CD² = 2π n M/(m (3 R_B²/4 + R_A²/8)). A gear meshing
    above its centre (H = (R_B, +R_A, 0): the fixed gear over it) spins the other way:
    v_H = −ω_CD R_B k − ω_spin R_A k = 0, ω_spin = −(R_B/R_A) ω_CD; T2 is the same."""
    r_A, r_B = R_A / 100, R_B / 100
    text = gear(R_A=r_A, R_B=r_B, M=M, n=n, below="-" if below else "")
    solution = solve_text(text, "gear.dyn")
    assert solution.passed
    found = answers(solution)
    omega = math.sqrt(2 * math.pi * n * M / (4 * (3 * r_B**2 / 4 + r_A**2 / 8)))
    assert found["omega_CD"].value == pytest.approx(omega, rel=1e-9)
    spin = (r_B / r_A) * omega * (1 if below else -1)
    assert found["omega_spin"].value == pytest.approx(spin, rel=1e-9)
    assert found["T"].value == pytest.approx(2 * math.pi * n * M, rel=1e-9)


ARM = """\
given:
  m = 2 kg
  r = 0.1 m
  L = 0.5 m
  q = 90 deg
scene:
  body disk: mass m, disk r, at (L, 0, 0)
  axis disk: (1, 0, 0)
  rotates disk: about {axis}, through (0, 0, 0), omega w
  gravity
  travel disk: turns q about (0, 0, -1)
find: w, U = U(disk)
"""


@pytest.mark.parametrize(("axis", "sign"), [("(0, 0, -1)", 1), ("(0, 0, 1)", -1)])
def test_the_weight_does_work_as_g_falls(axis, sign):
    """A disk on a massless arm of length L from a horizontal axle (z), released from rest
    with the arm horizontal, swings down a quarter turn (about −z: clockwise). By hand:
    U = m g L = 9.81 J; T2 = ½ m L² ω² + ½ (m r²/4) ω² (the disk's axis along the arm,
    so about z it has its diametral moment), ω = √(2 g L/(L² + r²/4)); ω along the
    rotates line's axis, which is −z (ω > 0) or +z (ω < 0: the travel's sense)."""
    found = answers(solve_text(ARM.format(axis=axis), "arm.dyn"))
    assert found["U"].value == pytest.approx(2 * 9.81 * 0.5, rel=1e-12)
    omega = math.sqrt(2 * 9.81 * 0.5 / (0.5**2 + 0.1**2 / 4))
    assert found["w"].value == pytest.approx(sign * omega, rel=1e-12)


def test_the_gear_derivation_lists_work_and_energy_term_by_term():
    """The seed's 9.1 solution, term by term (seed 002, (9.2), (9.5)–(9.7)): T1 = 0 (at
    rest), U_M = M (2 rev) = 20π = 62.8 J; about the fixed point C, I_xx = m R_A²/2 =
    4 (0.1)²/2 = 0.0200 kg·m², I_yy = I_zz = m R_A²/4 + m R_B² = 0.01 + 0.36 = 0.370 kg·m²;
    T2 = ½ I_xx ω_x² + ½ I_yy ω_y² = T1 + ΣU = 62.8 J."""
    solution = solve_file(PROBLEMS / "rigid3d" / "gear_rolling.dyn")
    terms = {t.name: t for t in solution.energy}
    assert list(terms) == ["T1", "U_M", "I_xx", "I_yy", "I_zz", "T2"]
    assert terms["T1"].value == "0 J" and terms["U_M"].value == "62.8 J"
    assert terms["U_M"].formula == "M*n" and "M Δθ" in terms["U_M"].meaning
    assert terms["I_xx"].value == "0.0200 kg·m²"
    assert terms["I_yy"].value == terms["I_zz"].value == "0.370 kg·m²"
    assert terms["T2"].formula == "I_xx*ω_spin^2/2 + I_yy*ω_CD^2/2"
    assert terms["T2"].value == "62.8 J"


def test_the_weight_work_and_t_about_the_axle_are_listed():
    """The swinging arm (above): U_W = m g L = 2 (9.81) 0.5 = 9.81 J; about the axle
    (z, through the fixed point O), I_zz = m r²/4 + m L² = 2 (0.0025 + 0.25) = 0.505 kg·m²,
    and T2 = ½ I_zz ω² (ω only about z)."""
    terms = {t.name: t for t in solve_text(ARM.format(axis="(0, 0, -1)"), "arm.dyn").energy}
    assert terms["U_W"].value == "9.81 J" and "−m g Δy_G" in terms["U_W"].meaning
    assert terms["I_zz"].value == "0.505 kg·m²"
    assert terms["T2"].formula == "I_zz*w^2/2" and terms["T2"].value == "9.81 J"


def test_the_moments_about_the_second_point_are_printed():
    """The moment equations about the second point, as the notes write them: the
    gyroscope's precession is unknown, so its equations are about the pivot O, where the
    reactions drop out, m g d = Ω I_s ω_s with I_s = m r²/2 (Hibbeler 21.5), and the second
    point is G: ΣM_G,z, −O_y d = −I_s ω_s Ω; about bearing C of the plate turning about its
    diagonal, the bearings' couple F √(a² + b²) = M ω² ab(a² − b²)/(12(a² + b²)) (seed 002,
    (9.33)–(9.34))."""
    gyroscope = solve_file(PROBLEMS / "rigid3d" / "gyroscope.dyn")
    about_O = [r for r in gyroscope.equations if r.text == "-d*g*m = -m*r^2*w_s*Ω/2"]
    assert about_O and about_O[0].note.startswith("ΣM_O,z = (Ḣ_G + r_G/O × m a_G)_z")
    about_G = {r.text: r.note for r in gyroscope.second_moments}
    assert about_G["-O_y*d = -m*r^2*w_s*Ω/2"].startswith("ΣM_G,z = (Ḣ_G)_z")
    plate = solve_file(PROBLEMS / "seed" / "3d_seed_plate_diagonal.dyn")
    texts = [r.text for r in plate.second_moments]
    assert "D_y*sqrt(a^2 + b^2) = M*a*b*ω^2*(a^2 - b^2)/(12*(a^2 + b^2))" in texts
    assert not solve_file(PROBLEMS / "rigid3d" / "gear_rolling.dyn").second_moments


@pytest.mark.parametrize(
    ("change", "message", "line"),
    [
        (("rolls A at (R_B, -R_A, 0)", "rolls A at (R_B, -R_A, R_A/2)"), "cannot stay at rest", 12),
        (("  travel A: turns n about (0, 1, 0)\n", ""), "add a travel line", 12),
        (("turns n about (0, 1, 0)", "turns n about (1, 0, 0)"), "the 'rotates' line's axis", 15),
        (("M = 5 N*m", "M = -5 N*m"), "never gets there", 15),
        (("  torque M on A\n", ""), "nothing does work", 14),
        (("omega omega_CD", "omega omega_CD, alpha M/(m_A*R_B^2)"), "an alpha has no place", 10),
        (("travel A:", "travel B:"), "there is no body 'B'", 15),
        (("rolls A at (R_B, -R_A, 0)", "rolls A at (R_B, -R_A)"), "cannot go in a 3D scene", 12),
        (  # above and below G: each alone could be at rest, not both (Ω would be 0)
            ("rolls A at (R_B, -R_A, 0)", "rolls A at (R_B, -R_A, 0)\n  rolls A at (R_B, R_A, 0)"),
            "the rolling points together cannot stay at rest",
            13,
        ),
    ],
)
def test_a_bad_gear_scene_gets_a_positioned_error(change, message, line):
    text = gear().replace(*change)
    assert text != gear()
    with pytest.raises(SpecError) as error:
        solve_text(text, "gear.dyn")
    assert message in str(error.value)
    assert error.value.position is not None and error.value.position.line == line


def test_an_unknown_angle_is_not_found_between_two_states():
    text = gear(find="omega_CD, phi").replace("at (R_B, 0, 0)", "at (R_B*cos(phi), 0, 0)")
    with pytest.raises(SpecError, match="cannot be found between two states"):
        solve_text(text, "gear.dyn")


def test_a_two_state_scene_refuses_instant_quantities():
    with pytest.raises(SpecError, match="between two states ask for the rates"):
        solve_text(gear(find="omega_CD, H = Hdot_x(A)"), "gear.dyn")


def test_a_spinning_body_must_be_symmetric_about_its_spin_axis():
    # a plate's inertia changes as it spins about its normal (I_x ≠ I_y): T2 would depend
    # on where the spin left it
    text = (
        gear()
        .replace("disk R_A,", "plate R_A by R_B,")
        .replace("axis A: (1, 0, 0)", "axes A: (0, 1, 0), (0, 0, 1)")
    )
    with pytest.raises(SpecError, match="symmetric about its spin axis"):
        solve_text(text, "gear.dyn")


def test_a_misspelt_rate_between_states_is_not_an_unknown():
    # 'omega_CE' is not asked for and close to nothing given: the rolling point fixes it;
    # 'R_b' (for R_B) in a rate would be a typo, and is refused
    text = gear(find="omega_CD").replace("omega omega_spin", "omega R_b")
    with pytest.raises(SpecError, match="'R_b' is not a given"):
        solve_text(text, "gear.dyn")


def test_cli_reports_a_bad_gear_scene_without_a_traceback(tmp_path):
    spec = tmp_path / "gear.dyn"
    spec.write_text(gear().replace("M = 5 N*m", "M = -5 N*m"))
    result = CliRunner().invoke(app, ["solve", str(spec)])
    assert result.exit_code != 0
    assert "gear.dyn:15" in result.output and "Traceback" not in result.output


def test_the_torque_for_a_given_final_rate():
    # the same energy equation read the other way: M = m (3 R_B²/4 + R_A²/8) ω_CD²/(4π)
    # = 0.275 (15.11554²)/(4π) = 5.000 N·m (by hand, as in the first gear test)
    text = gear(find="M, omega_spin").replace("  M = 5 N*m\n", "  omega_CD = 15 rad/s\n")
    found = answers(solve_text(text, "gear.dyn"))
    assert found["M"].value == pytest.approx(0.275 * 15**2 / (4 * math.pi), rel=1e-12)
    assert found["omega_spin"].value == pytest.approx(45, rel=1e-12)


def test_the_frame_rate_between_states_must_be_asked_for():
    # only the spin that the rolling point fixes may stay out of find
    with pytest.raises(SpecError, match="'omega_CD' is not a given"):
        solve_text(gear(find="omega_spin"), "gear.dyn")


# ---- the bar on a shaft, parts (b) and (c): an unknown angle of the position ----

STEADY_BAR = """\
given:
  m = 2 kg
  L = 0.8 m
  Omega = {Omega} rad/s
scene:
  body bar: mass m, rod L, at (L/2*sin(theta_s), -L/2*cos(theta_s), 0)
  axis bar: (sin(theta_s), -cos(theta_s), 0)
  rotates bar: about (0, 1, 0), through (0, 0, 0), omega Omega
  spins bar: about (0, 0, 1), through (0, 0, 0), omega 0, alpha 0
  bearing B: at (0, 0, 0), pin
  gravity
  assume theta_s > 0
  assume theta_s < pi/2
find: {find}
"""


def steady_bar(find: str = "theta_s, B_x, B_y, Omega_min = onset(theta_s, Omega)", Omega=6) -> str:
    return STEADY_BAR.format(find=find, Omega=Omega)


def test_bar_steady_angle_and_least_speed_agree_with_the_seed_equations():
    """By hand (problems/rigid3d/bar_on_shaft_steady.dyn's header): moments about the pin
    with θ'' = θ' = 0, (m L²/3) Ω² sin θ cos θ = m g (L/2) sin θ, so cos θ_s = 3 g/(2 L Ω²)
    = 0.5109375, θ_s = 59.2737°; B_x = −m Ω² (L/2) sin θ_s = −24.75699 N, B_y = m g; the
    nonzero root leaves 0 where m L² Ω²/3 = m g L/2: Ω_min = √(3 g/(2 L)) = 4.288794 rad/s.
    The seed's equation-mode spec (problems/seed/3d_seed_bar_shaft.dyn) gives the same."""
    scene = solve_file(PROBLEMS / "rigid3d" / "bar_on_shaft_steady.dyn")
    seed = answers(solve_file(PROBLEMS / "seed" / "3d_seed_bar_shaft.dyn"))
    assert scene.mode == "3D scene" and scene.passed
    found = answers(scene)
    c = 3 * 9.81 / (2 * 0.8 * 36)
    assert c == pytest.approx(0.5109375, rel=1e-12)
    assert found["theta_s"].value == pytest.approx(math.degrees(math.acos(c)), rel=1e-12)
    assert found["theta_s"].value == pytest.approx(seed["theta_s"].value, rel=1e-9)
    assert found["Omega_min"].value == pytest.approx(math.sqrt(3 * 9.81 / 1.6), rel=1e-12)
    assert found["Omega_min"].value == pytest.approx(seed["Omega_min"].value, rel=1e-9)
    assert found["B_x"].value == pytest.approx(-2 * 36 * 0.4 * math.sqrt(1 - c * c), rel=1e-12)
    assert found["B_y"].value == pytest.approx(2 * 9.81, rel=1e-12)
    checks = {c.name: c for c in scene.checks}
    assert checks["onset Omega_min"].passed and checks["second moment point: G"].passed


def test_the_symbolic_steady_bar_gives_the_seed_formulas():
    # θ_s = acos(3 g/(2 L Ω²)), Ω_min = √(3 g/(2 L)) (the seed list's symbolic answers)
    solution = solve_file(PROBLEMS / "rigid3d" / "bar_on_shaft_steady-symbolic.dyn")
    assert solution.passed
    assert {k.name for k in solution.key if k.passed} == {"theta_s", "Omega_min"}
    assert all(a.value is None for a in solution.answers)


@settings(max_examples=6, deadline=None)
@given(Omega=st.integers(5, 30))
def test_the_steady_angle_follows_the_hand_formula(Omega):
    # cos θ_s = 3 g/(2 L Ω²) for any Ω above Ω_min = 4.2888 rad/s (hand, as above)
    found = answers(solve_text(steady_bar(find="theta_s, B_x", Omega=Omega), "s.dyn"))
    c = 3 * 9.81 / (2 * 0.8 * Omega**2)
    assert found["theta_s"].value == pytest.approx(math.acos(c), rel=1e-9)
    assert found["B_x"].value == pytest.approx(-2 * Omega**2 * 0.4 * math.sqrt(1 - c * c))


def test_below_the_least_speed_there_is_no_steady_angle():
    # Ω = 4 < Ω_min: cos θ_s = 1.15 > 1; only θ_s = 0 is left, which the assume refuses
    solution = solve_text(steady_bar(Omega=4), "s.dyn")
    found = answers(solution)
    assert found["theta_s"].value is None and not solution.passed
    assert found["Omega_min"].value == pytest.approx(math.sqrt(3 * 9.81 / 1.6), rel=1e-12)


@pytest.mark.parametrize(
    ("find", "message"),
    [
        ("theta_s, W = onset(theta_s)", "onset takes two names"),
        ("theta_s, W = onset(Omega, Omega)", "'Omega' is not an unknown angle"),
        ("theta_s, W = onset(theta_s, Omega_0)", "'Omega_0' is not a given"),
        ("B_x", "'theta_s' in the scene is not a given"),  # an angle not asked: a typo
    ],
)
def test_a_bad_onset_or_angle_gets_a_positioned_error(find, message):
    with pytest.raises(SpecError) as error:
        solve_text(steady_bar(find=find), "s.dyn")
    assert message in str(error.value) and error.value.position is not None


def test_an_assume_line_must_bound_an_unknown():
    text = steady_bar().replace("assume theta_s < pi/2", "assume pi > 3")
    with pytest.raises(SpecError, match="bounds an unknown of the scene") as error:
        solve_text(text, "s.dyn")
    assert error.value.position is not None and error.value.position.line == 13


def test_onset_needs_a_scene_that_can_rest_at_zero_angle():
    # G set off the line of the bar: at θ = 0 the weight has a moment about the pin
    text = steady_bar().replace("at (L/2*sin(theta_s),", "at (L/2*sin(theta_s) + L/8,")
    with pytest.raises(SpecError, match="is not a steady angle for every Omega"):
        solve_text(text, "s.dyn")


def test_onset_needs_a_load_that_moves_the_branch():
    # without gravity the bar's only steady angles are 0 and 90° for every Ω > 0:
    # ∂F/∂θ(0, Ω) = (m L²/3) Ω² vanishes at Ω = 0 only
    text = steady_bar().replace("  gravity\n", "")
    with pytest.raises(SpecError, match="no positive Omega"):
        solve_text(text, "s.dyn")
