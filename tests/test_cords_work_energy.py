"""Inextensible cords between two states: work and energy of drums, pulleys and blocks.

Every expected number is derived by hand in the comments (T1 + ΣU = T2 with the cord's
kinematics v = ω r), never taken from dynsolve's output.
"""

import math
from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file
from dynsolve.system import SolveOptions

G = 9.81
SCENES = Path(__file__).resolve().parent.parent / "problems" / "scenes"

# the newcomer's spec, as the brief gives it (Hibbeler 12e Example 17.11's drum, ch. 18)
DRUM = """\
problem: Drum and block, work-energy
units: SI
given:
  m_d = 60 kg
  k_O = 0.25 m
  r = 0.4 m
  m_b = 20 kg
  h = 2 m
{extra}scene:
  point O: (0, 0)
  body drum: mass m_d, gyration k_O, at (0, 0)
  body block: particle, mass m_b, at (r, -2*r)
  point A on drum: (r, 0)
  pin drum at O
  cord T: drum at A to block, down
{load}  gravity
  travel block: by h, down
find: v = speed(block), omega_2 = omega2(drum)
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "cords.dyn"
    path.write_text(text)
    return path


def by_name(solution, name: str):
    return next(a for a in solution.answers if a.name == name)


def assumption(solution, name: str):
    return next(a for a in solution.assumptions if a.name == name)


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_the_newcomers_drum_and_block(tmp_path, mode):
    # I_O = m_d k_O² = 3.75 kg·m²; m_b g h = ½ (m_b + I_O/r²) v²:
    # 392.4 = ½ (20 + 23.4375) v² → v = √(392.4/21.71875) = 4.250569 m/s; ω = v/r, cw
    solution = solve_file(write(tmp_path, DRUM.format(extra="", load="")), SolveOptions(mode))
    v = math.sqrt(20 * G * 2 / (0.5 * (20 + 60 * 0.25**2 / 0.4**2)))
    assert v == pytest.approx(4.250569, rel=1e-6)
    assert by_name(solution, "v").value == pytest.approx(v, rel=1e-9)
    omega = by_name(solution, "omega_2")
    assert omega.value == pytest.approx(v / 0.4, rel=1e-9)
    assert omega.direction == "cw"  # the block falls on the drum's right
    assert solution.passed
    note = solution.equations[0].note
    assert "T (inextensible and taut" in note and "O (the pin does not move)" in note


def test_the_drum_is_checked_by_its_constant_acceleration_and_its_tension(tmp_path):
    # at state 1: a = m_b g r²/(I_O + m_b r²) = 20(9.81)(0.16)/6.95 = 4.51683 m/s², and
    # T = m_b (g − a) = 20(9.81 − 4.51683) = 105.863 N, both constant: v = √(2 a h)
    solution = solve_file(write(tmp_path, DRUM.format(extra="", load="")))
    second = next(c for c in solution.checks if c.name.startswith("second method"))
    assert second.passed and "v₂² = 2 a s" in second.detail
    a = 20 * G * 0.16 / 6.95
    assert second.detail.startswith("ΣF = m a_G") and f"{math.sqrt(2 * a * 2):.7g}" in second.detail
    taut = assumption(solution, "cord T taut between the states")
    assert taut.holds and f"T = {20 * (G - a):.4g} N ≥ 0" in taut.detail
    assert "constant" in taut.detail


def test_a_couple_that_unwinds_the_drum_faster_than_the_block_falls_slackens_the_cord(
    tmp_path,
):
    # M = 2000 N·m cw on the drum: as one, α = (M + m_b g r)/(I_O + m_b r²) = 2078.48/6.95
    # = 299.06 rad/s², a = α r = 119.6 m/s² > g, so T = m_b (g − a) = −2196 N < 0: the
    # work–energy answer (block and drum moving as one) does not hold, and says so
    text = DRUM.format(extra="  M = 2000 N*m\n", load="  couple M on drum: cw\n")
    solution = solve_file(write(tmp_path, text))
    taut = assumption(solution, "cord T taut between the states")
    T = 20 * (G - 0.4 * (2000 + 20 * G * 0.4) / 6.95)
    assert not taut.holds and f"T = {T:.4g} N < 0" in taut.detail
    assert not solution.passed


def test_a_cord_between_two_drums_each_wound(tmp_path):
    # drum 1 (I_1 = ½ 15 (0.2)² = 0.3 kg·m², r_1 = 0.2 m) lowers a 10-kg block from its right
    # side and winds a horizontal cord from its top onto the top of drum 2 (I_2 = ½ 8 (0.1)²
    # = 0.04 kg·m², r_2 = 0.1 m): ω_1 r_1 = v = ω_2 r_2, both cw.
    # m g h = ½ (m + I_1/r_1² + I_2/r_2²) v² = ½ (10 + 7.5 + 4) v² → v = √(98.1/10.75)
    text = """\
given:
  m = 10 kg
  m_1 = 15 kg
  m_2 = 8 kg
  r_1 = 0.2 m
  r_2 = 0.1 m
  d = 1 m
  h = 1 m
scene:
  point O_1: (0, 0)
  point O_2: (-d, r_1 - r_2)
  body one: mass m_1, disk r_1, at (0, 0)
  body two: mass m_2, disk r_2, at (-d, r_1 - r_2)
  body block: particle, mass m, at (r_1, -d)
  pin one at O_1
  pin two at O_2
  cord T_1: one at (r_1, 0) to block, down   # points relative to each body's G
  cord T_2: one at (0, r_1) to two at (0, r_2), left
  gravity
  travel block: by h, down
find: v = speed(block), w_1 = omega2(one), w_2 = omega2(two)
"""
    solution = solve_file(write(tmp_path, text))
    v = math.sqrt(98.1 / 10.75)
    assert by_name(solution, "v").value == pytest.approx(v, rel=1e-9)
    assert by_name(solution, "w_1").value == pytest.approx(v / 0.2, rel=1e-9)
    assert by_name(solution, "w_2").value == pytest.approx(v / 0.1, rel=1e-9)
    assert by_name(solution, "w_1").direction == by_name(solution, "w_2").direction == "cw"
    # T_2 = I_2 α_2/r_2 with α_2 = a/r_2, a = v²/(2h): 0.04 (v²/2)/0.01 = 4·v²/2
    taut = assumption(solution, "cord T_2 taut between the states")
    assert taut.holds and f"T_2 = {0.04 * (v**2 / 2) / 0.01:.4g} N ≥ 0" in taut.detail
    assert solution.passed


@pytest.mark.parametrize(
    ("name", "answers"),
    [
        # m_b g h = ½ (m_b + I_O/r²) v², above: 4.250569 m/s, ω = v/0.4
        ("drum_block_cord_energy", {"v": 4.250569, "omega_2": 10.62642}),
        # (m_B − m_A sin θ − μk m_A cos θ) g s = ½ (m_A + m_B + ½ m_p) v²:
        # (20 − 5 − 1.732051)(9.81)(1.5) = 195.2379 J = 16.5 v² → v = 3.439854, ω = v/0.15
        ("incline_pulley_hanging_block", {"v": 3.439854, "v_A": 3.439854, "omega_2": 22.93236}),
        # (m_B − m_A) g h = ½ (m_A + m_B + ½ m_p) v²: 70.632 = 10 v² → v = 2.657668, ω = v/0.15
        ("pulley_two_blocks_energy", {"v": 2.657668, "v_A": 2.657668, "omega_2": 17.71779}),
        # m g h = ¾ m v² → v = √(4 g h/3) = √(7.848) = 2.801428, ω = v/0.03
        ("yoyo_cord_fixed_energy", {"v": 2.801428, "omega_2": 93.38094}),
    ],
)
@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_the_bundled_cord_problems(name, answers, mode):
    solution = solve_file(SCENES / f"{name}.dyn", SolveOptions(mode))
    for answer, value in answers.items():
        assert by_name(solution, answer).value == pytest.approx(value, rel=1e-6)
    assert solution.passed
    assert any(c.name.startswith("second method") and c.passed for c in solution.checks)


def test_a_cord_tied_to_a_fixed_point_swings_and_is_refused(tmp_path):
    text = """\
given:
  m = 2 kg
  L = 1 m
scene:
  point O: (0, 0)
  body bob: particle, mass m, at (L, 0)
  cord T: bob at G, left, fixed
  gravity
  travel bob: to (0, -L)
find: v = speed(bob)
"""
    with pytest.raises(SpecError, match="swings about it") as error:
        solve_file(write(tmp_path, text))
    assert error.value.position.line == 7


def test_a_cord_whose_ends_would_move_apart_across_it_is_refused(tmp_path):
    # the block slides right on the floor under the drum: the vertical cord would lean over
    text = DRUM.format(extra="", load="  contact block at G: normal up\n").replace(
        "travel block: by h, down", "travel block: by h, right"
    )
    with pytest.raises(SpecError, match="would change direction between the states"):
        solve_file(write(tmp_path, text))


def test_two_blocks_tied_by_a_cord_and_pulled_along_a_smooth_floor(tmp_path):
    # P s = ½ (m_1 + m_2) v²: 50(2) = 5 v² → v = √20 = 4.472136 m/s, both blocks;
    # a = P/(m_1 + m_2) = 5 m/s², T = m_1 a = 20 N (taut); the simulation follows both
    text = """\
given:
  m_1 = 4 kg
  m_2 = 6 kg
  P = 50 N
  s = 2 m
  L = 1 m
scene:
  body one: particle, mass m_1, at (0, 0)
  body two: particle, mass m_2, at (L, 0)
  contact one at G: normal up
  contact two at G: normal up
  cord T: one at G to two, right
  force P on two at G: right
  gravity
  travel two: by s, right
find: v = speed(two), v_1 = speed(one)
"""
    solution = solve_file(write(tmp_path, text))
    assert by_name(solution, "v").value == pytest.approx(math.sqrt(20), rel=1e-9)
    assert by_name(solution, "v_1").value == pytest.approx(math.sqrt(20), rel=1e-9)
    assert assumption(solution, "cord T taut").detail == "T = 20 N ≥ 0"
    assert next(c for c in solution.checks if c.name == "simulation").passed
    assert solution.passed


def test_a_cord_tied_to_the_end_of_a_turning_bar_is_refused(tmp_path):
    # the bar's end goes round the pin, so the hanging cord would lean: not a wound drum
    text = """\
given:
  m = 6 kg
  L = 1 m
  m_b = 2 kg
  h = 0.1 m
scene:
  point O: (0, 0)
  body bar: mass m, rod L, at (L/2, 0)
  body block: particle, mass m_b, at (L, -L)
  pin bar at O
  cord T: bar at (L/2, 0) to block, down
  gravity
  travel block: by h, down
find: v = speed(block)
"""
    with pytest.raises(SpecError, match="tied to a point of bar, which turns") as error:
        solve_file(write(tmp_path, text))
    assert error.value.position.line == 11


def test_a_block_pushed_across_the_cord_it_hangs_on_is_refused(tmp_path):
    # a horizontal push would swing the hanging block: its cord would lean
    text = DRUM.format(extra="  P = 50 N\n", load="  force P on block at G: right\n")
    with pytest.raises(SpecError, match="acts across the cord: it would swing"):
        solve_file(write(tmp_path, text))


def test_a_push_along_the_cord_adds_its_work(tmp_path):
    # P = 50 N down on the block: (m_b g + P) h = ½ (m_b + I_O/r²) v²:
    # (196.2 + 50)(2) = 21.71875 v² → v = √(492.4/21.71875) = 4.761476 m/s
    text = DRUM.format(extra="  P = 50 N\n", load="  force P on block at G: down\n")
    solution = solve_file(write(tmp_path, text))
    assert by_name(solution, "v").value == pytest.approx(math.sqrt(492.4 / 21.71875), rel=1e-9)
    assert solution.passed


def test_the_block_moving_down_at_state_1_counts_in_T1(tmp_path):
    # v_1 = 2 m/s down, the drum turning at v_1/r: T1 = 21.71875 (2²) = 86.875 J;
    # T2 = T1 + m_b g h → v = √((86.875 + 392.4)/21.71875) = 4.697589 m/s
    text = DRUM.format(extra="  v_1 = 2 m/s\n", load="  velocity block: v_1, down\n")
    solution = solve_file(write(tmp_path, text))
    expected = math.sqrt((86.875 + 392.4) / 21.71875)
    assert by_name(solution, "v").value == pytest.approx(expected, rel=1e-9)
    assert solution.passed


def test_a_drum_winds_a_block_up_a_smooth_incline(tmp_path):
    # a couple M = 100 N·m cw on the drum (I_O = 30(0.2)² = 1.2 kg·m², r = 0.25 m) winds
    # in the cord tied to a 20-kg block on a smooth 30° incline; the block moves s = 1.5 m
    # up: Δθ = s/r = 6 rad. M Δθ − m g s sin θ = ½ (m + I_O/r²) v²:
    # 600 − 147.15 = 452.85 J = ½ (20 + 19.2) v² → v = √(452.85/19.6) = 4.806715 m/s
    # (the block starts L = 2.5 m of cord from the drum: 1 m left at state 2)
    text = """\
given:
  m_d = 30 kg
  k_O = 0.2 m
  r = 0.25 m
  m = 20 kg
  theta = 30 deg
  M = 100 N*m
  s = 1.5 m
  L = 2.5 m
scene:
  point O: (0, 0)
  body drum: mass m_d, gyration k_O, at (0, 0)
  body block: particle, mass m, at (-r*sin(theta) - L*cos(theta), r*cos(theta) - L*sin(theta))
  pin drum at O
  contact block at G: normal (-sin(theta), cos(theta))
  cord T: drum at (-r*sin(theta), r*cos(theta)) to block, (-cos(theta), -sin(theta))
  couple M on drum: cw
  gravity
  travel block: by s, angle theta
find: v = speed(block)
"""
    solution = solve_file(write(tmp_path, text))
    assert by_name(solution, "v").value == pytest.approx(math.sqrt(452.85 / 19.6), rel=1e-9)
    assert solution.passed
    assert "U_M = M Δθ" in solution.equations[0].note


def test_a_cord_wound_on_top_of_a_rolling_wheel_moves_twice_as_far_as_its_centre(tmp_path):
    # the cord leaves the top of the wheel (disk, m = 8 kg, R = 0.3 m) rolling without
    # slip; block B (5 kg, smooth table) is pulled by P = 30 N through s = 1 m. The top
    # moves 2 s_G, so v_G = v/2, ω = v/(2R): P s = ½ v² (m_B + m/4 + ½ m R²/(4R²)) = 4 v²
    # → v = √7.5 = 2.738613 m/s, v_G = 1.369306 m/s; a = v²/(2s) = 3.75 m/s² and
    # T = P − m_B a = 11.25 N (taut)
    text = """\
given:
  m = 8 kg
  R = 0.3 m
  m_B = 5 kg
  P = 30 N
  s = 1 m
  L = 2 m
scene:
  point C: (0, 0)
  body wheel: mass m, disk R, at (0, R)
  body B: particle, mass m_B, at (L, 2*R)
  rolls wheel at C: normal up
  contact B at G: normal up
  cord T: wheel at (0, R) to B, right
  force P on B at G: right
  gravity
  travel B: by s, right
find: v = speed(B), v_G = speed(wheel)
"""
    solution = solve_file(write(tmp_path, text))
    assert by_name(solution, "v").value == pytest.approx(math.sqrt(7.5), rel=1e-9)
    assert by_name(solution, "v_G").value == pytest.approx(math.sqrt(7.5) / 2, rel=1e-9)
    taut = assumption(solution, "cord T taut between the states")
    assert taut.holds and taut.detail.startswith("T = 11.25 N ≥ 0")
    assert solution.passed


@pytest.mark.parametrize(("E", "swings"), [("(r, -2*r - L_0)", False), ("(r + L_0, -2*r)", True)])
def test_a_spring_on_the_hanging_block_along_or_across_its_cord(tmp_path, E, swings):
    # along (E below the block, spring unstretched at state 1, k = 50 N/m): it is
    # compressed by h = 2 m on the way down, U_S = −½ k h² = −100 J:
    # 392.4 − 100 = 21.71875 v² → v = √(292.4/21.71875) = 3.669202 m/s.
    # Across (E to the right): the block would be pulled off the cord's line: refused.
    text = DRUM.format(
        extra="  k = 50 N/m\n  L_0 = 3 m\n",
        load=f"  point E: {E}\n  spring S: block at G to E, k k, unstretched L_0\n",
    )
    if swings:
        with pytest.raises(SpecError, match="a spring or its velocity acts across the cord"):
            solve_file(write(tmp_path, text))
        return
    solution = solve_file(write(tmp_path, text))
    assert by_name(solution, "v").value == pytest.approx(math.sqrt(292.4 / 21.71875), rel=1e-9)
    taut = assumption(solution, "cord T taut between the states")
    # the spring's force changes: T sampled along the way; at state 2 (x = h = 2 m, spring
    # force k h = 100 N up) a = (m_b g − k h)/(m_b + I_O/r²) = 96.2/43.4375 = 2.214676 m/s²,
    # T = (I_O/r²) a = 23.4375 × 2.214676 = 51.907 N ≥ 0
    assert taut.holds and "T = 51.91 N at state 2" in taut.detail
    assert "8 of 8 states sampled along the travel" in taut.detail


# the newcomer's round-3 reproducers (drum_block_spring_slack.dyn and the two travels past
# the drum or pulley), without their comments
SPRING_BELOW = """\
units: SI
given:
  m_d = 10 kg
  k_O = 0.2 m
  r = 0.2 m
  m_b = 5 kg
  k = 500 N/m
  L_0 = 0.5 m
  h = 0.15 m
scene:
  point O: (0, 0)
  point F: (r, -3*r - L_0)
  body drum: mass m_d, gyration k_O, at (0, 0)
  body block: particle, mass m_b, at (r, -3*r)
  pin drum at O
  cord T: drum at (r, 0) to block, down
  spring S: block at G to F, k k, unstretched L_0
  gravity
  travel block: by h, down
find: v = speed(block)
"""


@pytest.mark.parametrize("mode", ["exact", "numeric"])
def test_a_spring_below_the_block_slackens_the_cord_on_the_way_and_fails(tmp_path, mode):
    # taut: (m_b + I_O/r²) a = m_b g − k x with I_O/r² = 10 kg, and the drum's ΣM_O gives
    # T = (I_O/r²) a = 10 (49.05 − 500 x)/15: T = 32.7 N at x = 0, −17.3 N at x = h = 0.15 m,
    # zero at x = m_b g/k = 0.0981 m, past which the cord is slack (the right answer is
    # 0.226771 m/s, not the taut 0.480625 m/s): the assumption fails, with where
    solution = solve_file(write(tmp_path, SPRING_BELOW), SolveOptions(mode))
    taut = assumption(solution, "cord T taut between the states")
    T_1, T_2 = 10 * 5 * G / 15, 10 * (5 * G - 500 * 0.15) / 15
    assert (round(T_1, 1), round(T_2, 1)) == (32.7, -17.3)
    assert not taut.holds
    assert f"T = {T_1:.4g} N ≥ 0 at state 1" in taut.detail
    assert f"T = {T_2:.4g} N at state 2" in taut.detail
    assert f"goes slack at a travel of {5 * G / 500:.4g} of the 0.15" in taut.detail
    assert not solution.passed


DRUM_INCLINE = """\
units: FPS
given:
  W_d = 50 lb
  r = 1 ft
  k_O = 0.8 ft
  M = 40 lb*ft
  W_b = 20 lb
  theta = 30 deg
  mu = 0.2
  s = {s} ft
  L = 10 ft
scene:
  point O: (0, 0)
  body drum: weight W_d, gyration k_O, disk r, at (0, 0)
  point P on drum: (-r*sin(theta), r*cos(theta))
  body block: particle, weight W_b, at (-r*sin(theta) - L*cos(theta), r*cos(theta) - L*sin(theta))
  pin drum at O
  contact block at G: normal (-sin(theta), cos(theta)), mu_k mu
  cord T: drum at P to block, angle theta + pi
  couple M on drum: cw
  gravity
  travel block: by s, angle theta
find: v = speed(block)
"""


def test_a_travel_longer_than_the_cord_to_the_drum_is_refused(tmp_path):
    # the cord's free length from P to the block is L = 10 ft; pulled s = 12 ft up toward
    # the drum, it would be 10 − 12 = −2 ft long at state 2: refused, at the cord's line.
    # s = 8 ft leaves 2 ft and is solved.
    with pytest.raises(SpecError, match=r"cord T between drum and block would be -2 long"):
        solve_file(write(tmp_path, DRUM_INCLINE.format(s=12)))
    assert solve_file(write(tmp_path, DRUM_INCLINE.format(s=8))).answers


def test_a_block_hauled_up_through_its_pulley_is_refused(tmp_path):
    # A (40 lb) falls h = 4 ft and hauls B up from 3 r = 2.25 ft below the pulley's rim
    # point: the cord to B would be 2.25 − 4 = −1.75 ft long at state 2
    text = """\
units: FPS
given:
  W_A = 40 lb
  W_B = 25 lb
  W_p = 30 lb
  r = 0.75 ft
  k_O = 0.5 ft
  h = 4 ft
scene:
  point O: (0, 0)
  body pulley: weight W_p, gyration k_O, disk r, at (0, 0)
  body A: particle, weight W_A, at (-r, -3*r)
  body B: particle, weight W_B, at (r, -3*r)
  pin pulley at O
  cord T1: pulley at (-r, 0) to A, down
  cord T2: pulley at (r, 0) to B, down
  gravity
  travel A: by h, down
find: v = speed(A)
"""
    with pytest.raises(SpecError, match=r"cord T2 between pulley and B would be -1.75 long"):
        solve_file(write(tmp_path, text))


def test_a_spring_on_the_drums_rim_is_carried_round_when_the_tension_is_sampled(tmp_path):
    # the spring from the drum's left rim point A = (−r, 0) to F = (−r, −L_0) (unstretched at
    # state 1) turns with the drum: after the block falls x, θ = x/r cw, A = (−r cos θ, r sin θ),
    # V_S = ½ k (ℓ − L_0)², ℓ = |A − F|. Block: m_b a = m_b g − T; energy:
    # (m_b + I_O/r²) a = m_b g − dV_S/dx, dV_S/dx = k (ℓ − L_0) ((A − F)·dA/dθ)/(ℓ r). At x = h
    # = 0.3 m: θ = 1.5 rad, ℓ = 0.723768 m, dV_S/dx = 7.2615 N, a = 2.78590 m/s², T = 35.12 N
    text = SPRING_BELOW.replace("k = 500 N/m", "k = 100 N/m").replace("h = 0.15 m", "h = 0.3 m")
    text = text.replace("(r, -3*r - L_0)", "(-r, -L_0)").replace(
        "block at G to F", "drum at (-r, 0) to F"
    )
    r, k, L_0, h = 0.2, 100, 0.5, 0.3
    theta = h / r
    A, F = (-r * math.cos(theta), r * math.sin(theta)), (-r, -L_0)
    AF = (A[0] - F[0], A[1] - F[1])
    ell = math.hypot(*AF)
    dA = (r * math.sin(theta), r * math.cos(theta))
    dV_dx = k * (ell - L_0) * (AF[0] * dA[0] + AF[1] * dA[1]) / (ell * r)
    T_2 = 5 * (G - (5 * G - dV_dx) / 15)
    assert (round(ell, 6), round(T_2, 2)) == (0.723768, 35.12)
    solution = solve_file(write(tmp_path, text))
    taut = assumption(solution, "cord T taut between the states")
    assert taut.holds and f"T = {T_2:.4g} N at state 2" in taut.detail
    # ½ (m_b + I_O/r²) v² = m_b g h − V_S(h)
    v = math.sqrt((5 * G * h - k * (ell - L_0) ** 2 / 2) / 7.5)
    assert by_name(solution, "v").value == pytest.approx(v, rel=1e-9)
    assert solution.passed
