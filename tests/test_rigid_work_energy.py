"""Work and energy of rigid bodies and linkages between two states (scene mode, `travel`)."""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

G = 9.81

PENDULUM = """\
given:
  m = 4 kg
  L = {L}
  w_1 = {w_1}
  turn = {turn}
scene:
  point O: (0, 0)
  body rod: mass m, rod L, at ({x}, {y})
  pin rod at O
  omega rod: w_1 cw
  gravity
  travel rod: turns turn cw
find: omega = omega2(rod)
"""


def write(tmp_path: Path, text: str, name: str = "energy.dyn") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def pendulum(tmp_path, L="1.2 m", w_1="0 rad/s", turn="90 deg", x="L/2", y="0"):
    text = PENDULUM.format(L=L, w_1=w_1, turn=turn, x=x, y=y)
    return solve_file(write(tmp_path, text))


def test_a_rod_released_horizontal_swings_down_at_sqrt_3g_over_L(tmp_path):
    # ½ (m L²/3) ω² = m g L/2  ->  ω = sqrt(3 g / L) = sqrt(3(9.81)/1.2) = 4.952 rad/s, cw
    solution = pendulum(tmp_path)
    assert solution.passed
    (answer,) = solution.answers
    assert answer.value == pytest.approx(math.sqrt(3 * G / 1.2), rel=1e-12)
    assert answer.direction == "cw"
    note = solution.equations[0].note
    assert "O (the pin does not move)" in note


def test_the_initial_angular_velocity_counts_in_T1(tmp_path):
    # ½ I_O ω₂² = ½ I_O ω₁² + m g L/2  ->  ω₂² = ω₁² + 3 g/L = 4 + 24.525
    solution = pendulum(tmp_path, w_1="2 rad/s")
    assert solution.answers[0].value == pytest.approx(math.sqrt(4 + 3 * G / 1.2), rel=1e-12)


@pytest.mark.parametrize("turn", ["90 deg", "1.5707963267948966 rad", "0.25 rev"])
def test_the_same_turn_in_deg_rad_or_rev(tmp_path, turn):
    assert pendulum(tmp_path, turn=turn).answers[0].value == pytest.approx(
        math.sqrt(3 * G / 1.2), rel=1e-9
    )


@settings(max_examples=6)
@given(st.integers(min_value=-179, max_value=180))
def test_a_pendulum_started_at_any_angle(tmp_path_factory, start):
    # G starts at angle `start` (deg, from +x) on the circle of radius L/2, turns 30° cw
    # with ω₁ = 3 rad/s: ½ I_O ω₂² = ½ I_O ω₁² + m g (L/2)(sin θ₁ − sin θ₂), θ₂ = θ₁ − 30°,
    # I_O = m L²/3; when the right side is negative it never gets there
    theta_1 = math.radians(start)
    drop = 0.6 * (math.sin(theta_1) - math.sin(theta_1 - math.radians(30)))
    x, y = f"L*{math.cos(theta_1) / 2!r}", f"L*{math.sin(theta_1) / 2!r}"
    tmp_path = tmp_path_factory.mktemp("pendulum")
    solution = pendulum(tmp_path, w_1="3 rad/s", turn="30 deg", x=x, y=y)
    squared = 9 + 2 * G * drop / (1.2**2 / 3)
    if squared < 0:
        assert not solution.passed
        return
    assert solution.answers[0].value == pytest.approx(math.sqrt(squared), rel=1e-9)


INCLINE = """\
given:
  m = 5 kg
  R = 0.2 m
  d = 3 m
  beta = {beta} deg
scene:
  point C: (0, 0)
  body disk: mass m, disk R, at (-R*sin(beta), R*cos(beta))
  rolls disk at C: normal angle (pi/2 + beta)
  gravity
  travel disk: by d, angle (pi + beta)
find: v = speed(disk), omega = omega2(disk)
"""


@pytest.mark.parametrize("beta", [-30, -10, 25])
def test_a_disk_rolling_down_an_incline(tmp_path, beta):
    # the plane rises to the right at β; "by d, angle 180° + β" goes down it when β > 0, up
    # it when β < 0. Rolling from rest down a height h = d |sin β| (β > 0 only):
    # m g h = ½ m v² + ½ (m R²/2)(v/R)²  ->  v = sqrt(4 g h / 3)
    text = INCLINE.format(beta=beta)
    solution = solve_file(write(tmp_path, text))
    if beta < 0:  # it would have to climb from rest
        assert not solution.passed
        return
    v, omega = solution.answers
    h = 3 * math.sin(math.radians(beta))
    assert v.value == pytest.approx(math.sqrt(4 * G * h / 3), rel=1e-12)
    assert omega.value == pytest.approx(v.value / 0.2, rel=1e-12)
    assert omega.direction == "ccw"  # rolling to the left
    # second method: α = g sin β/(3R/2) constant down the plane, ω₂² = 2 α θ
    assert any(c.name.startswith("second method") and c.passed for c in solution.checks)


SPRING_DISK = Path(__file__).resolve().parent.parent / "problems" / "seed" / "rwe_seed_disk40lb.dyn"


def test_a_spring_pinned_to_the_rim_follows_the_material_point(tmp_path):
    # Without `wound` the spring's end is the material point T at the top: after rolling
    # 0.5 ft left the disk has turned θ = 0.625 rad ccw, so T is at
    # G₂ + 0.8 (−sin θ, cos θ) = (−0.5 − 0.46823, 0.8 + 0.64863); the wall end is at (2, 1.6):
    # s₂ = sqrt(2.96823² + 0.15137²) − 2 = 0.97209 ft (not 2 s_G = 1 ft)
    # ΣU = 15(0.625) − 5 s₂²;  T2 = ½ (40/32.2)(0.8² + 0.6²) ω²
    text = SPRING_DISK.read_text().replace(", wound", "")
    solution = solve_file(write(tmp_path, text))
    theta = 0.5 / 0.8
    T_x, T_y = -0.5 - 0.8 * math.sin(theta), 0.8 + 0.8 * math.cos(theta)
    s_2 = math.hypot(2 - T_x, 1.6 - T_y) - 2
    omega = math.sqrt((15 * theta - 5 * s_2**2) / (0.5 * 40 / 32.2 * (0.64 + 0.36)))
    assert solution.answers[0].value == pytest.approx(omega, rel=1e-9)
    assert not solution.passed  # the published 2.65 assumes the wound (horizontal) spring


def test_a_wound_spring_must_run_along_its_ends_motion(tmp_path):
    text = SPRING_DISK.read_text().replace("point E: (L_0, 2*r)", "point E: (L_0, 3*r)")
    with pytest.raises(SpecError, match="must pull along the motion"):
        solve_file(write(tmp_path, text))


PLATFORM = Path(__file__).resolve().parent.parent / "problems" / "seed" / "rwe_seed_platform.dyn"


def test_a_four_bar_whose_platform_turn_is_left_open_asks_how_it_moves(tmp_path):
    # Without 'motion platform: translation' the platform's turn follows only from closing
    # the loop A-B-D-C (circle conditions with two assemblies): dynsolve asks instead of
    # guessing the assembly.
    text = PLATFORM.read_text().replace("  motion platform: translation", "")
    text = text.replace("weight W, at", "weight W, gyration h, at")
    with pytest.raises(SpecError, match="closure of a loop") as caught:
        solve_file(write(tmp_path, text))
    assert "motion platform: translation" in caught.value.message


BLOCK = """\
given:
  m = 10 kg
  v_1 = 6 m/s
  d = 2 m
  mu_k = 0.3
  P = {P}
  b = 0.4 m
  h = 0.2 m
scene:
  point C: (0, 0)
  body block: mass m, block b by h, at (0, h/2)
  base B on block: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k
  force P on block at G: angle pi/6
  velocity block: v_1, right
  gravity
  travel block: by d, right
find: v = speed(block)
"""


@pytest.mark.parametrize("P", ["0 N", "40 N"])
def test_friction_work_while_sliding(tmp_path, P):
    # N = m g − P sin 30° (ΣF_y = 0 on the straight floor); U_F = −μk N d; U_P = P cos 30° d
    # ½ m v₂² = ½ m v₁² + P cos 30° d − μk (m g − P sin 30°) d
    force = float(P.split()[0])
    text = BLOCK.format(P=P)
    if force == 0:
        text = text.replace("  force P on block at G: angle pi/6\n", "")
    solution = solve_file(write(tmp_path, text))
    N = 10 * G - force * 0.5
    work = force * math.cos(math.radians(30)) * 2 - 0.3 * N * 2
    expected = math.sqrt(6**2 + 2 * work / 10)
    assert solution.answers[0].value == pytest.approx(expected, rel=1e-12)
    assert "μk N s" in solution.equations[0].note


@pytest.mark.parametrize(
    ("change", "message"),
    [
        # a link's state is its angle only
        (("travel AB: turns theta2 ccw", "travel AB: to (0, l)"), "can only turn"),
        # an unknown body
        (("travel AB: turns", "travel EF: turns"), "there is no body 'EF'"),
        # drop one link: the platform can move two ways
        (("  link CD: platform at D to C\n", ""), "degrees of freedom"),
    ],
)
def test_bad_states_of_a_linkage(tmp_path, change, message):
    text = PLATFORM.read_text().replace(*change).replace("  motion platform: translation", "")
    text = text.replace("weight W, at", "weight W, gyration h, at")
    with pytest.raises(SpecError, match=message):
        solve_file(write(tmp_path, text))


def test_friction_work_needs_mu_k(tmp_path):
    text = BLOCK.format(P="0 N").replace(", mu_k mu_k", ", mu_s 0.5")
    with pytest.raises(SpecError, match="give mu_k there"):
        solve_file(write(tmp_path, text))


def test_the_rolling_wheel_is_checked_with_its_constant_angular_acceleration():
    # ΣM about the contact point: P cos φ r = (I_G + m r²) α with I_G = m k_O² = 4.5 kg·m²,
    # m r² = 8 kg·m²: α = 43.30(0.4)/12.5 = 1.3856 rad/s² (cw), constant;
    # ω₂² = 2 α θ = 2(1.3856)(20π) → ω₂ = 13.20 rad/s
    seed = Path(__file__).resolve().parent.parent / "problems" / "seed" / "rwe_seed_wheel10rev.dyn"
    solution = solve_file(seed)
    check = next(c for c in solution.checks if c.name == "second method: |ω| of wheel")
    assert check.passed
    alpha = 50 * math.cos(math.radians(30)) * 0.4 / (50 * 0.3**2 + 50 * 0.4**2)
    assert f"{math.sqrt(2 * alpha * 20 * math.pi):.7g}" in check.detail


def test_a_travel_that_stops_must_end_at_rest(tmp_path):
    # regression: 'stops' with nothing unknown dropped the energy equation and reported ω = 0
    # as found; here T1 + ΣU = 15(0.625) − 5(1)² = 4.375 ft·lb ≠ 0, so it still moves
    text = SPRING_DISK.read_text().replace("by s_G, left ", "by s_G, left, stops ")
    solution = solve_file(write(tmp_path, text))
    check = next(c for c in solution.checks if c.name == "assumption: at rest in state 2")
    assert not check.passed and "still moves" in check.detail
    assert not solution.passed
