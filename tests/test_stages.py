"""Scenes followed through stages: a fall, an impact (with a body or the ground), a rebound;
kinetic energy, work, energy lost and impulse as finds; derived finds (`define:`)."""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import DimensionError, SpecError
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.spec.parser import parse_spec

G = 9.81
PROBLEMS = Path(__file__).parent.parent / "problems" / "stages"

BOUNCE = """\
given:
  m = {m}
  h = {h}
  e = {e}
scene:
  body ball: particle, mass m, at (0, h)
  gravity
  travel ball: by h, down
  impact ball with ground: e e, line down
  travel ball: by h_2, up, stops
find: {find}
"""

FALL_THEN_IMPACT = """\
given:
  m = 2 kg
  M = 8 kg
  h = 1.25 m
  e = {e}
scene:
  body ram: particle, mass m, at (0, h)
  body pile: particle, mass M, at (0, -h)
  gravity
  travel ram: to (0, 0)
  impact ram with pile: e e, line down
find: {find}
"""


def solve(tmp_path: Path, text: str, name: str = "stages.dyn"):
    path = tmp_path / name
    path.write_text(text)
    return solve_file(path)


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def bounce(tmp_path: Path, find: str, m: str = "0.5 kg", h: str = "2 m", e: str = "0.6"):
    return solve(tmp_path, BOUNCE.format(m=m, h=h, e=e, find=find))


# ---- chaining: the velocities after one stage are those before the next
def test_a_fall_then_an_impact_uses_the_speed_at_the_end_of_the_fall(tmp_path):
    # regression: the impact used v = 0 before it and reported v_after = 0.
    # fall: v₂ = √(2 g h) = √(2 (9.81)(1.25)) = 4.952272 m/s;
    # plastic impact: m v₂ = (m + M) v₃ → v₃ = 2 (4.952272)/10 = 0.9904544 m/s, down
    solution = solve(tmp_path, FALL_THEN_IMPACT.format(e="0", find="v = v_after(ram)"))
    got = answers(solution)["v"]
    assert got.value == pytest.approx(0.2 * math.sqrt(2 * G * 1.25), rel=1e-9)
    assert got.direction == "down"
    assert solution.passed


def test_an_impact_of_bodies_moving_apart_fails_its_check(tmp_path):
    # line up: from the ram toward the pile is down, so (v_ram − v_pile)·n < 0 as written
    text = FALL_THEN_IMPACT.format(e="0", find="v = v_after(ram)").replace("line down", "line up")
    solution = solve(tmp_path, text)
    approach = next(a for a in solution.assumptions if a.name == "approach in stage 2")
    assert not approach.holds and "does not strike pile" in approach.detail
    assert not solution.passed


def test_each_stage_is_shown_in_order_with_its_principle(tmp_path):
    solution = solve(tmp_path, FALL_THEN_IMPACT.format(e="0.5", find="v = v_after(pile)"))
    notes = [row.note for row in solution.equations]
    assert notes[0].startswith("stage 1 (state 1 → 2): ram travels to its position, work and")
    assert "T1 + ΣU(1→2) = T2" in notes[0]
    assert all(n.startswith("stage 2 (state 2 → 3): ram strikes pile, impact") for n in notes[1:])
    stages = next(c for c in solution.checks if c.name == "stages")
    assert stages.detail.index("stage 1") < stages.detail.index("stage 2")


def test_a_ball_bounces_off_the_ground_and_rises_e_squared_h(tmp_path):
    # v₂ = √(2 g h) = 6.264184; v₃ = e v₂ = 3.758510 up; h₂ = e² h = 0.72 m
    got = answers(bounce(tmp_path, "v_2 = speed(ball, 2), v_3 = v_after(ball), h_2"))
    assert got["v_2"].value == pytest.approx(math.sqrt(2 * G * 2), rel=1e-9)
    assert got["v_3"].value == pytest.approx(0.6 * math.sqrt(2 * G * 2), rel=1e-9)
    assert got["v_3"].direction == "up"
    assert got["h_2"].value == pytest.approx(0.36 * 2, rel=1e-9)


def test_an_oblique_strike_on_the_ground_keeps_the_tangential_component(tmp_path):
    # v = 4 m/s along (3, −4)/5 = (2.4, −3.2); smooth floor, e = 0.6: (2.4, +1.92),
    # |v| = √(2.4² + 1.92²) = 3.073467 m/s at atan(1.92/2.4) = 38.66° above +x
    text = """\
given:
  m = 0.5 kg
  v = 4 m/s
  e = 0.6
scene:
  body ball: particle, mass m, at (0, 0)
  velocity ball: v, (3, -4)
  impact ball with ground: e e, line down
find: v2 = v_after(ball)
"""
    got = answers(solve(tmp_path, text))["v2"]
    assert got.value == pytest.approx(math.hypot(2.4, 1.92), rel=1e-12)
    assert got.direction == "38.7° above the horizontal, to the right"


@pytest.mark.parametrize(("e", "speed", "direction"), [("0", 0.0, ""), ("1", 5.0, "up")])
def test_plastic_and_elastic_strikes_on_the_ground(tmp_path, e, speed, direction):
    # straight down at 5 m/s: e = 0 stops it, e = 1 sends it back up at 5 m/s
    text = f"""\
given:
  m = 1 kg
  v = 5 m/s
scene:
  body ball: particle, mass m, at (0, 0)
  velocity ball: v, down
  impact ball with ground: e {e}, line down
find: v2 = v_after(ball)
"""
    got = answers(solve(tmp_path, text))["v2"]
    assert got.value == pytest.approx(speed, abs=1e-12)
    assert got.direction == direction


PENETRATION = """\
given:
  m_r = 800 kg
  m_p = 1200 kg
  h   = 1.5 m
  R   = 50 kN
scene:
  body ram: particle, mass m_r, at (0, h)
  body pile: particle, mass m_p, at (0, -h)
  force R on pile at G: up
  gravity
  travel ram: by h, down
  impact ram with pile: e {e}, line down
  travel pile: by d, down, stops
find: d [m]
"""


def test_after_a_plastic_impact_the_bodies_travel_together(tmp_path):
    # v₃ = 800 √(2 g h)/2000 → ½ (2000) v₃² = 4708.8 J; the pair then stops after d:
    # 4708.8 + 2000 (9.81) d − 50000 d = 0 → d = 4708.8/30380 = 0.1549967 m
    solution = solve(tmp_path, PENETRATION.format(e="0"))
    assert answers(solution)["d"].value == pytest.approx(4708.8 / 30380, rel=1e-9)
    assert "ram moving with pile: their masses added" in solution.equations[-1].note


def test_the_average_resistance_that_stops_the_pile_is_an_unknown(tmp_path):
    # same chain, d = 0.155 m given: R = (m_r + m_p) g + ½ (m_r + m_p) v₃²/d
    #   = 19620 + 4708.8/0.155 = 49999.355 N
    text = PENETRATION.format(e="0").replace("R   = 50 kN", "d   = 0.155 m")
    got = answers(solve(tmp_path, text.replace("find: d [m]", "find: R [N]")))["R"]
    assert got.value == pytest.approx(19620 + 4708.8 / 0.155, rel=1e-9)


def test_a_moving_body_left_out_of_a_travel_is_refused(tmp_path):
    # with e = 0.5 the ram rebounds on its own: the pile's travel cannot ignore it
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, PENETRATION.format(e="0.5"))
    assert "ram is moving but takes no part" in caught.value.message
    assert (caught.value.position.line, caught.value.position.column) == (13, 10)


def test_a_pivot_then_a_swing_still_chains(tmp_path):
    # the cube over the lip (seed problem) goes through the stages as well
    solution = solve_file(Path(__file__).parent.parent / "problems/seed/ci_seed_cube_lip.dyn")
    assert solution.passed
    assert solution.equations[0].note.startswith("stage 1 (state 1 → 2): cube strikes B")


def test_the_energy_lost_when_the_cube_strikes_the_lip(tmp_path):
    # I_B = (8/3) M a², ω₁ = 3 v/(8 a): T after = ½ I_B ω₁² = (3/8)(½ M v²), so 5/8 of
    # T1 = ½ M v² is lost, v² = 16 a g (√2 − 1)/3 (a = 0.25 m, M = 8 kg)
    seed = Path(__file__).parent.parent / "problems/seed/ci_seed_cube_lip.dyn"
    text = seed.read_text().replace(
        "find: v_min [m/s], omega_1 = omega_after(cube)", "find: v_min, dE = energy_lost(1)"
    )
    text = text[: text.index("answers:")]
    got = answers(solve(tmp_path, text))
    v2 = 16 * 0.25 * G * (math.sqrt(2) - 1) / 3
    assert got["dE"].value == pytest.approx(5 / 8 * 0.5 * 8 * v2, rel=1e-9)


# ---- findable quantities
def test_kinetic_energy_work_energy_lost_and_impulse(tmp_path):
    # m = 0.5 kg, h = 2 m, e = 0.6; v₂² = 2 g h = 39.24, v₃² = e² v₂² = 14.1264
    # T(ball, 3) = ½ (0.5)(14.1264) = 3.5316 J; T(1) = 0
    # work(W_ball, 1) = m g h = 9.81 J; work(gravity, 3) = −m g h₂ = −0.5 (9.81)(0.72) = −3.5316 J
    # energy lost in the bounce = ½ m (v₂² − v₃²) = 0.25 (25.1136) = 6.2784 J
    # impulse on the ball = m (1 + e) v₂ = 0.5 (1.6)(6.264184) = 5.011347 N·s, up
    find = (
        "T_3 = T(ball, 3), T_1 = T(1), U_1 = work(W_ball, 1), U_3 = work(gravity, 3), "
        "dE = energy_lost(2), J = impulse(ball)"
    )
    got = answers(bounce(tmp_path, find))
    assert got["T_3"].value == pytest.approx(3.5316, rel=1e-9)
    assert got["T_3"].unit == "J"
    assert got["T_1"].value == pytest.approx(0.0, abs=1e-12)
    assert got["U_1"].value == pytest.approx(9.81, rel=1e-9)
    assert got["U_3"].value == pytest.approx(-3.5316, rel=1e-9)
    assert got["dE"].value == pytest.approx(6.2784, rel=1e-9)
    assert got["J"].value == pytest.approx(0.5 * 1.6 * math.sqrt(2 * G * 2), rel=1e-9)
    assert got["J"].direction == "up"


def test_derived_finds_are_expressions_of_finds_givens_and_scene_quantities(tmp_path):
    # lost = energy_lost(2)/T(ball, 2) = 1 − e² = 0.64; ratio = h_2/h = e² = 0.36
    text = BOUNCE.format(m="0.5 kg", h="2 m", e="0.6", find="h_2, ratio")
    text += "define:\n  lost = energy_lost(2)/T(ball, 2)\n  ratio = h_2/h   # rebound ratio\n"
    got = answers(solve(tmp_path, text))
    assert got["ratio"].value == pytest.approx(0.36, rel=1e-9)
    assert got["lost"].value == pytest.approx(0.64, rel=1e-9)  # shown though not in find
    assert [a for a in got] == ["h_2", "ratio", "lost"]


def test_the_bundled_stage_problems_meet_their_hand_derived_keys():
    for path in sorted(PROBLEMS.glob("*.dyn")):
        solution = solve_file(path)
        failed = [c for c in solution.checks if c.failed]
        assert not failed, (path.name, failed)
    assert (
        len(list(PROBLEMS.glob("*.dyn"))) == 13
    )  # block_up_incline_slides_back (newcomer round 7) is the 13th


# ---- bad input
def test_a_define_must_be_dimensionally_consistent(tmp_path):
    text = BOUNCE.format(m="0.5 kg", h="2 m", e="0.6", find="h_2")
    text += "define:\n  bad = T(ball, 2) + h\n"
    with pytest.raises(DimensionError) as caught:
        solve(tmp_path, text)
    assert caught.value.position is not None and caught.value.position.line == 13


def test_a_define_names_only_known_quantities(tmp_path):
    text = BOUNCE.format(m="0.5 kg", h="2 m", e="0.6", find="h_2")
    text += "define:\n  r = h_3/h\n"
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, text)
    assert "'h_3'" in caught.value.message and "h_2" in caught.value.hint
    assert (caught.value.position.line, caught.value.position.column) == (13, 7)


@pytest.mark.parametrize(
    ("find", "define", "what"),
    [("dE = energy_lost(2)", "dE = T(2) - T(3)", "find"), ("h_2", "h = 2*h_2", "given")],
)
def test_a_define_needs_a_name_of_its_own(tmp_path, find, define, what):
    text = BOUNCE.format(m="0.5 kg", h="2 m", e="0.6", find=find) + f"define:\n  {define}\n"
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, text)
    assert f"already a {what}" in caught.value.message and caught.value.position.line == 13


def test_a_single_rigid_travel_answers_kinetic_energy_and_work(tmp_path):
    # Ch.18 wheel (seed rwe_seed_wheel10rev): s_O = 0.4 (10)(2π) = 25.13274 m;
    # work(P) = P cos 30° s_O = 43.30127 (25.13274) = 1088.28 J = T2 (T1 = 0);
    # the weight does no work (G moves across it)
    seed = Path(__file__).parent.parent / "problems/seed/rwe_seed_wheel10rev.dyn"
    text = seed.read_text().replace(
        "find: omega = omega2(wheel)",
        "find: omega = omega2(wheel), T_2 = T(wheel, 2), U_P = work(P), U_W = work(W_wheel)",
    )
    solution = solve(tmp_path, text)
    got = answers(solution)
    s_O = 0.4 * 10 * 2 * math.pi
    assert got["U_P"].value == pytest.approx(50 * math.cos(math.pi / 6) * s_O, rel=1e-9)
    assert got["T_2"].value == pytest.approx(got["U_P"].value, rel=1e-9)
    assert got["U_W"].value == pytest.approx(0.0, abs=1e-12)
    assert got["omega"].value == pytest.approx(13.2, rel=5e-3) and solution.passed


def test_a_define_is_one_name_equal_to_an_expression():
    with pytest.raises(SpecError) as caught:
        parse_spec("scene:\n  gravity\ndefine:\n  x > 2\n", "d.dyn")
    assert "NAME = EXPRESSION" in caught.value.message


def test_define_needs_a_scene():
    with pytest.raises(SpecError) as caught:
        parse_spec("equations:\n  x = 2\nfind: x\ndefine:\n  y = 2*x\n", "d.dyn")
    assert caught.value.position.line == 4 and "equation" in caught.value.hint


@pytest.mark.parametrize(
    ("find", "message", "hint"),
    [
        ("E = T(ball, 9)", "no state '9'", "1 to 4"),
        ("U = work(P)", "no single work of 'P'", "W_ball"),
        ("L = energy_lost(1)", "not an impact", "2"),
        ("J = impulse(2)", "impulse needs the body", "impulse on B"),
    ],
)
def test_stage_quantities_report_bad_arguments(tmp_path, find, message, hint):
    with pytest.raises(SpecError) as caught:
        bounce(tmp_path, find)
    assert message in caught.value.message and hint in caught.value.hint
    assert caught.value.position.line == 11


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        # the cord is vertical at the bottom: a line of impact with a vertical part pulls it
        ("line right", "line (1, 1)", "link cord on bob is not across the line"),
        # a pinned rod that swings to the impact: where it is after the swing is not followed
        # (the impact itself, angular momentum about O, is tests/test_angular_momentum.py)
        ("body bob: particle, mass m_A,", "body bob: mass m_A, rod L,", "bob is after an earlier"),
    ],
)
def test_an_impact_whose_supports_would_take_part_is_refused(tmp_path, old, new, message):
    text = (PROBLEMS / "pendulum_block.dyn").read_text()
    if "rod" in new:
        text = text.replace(old, new).replace("link cord: bob at G to O", "pin bob at O")
    else:
        text = text.replace(old, new)
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, text)
    assert message in caught.value.message


def test_an_impact_into_a_supported_body_along_its_support_normal_is_refused(tmp_path):
    # a ball dropped onto a block resting on the floor: the floor's impulse acts too
    text = BOUNCE.format(m="1 kg", h="1 m", e="0.5", find="v = v_after(ball)")
    text = text.replace(
        "  gravity\n",
        "  body block: particle, mass m, at (0, 0)\n  contact block at G: normal up, smooth\n"
        "  gravity\n",
    ).replace("ball with ground", "ball with block")
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, text)
    assert "support G of block pushes along the line of impact" in caught.value.message


def test_a_particle_moving_across_its_travel_is_refused(tmp_path):
    # a ball thrown sideways does not fall straight: its direction at the floor is unknown
    text = """\
given:
  m = 1 kg
  v = 3 m/s
  h = 2 m
scene:
  body ball: particle, mass m, at (0, h)
  velocity ball: v, right
  gravity
  travel ball: by h, down
  impact ball with ground: e 1, line down
find: v2 = v_after(ball)
"""
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, text)
    assert "straight" in caught.value.message
    assert caught.value.position.line == 9  # the travel line


def test_a_travel_against_the_motion_fails_its_sense_check(tmp_path):
    # after e = 0.5 the ball moves up; a travel 'down' from there is reported, not passed
    text = (
        BOUNCE.format(m="1 kg", h="1 m", e="0.5", find="h_2")
        .replace("travel ball: by h_2, up, stops", "travel ball: by h, down")
        .replace("find: h_2", "find: v = speed(ball, 4)")
    )
    solution = solve(tmp_path, text)
    sense = next(a for a in solution.assumptions if a.name == "sense of motion in stage 3")
    assert not sense.holds and not solution.passed


# ---- properties
@settings(max_examples=8, deadline=None)
@given(e=st.integers(0, 10), h=st.integers(1, 20), m=st.integers(1, 9), M=st.integers(1, 9))
def test_momentum_is_conserved_across_a_chained_impact_for_any_e(tmp_path_factory, e, h, m, M):
    tmp = tmp_path_factory.mktemp("momentum")
    text = FALL_THEN_IMPACT.format(e=f"{e / 10}", find="v_r = v_after(ram), v_p = v_after(pile)")
    text = text.replace("m = 2 kg", f"m = {m} kg").replace("M = 8 kg", f"M = {M} kg")
    text = text.replace("h = 1.25 m", f"h = {h / 4} m")
    got = answers(solve(tmp, text))
    sign = {"down": 1, "up": -1, "": 0}
    v2 = math.sqrt(2 * G * h / 4)  # the fall, by hand
    v_r = sign[got["v_r"].direction] * got["v_r"].value
    v_p = sign[got["v_p"].direction] * got["v_p"].value
    assert m * v_r + M * v_p == pytest.approx(m * v2, rel=1e-9)  # Σ m v kept
    assert v_p - v_r == pytest.approx(e / 10 * v2, rel=1e-9, abs=1e-12)  # restitution


@settings(max_examples=8, deadline=None)
@given(e=st.integers(0, 10), h=st.integers(1, 20))
def test_energy_bookkeeping_across_chained_stages(tmp_path_factory, e, h):
    # T1 + ΣU(1→2) = T2 and T3 + ΣU(3→4) = T4 = 0, with T3 = e² T2 across the bounce
    tmp = tmp_path_factory.mktemp("energy")
    find = (
        "T_1 = T(ball, 1), T_2 = T(ball, 2), T_3 = T(ball, 3), T_4 = T(ball, 4), "
        "U_1 = work(gravity, 1), U_3 = work(gravity, 3)"
    )
    got = {n: a.value for n, a in answers(bounce(tmp, find, h=f"{h} m", e=f"{e / 10}")).items()}
    assert got["T_1"] + got["U_1"] == pytest.approx(got["T_2"], rel=1e-9)
    assert got["T_3"] + got["U_3"] == pytest.approx(got["T_4"], abs=1e-9)
    assert got["T_3"] == pytest.approx((e / 10) ** 2 * got["T_2"], rel=1e-9, abs=1e-12)
    assert got["T_2"] == pytest.approx(0.5 * G * h, rel=1e-9)  # m g h, m = 0.5 kg


def test_a_line_of_impact_written_backwards_is_named_as_such() -> None:
    # newcomer round 5: A (x = 0) moves right at 4 m/s toward B (x = 1 m) moving left at
    # 2 m/s, with the line written 'left' (from B toward A): the check said "A does not
    # strike B", which is false; it now says the line must point from A toward B.
    text = """given:
  m_A = 2 kg
  m_B = 3 kg
  v_A1 = 4 m/s
  v_B1 = 2 m/s
  e = 0.6
  D = 1 m
scene:
  body A: particle, mass m_A, at (0, 0)
  body B: particle, mass m_B, at (D, 0)
  velocity A: v_A1, right
  velocity B: v_B1, left
  impact A with B: e e, line left
find: v_A = v_after(A)
"""
    solution = solve_text(text)
    (approach,) = [c for c in solution.checks if c.name == "assumption: approach in stage 1"]
    assert not approach.passed
    assert (
        "must point from A toward B" in approach.detail and "does not strike" not in approach.detail
    )
