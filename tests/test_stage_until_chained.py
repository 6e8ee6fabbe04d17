"""``until CORD slack`` and ``until contact lost`` after other stages: a particle on a
circle followed from the motion the stage before left (an impact, a swing), its root
branch found from the numbers the stages before give, and the refusals that keep it honest.

Hand results used throughout (θ from the lowest point of a cord of length L, speed v_a
there): the cord goes slack where −g cos θ = v²/L with v² = v_a² − 2 g L (1 − cos θ), so
cos θ = (2 g L − v_a²)/(3 g L), for 2 g L < v_a² < 5 g L (below it swings back, above it
loops). On a dome of radius R from the top at speed v_a: cos θ = (v_a² + 2 g R)/(3 g R).
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

G = 9.81

BULLET_BOB = """\
given:
  m_b = {m_b}
  M   = {M}
  L   = {L}
  v_0 = {v_0}
scene:
  point O: (0, 0)
  body bullet: particle, mass m_b, at (-L/2, -L)
  body bob: particle, mass M, at (0, -L)
  link cord: bob at G to O
  velocity bullet: v_0, right
  gravity
  impact bullet with bob: e {e}, line right
  travel bob: until cord slack
find: {find}
"""


def solve(tmp_path: Path, text: str):
    path = tmp_path / "until_chain.dyn"
    path.write_text(text)
    return solve_file(path)


def answers(solution) -> dict:
    return {a.name: a.value for a in solution.answers}


def bullet_bob(tmp_path, find="theta = angle(bob), v_3 = speed(bob)", e="0", **given):
    values = {"m_b": "50 g", "M": "2 kg", "L": "1.2 m", "v_0": "250 m/s"} | given
    return solve(tmp_path, BULLET_BOB.format(find=find, e=e, **values))


def slack_angle(v_a: float, L: float) -> float:
    return math.acos((2 * G * L - v_a**2) / (3 * G * L))


def test_a_bullet_embeds_and_the_bob_swings_until_the_cord_goes_slack(tmp_path):
    # hand: v_2 = 0.05·250/2.05 = 6.097561 m/s; cos θ = (2gL − v_2²)/(3gL) → θ = 112.7134°;
    # v_3 = √(−gL cos θ) = 2.131998 m/s; T_3 = ½ (2.05) v_3² = 4.659 J
    solution = bullet_bob(tmp_path, find="theta = angle(bob), v_3 = speed(bob), T_3 = T(bob, 3)")
    assert not any(c.failed for c in solution.checks), [c for c in solution.checks if c.failed]
    got = answers(solution)
    assert got["theta"] == pytest.approx(112.7134, rel=1e-6)
    assert got["v_3"] == pytest.approx(2.131998, rel=1e-6)
    # the state after the event carries the speed along the circle: T(bob, 3) of bob alone
    assert got["T_3"] == pytest.approx(0.5 * 2.0 * 2.131998**2, rel=1e-6)


def test_the_cord_is_checked_taut_where_the_until_stage_starts(tmp_path):
    # hand: the tension just after the impact, T = (m_b + M)(v_2²/L + g) = 83.63 N
    solution = bullet_bob(tmp_path)
    taut = next(c for c in solution.checks if "taut at the start in stage 2" in c.name)
    assert taut.passed and "83.63" in taut.detail


def test_too_slow_a_bullet_swings_the_bob_back_and_the_cord_never_goes_slack(tmp_path):
    # v_2² < 2 g L: 0.05·150/2.05 = 3.66 m/s, v_2² = 13.4 < 23.5: it swings back
    with pytest.raises(SpecError, match="swings back"):
        bullet_bob(tmp_path, v_0="150 m/s")


def test_too_fast_a_bullet_sends_the_bob_round_and_the_cord_stays_taut(tmp_path):
    # v_2² > 5 g L: 0.05·400/2.05 = 9.76 m/s, v_2² = 95.2 > 58.9: it loops
    with pytest.raises(SpecError, match="loops"):
        bullet_bob(tmp_path, v_0="400 m/s")


def test_a_bullet_that_rebounds_is_still_moving_and_the_stage_is_refused(tmp_path):
    # e > 0 with m_b ≠ M: the bullet rebounds and keeps moving while the bob swings
    with pytest.raises(SpecError, match="bullet is still moving"):
        bullet_bob(tmp_path, e="0.5")


def test_symbolic_givens_are_refused_with_the_reason(tmp_path):
    text = BULLET_BOB.format(
        find="theta = angle(bob)", e="0", m_b="kg", M="kg", L="m", v_0="m/s"
    ).replace(" = ", ": ", 4)  # m_b: kg, ... (symbols without values)
    with pytest.raises(SpecError, match="needs numbers"):
        solve(tmp_path, text)


def test_a_particle_with_a_support_of_its_own_is_refused(tmp_path):
    text = BULLET_BOB.format(
        find="theta = angle(bob)", e="0", m_b="50 g", M="2 kg", L="1.2 m", v_0="250 m/s"
    ).replace("  gravity\n", "  point C: (0, -L)\n  contact bob at C: normal up\n  gravity\n")
    with pytest.raises(SpecError, match="support C would act too"):
        solve(tmp_path, text)


def test_a_swing_to_the_horizontal_then_on_until_slack(tmp_path):
    # hand (problems/stages/bob_horizontal_then_slack.dyn): v_2 = √(v_1² − 2gL) = 4.757100;
    # φ = 140.2591° from the bottom, 50.25909° past the horizontal; v_3 = 2.746513 m/s
    path = Path(__file__).parent.parent / "problems" / "stages" / "bob_horizontal_then_slack.dyn"
    solution = solve_file(path)
    assert not any(c.failed for c in solution.checks)
    got = answers(solution)
    assert got["theta"] == pytest.approx(50.25909, rel=1e-6)
    assert got["v_3"] == pytest.approx(2.746513, rel=1e-6)


def test_clay_sticks_to_a_block_on_a_dome_which_then_leaves_it(tmp_path):
    # hand (problems/stages/clay_dome_leaves.dyn): v_2 = 0.5714286 m/s;
    # cos θ = (v_2² + 2gR)/(3gR) → θ = 47.47494°; v_3 = √(gR cos θ) = 2.820788 m/s
    path = Path(__file__).parent.parent / "problems" / "stages" / "clay_dome_leaves.dyn"
    solution = solve_file(path)
    assert not any(c.failed for c in solution.checks)
    got = answers(solution)
    assert got["theta"] == pytest.approx(47.47494, rel=1e-6)
    assert got["v_3"] == pytest.approx(2.820788, rel=1e-6)


@settings(max_examples=8, deadline=None)
@given(
    ratio=st.floats(2.2, 4.8),  # v_2²/(g L): between swinging back and looping
    L=st.floats(0.3, 3.0),
    mass_ratio=st.floats(0.01, 0.2),
)
def test_the_slack_angle_and_the_energy_bookkeeping_for_any_start(
    tmp_path_factory, ratio, L, mass_ratio
):
    # momentum: v_2 = m_b v_0/(m_b + M); energy across stage 2: T_3 = T_2 − (m_b + M) g h
    M = 2.0
    m_b = mass_ratio * M
    v_2 = math.sqrt(ratio * G * L)
    v_0 = v_2 * (m_b + M) / m_b
    solution = bullet_bob(
        tmp_path_factory.mktemp("h"),
        find="theta = angle(bob), h = height(bob), T_2 = T(2), T_3 = T(3)",
        m_b=f"{m_b!r} kg",
        M=f"{M!r} kg",
        L=f"{L!r} m",
        v_0=f"{v_0!r} m/s",
    )
    assert not any(c.failed for c in solution.checks)
    got = answers(solution)
    assert got["theta"] == pytest.approx(math.degrees(slack_angle(v_2, L)), rel=1e-7)  # deg
    assert got["T_3"] == pytest.approx(got["T_2"] - (m_b + M) * G * got["h"], rel=1e-7)
