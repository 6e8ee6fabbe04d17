"""Until events: a round body slides until it rolls, a block slides until it stops, a
particle on a circle goes on until its cord goes slack or it leaves the surface."""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

G = 9.81
PROBLEMS = Path(__file__).parent.parent / "problems" / "scenes"

DISK = """\
given:
  m = {m} kg
  r = {r} m
  v_1 = {v} m/s
  omega_1 = {w} rad/s
  mu_k = {mu}
scene:
  point C: (0, 0)
  body disk: mass m, {shape} r, at (0, r)
  contact disk at C: normal up, mu_k mu_k
  velocity disk: v_1, right
  omega disk: omega_1 {sense}
  gravity
  travel disk: for t_1, until rolls
find: {find}
"""


def disk(find: str, m=10, r=0.3, v=5, w=10, mu=0.2, shape="disk", sense="ccw"):
    text = DISK.format(m=m, r=r, v=v, w=w, mu=mu, find=find, shape=shape, sense=sense)
    return solve_text(text, "disk.dyn")


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def checks(solution) -> dict:
    return {c.name: c for c in solution.checks}


def test_bundled_until_problems_pass_their_keys():
    for name in ("disk_backspin_rolls", "bob_cord_slack", "dome_contact_lost"):
        solution = solve_file(PROBLEMS / f"{name}.dyn")
        assert solution.passed, name


# ---- slides until it rolls
def test_a_disk_with_backspin_rolls_after_t_equals_slip_over_three_mu_g():
    # Hand derivation (solid disk, I_G = m r²/2): a = −μ g, α = −2 μ g / r, and the slip
    # v + ω r falls at 3 μ g, so t = (v_1 + ω_1 r)/(3 μ g) = 8/5.886 s and
    # v_2 = (2 v_1 − ω_1 r)/3 = 7/3 m/s; s = (v_1 + v_2) t / 2.
    solution = disk("t_1, v = speed(disk), w = omega2(disk), s = distance(disk)")
    got = answers(solution)
    t = 8 / (3 * 0.2 * G)
    assert got["t_1"].value == pytest.approx(t, rel=1e-9)
    assert got["v"].value == pytest.approx(7 / 3, rel=1e-9)
    assert got["w"].value == pytest.approx(7 / 3 / 0.3, rel=1e-9)
    assert got["w"].direction == "cw"  # rolling to the right turns clockwise
    assert got["s"].value == pytest.approx((5 + 7 / 3) * t / 2, rel=1e-9)
    assert not any(c.failed for c in solution.checks)


def test_topspin_faster_than_rolling_speeds_the_disk_up():
    # v_1 = 1 m/s right, ω_1 = 20 rad/s cw: the rim slips left at ω r − v = 5 m/s, so the
    # friction pushes right: a = +μ g; t = (ω_1 r − v_1)/(3 μ g); v_2 = (2 v_1 + ω_1 r)/3
    # = 8/3 m/s (hand derivation as above with the senses reversed).
    solution = disk("t_1, v = speed(disk)", v=1, w=20, sense="cw")
    got = answers(solution)
    assert got["t_1"].value == pytest.approx(5 / (3 * 0.2 * G), rel=1e-9)
    assert got["v"].value == pytest.approx(8 / 3, rel=1e-9)


def test_a_ring_rolls_sooner_with_its_larger_inertia():
    # Thin ring, I_G = m r²: α = −μ g / r, the slip falls at 2 μ g: t = 8/(2 μ g) and
    # v_2 = v_1 − μ g t = 5 − 4 = 1 m/s (hand derivation).
    got = answers(disk("t_1, v = speed(disk)", shape="ring"))
    assert got["t_1"].value == pytest.approx(8 / (2 * 0.2 * G), rel=1e-9)
    assert got["v"].value == pytest.approx(1.0, rel=1e-9)


@settings(max_examples=6, deadline=None)
@given(
    v=st.floats(0.5, 10),
    w=st.floats(0.5, 30),
    mu=st.floats(0.05, 0.6),
)
def test_energy_bookkeeping_across_the_slide(v, w, mu):
    # T1 + U_friction = T2, with U = −μk N × (the slip distance) = −μ m g (v_P1 t / 2): the
    # contact point's slip speed falls linearly from v_P1 to 0 (hand derivation).
    m, r = 10, 0.3
    got = answers(disk("t_1, v = speed(disk), w = omega2(disk)", v=v, w=w, mu=mu))
    t, v2, w2 = got["t_1"].value, got["v"].value, got["w"].value
    I_G = m * r**2 / 2
    T1 = m * v**2 / 2 + I_G * w**2 / 2
    T2 = m * v2**2 / 2 + I_G * w2**2 / 2
    slip = v + w * r
    assert T1 - mu * m * G * slip * t / 2 == pytest.approx(T2, rel=1e-7)
    assert v2 == pytest.approx(w2 * r, rel=1e-9)  # it rolls at the end


def test_a_bowling_ball_thrown_without_spin_rolls_at_five_sevenths_of_its_speed():
    # Solid sphere, I_G = 2 m r²/5, no omega line (no spin at release): a = −μ g,
    # α = −5 μ g/(2 r); the slip v + ω r falls at 3.5 μ g: t = v_1/(3.5 μ g) and
    # v_2 = v_1 − μ g t = 5 v_1/7 (Hibbeler's bowling-ball result; hand derivation).
    text = DISK.format(m=7, r=0.11, v=6, w=0, mu=0.1, find="t_1, v = speed(disk)",
                       shape="sphere", sense="ccw")  # fmt: skip
    text = text.replace("  omega disk: omega_1 ccw\n", "").replace("  omega_1 = 0 rad/s\n", "")
    got = answers(solve_text(text, "ball.dyn"))
    assert got["t_1"].value == pytest.approx(6 / (3.5 * 0.1 * G), rel=1e-9)
    assert got["v"].value == pytest.approx(6 * 5 / 7, rel=1e-9)


def test_a_ball_that_never_stops_slipping_fails_its_check():
    # Gravity at −130° makes the floor a 40° slope falling to the left; the disk slides down
    # it (left) without spin. Slip v + ω r: a = −g sin 40° + μ g cos 40°, α r = 2 μ g cos 40°,
    # so d(slip)/dt = −g (sin 40° − 3 μ cos 40°) < 0 for μk = 0.05 < (1/3) tan 40°: the
    # slip (negative) grows, the time at which it would roll comes out negative, the check
    # fails and the exit is not 0 (hand derivation).
    text = DISK.format(m=10, r=0.3, v=2, w=0, mu=0.05, find="t_1", shape="disk", sense="ccw")
    text = text.replace("  gravity\n", "  gravity: angle phi\n").replace(
        "  mu_k = 0.05\n", "  mu_k = 0.05\n  phi = -130 deg\n"
    )
    text = text.replace("velocity disk: v_1, right", "velocity disk: v_1, left")
    text = text.replace("  omega disk: omega_1 ccw\n", "")
    solution = solve_text(text, "slope.dyn")
    event = next(a for a in solution.assumptions if a.name.startswith("slides until"))
    assert not event.holds and "never happens" in event.detail
    assert not solution.passed


def test_a_disk_already_rolling_is_refused_with_its_line():
    with pytest.raises(SpecError, match="already rolls") as error:
        disk("t_1", v=3, w=10, sense="cw")
    assert error.value.position.line == 14


def test_until_rolls_needs_a_rough_contact():
    text = DISK.format(m=1, r=1, v=1, w=1, mu=0.2, find="t_1", shape="disk", sense="ccw")
    text = text.replace("normal up, mu_k mu_k", "normal up, smooth")
    with pytest.raises(SpecError, match="one rough contact with mu_k"):
        solve_text(text, "d.dyn")


def test_until_rolls_goes_on_a_for_line_with_a_named_time():
    text = DISK.format(m=1, r=1, v=1, w=1, mu=0.2, find="m", shape="disk", sense="ccw")
    bare = text.replace("for t_1, until rolls", "until rolls")
    with pytest.raises(SpecError, match="ends an interval whose time is named") as error:
        solve_text(bare, "d.dyn")
    assert (error.value.position.line, error.value.position.column) == (14, 22)
    by = text.replace("for t_1, until rolls", "by d, right, until rolls")
    with pytest.raises(SpecError, match="goes on a 'for' line"):
        solve_text(by, "d.dyn")
    odd = text.replace("for t_1, until rolls", "until cord loose")
    with pytest.raises(SpecError, match="unknown end of a travel"):
        solve_text(odd, "d.dyn")


# ---- until stops
def test_a_block_slides_until_it_stops_in_v_squared_over_two_mu_g():
    # t = v_1/(μ g), s = v_1²/(2 μ g) (constant deceleration μ g; hand derivation).
    text = """\
given:
  m = 4 kg
  v_1 = 6 m/s
  mu_k = 0.3
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal up, mu_k mu_k, slides right
  velocity block: v_1, right
  gravity
  travel block: for t_s, until stops
find: t_s, s = distance(block)
"""
    got = answers(solve_text(text, "b.dyn"))
    assert got["t_s"].value == pytest.approx(6 / (0.3 * G), rel=1e-9)
    assert got["s"].value == pytest.approx(36 / (2 * 0.3 * G), rel=1e-9)
    assert got["s"].direction == "right"


# ---- a particle on a circle until its cord goes slack or it leaves the surface
BOB = """\
given:
  m = 2 kg
  L = {L} m
  v_1 = {v} m/s
scene:
  point O: (0, 0)
  body bob: particle, mass m, at (0, -L)
  link cord: bob at G to O
  velocity bob: v_1, right
  gravity
  travel bob: until cord slack
find: theta = angle(bob), v = speed(bob)
"""


@pytest.mark.parametrize("L, v", [(1.0, 6.0), (0.8, 5.0), (2.0, 8.5)])
def test_the_cord_goes_slack_where_cos_theta_is_two_thirds_less_v_squared(L, v):
    # From the bottom: T = m (v_1²/L − 2 g + 3 g cos θ) = 0 → cos θ = (2 g − v_1²/L)/(3 g),
    # and there v² = −g L cos θ (hand derivation in problems/scenes/bob_cord_slack.dyn).
    got = answers(solve_text(BOB.format(L=L, v=v), "bob.dyn"))
    cos = (2 * G - v**2 / L) / (3 * G)
    assert got["theta"].value == pytest.approx(math.degrees(math.acos(cos)), rel=1e-7)
    assert got["v"].value == pytest.approx(math.sqrt(-G * L * cos), rel=1e-7)


def test_a_bob_too_slow_swings_back_before_the_cord_goes_slack():
    # v_1² < 2 g L: it stops below the level of O (T > 0 there), so the cord never slackens.
    with pytest.raises(SpecError, match="swings back") as error:
        solve_text(BOB.format(L=1, v=3), "bob.dyn")
    assert error.value.position.line == 11


def test_a_bob_fast_enough_to_loop_never_goes_slack():
    # v_1² ≥ 5 g L: T ≥ 0 at the top (hand derivation), so it never slackens.
    with pytest.raises(SpecError, match="stays above zero all the way round"):
        solve_text(BOB.format(L=1, v=7.5), "bob.dyn")


def test_until_slack_names_a_link_to_a_fixed_point():
    text = BOB.format(L=1, v=6).replace("until cord slack", "until rope slack")
    with pytest.raises(SpecError, match="needs a link rope"):
        solve_text(text, "bob.dyn")


def test_a_block_inside_a_loop_leaves_the_track_where_the_bob_would():
    # Inside a circular track the push is toward the centre, as a cord's pull: the same
    # cos θ = (2 g − v_1²/R)/(3 g) from the bottom (hand derivation as for the bob).
    text = """\
given:
  m = 1 kg
  R = 1 m
  v_1 = 6 m/s
scene:
  path loop: x^2 + y^2 = R^2
  body car: particle, mass m, at (0, -R)
  velocity car: v_1, right
  gravity
  travel car: until contact lost
find: theta = angle(car)
"""
    got = answers(solve_text(text, "loop.dyn"))
    cos = (2 * G - 36) / (3 * G)
    assert got["theta"].value == pytest.approx(math.degrees(math.acos(cos)), rel=1e-7)


def test_contact_lost_needs_a_circular_path_through_the_particle():
    text = (PROBLEMS / "dome_contact_lost.dyn").read_text()
    with pytest.raises(SpecError, match="circular path through block"):
        solve_text(text.replace("at (0, R)", "at (0, 2*R)"), "dome.dyn")
