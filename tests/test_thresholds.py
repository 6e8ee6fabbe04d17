"""Thresholds: the size of a load that puts an assumption at its limit — tips(C, P),
slips(C, P), slack(T, P), lifts(A, P) — each from a hand derivation."""

import math
from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

G = 9.81
SCENES = Path(__file__).parent.parent / "problems" / "scenes"

CRATE = """\
given:
  m = 50 kg
  b = 1 m
  h = 1.5 m
  d = {d} m
  P = 200 N
  mu_k = 0.2
scene:
  body crate: mass m, block b by h, at (0, h/2)
  base C on crate: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, slides right
  force P on crate at (-b/2, d - h/2): right
  gravity
find: {find}
"""

BLOCK = """\
given:
  m = 10 kg
  P = 20 N
  theta = 30 deg
  mu_s = 0.4
  mu_k = 0.3
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal up, mu_s mu_s, mu_k mu_k
  force P on block at G: angle -theta
  gravity
find: {find}
"""


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def test_the_bundled_crate_tips_at_its_hand_derived_push():
    assert solve_file(SCENES / "crate_push_tips.dyn").passed


@pytest.mark.parametrize("d", [1.2, 1.0, 1.4])
def test_a_sliding_crate_tips_when_the_normal_force_reaches_its_front_edge(d):
    # ΣM_G = 0: −(d − h/2) P + m g x − (h/2) μk m g = 0, tipping at x = b/2:
    # P = m g (b/2 − μk h/2)/(d − h/2) (hand derivation, problems/scenes/crate_push_tips.dyn).
    got = answers(solve_text(CRATE.format(d=d, find="P_t = tips(C, P)"), "crate.dyn"))
    expected = 50 * G * (0.5 - 0.2 * 0.75) / (d - 0.75)
    assert got["P_t"].value == pytest.approx(expected, rel=1e-9)
    assert got["P_t"].unit == "N"


def test_a_push_down_at_an_angle_slips_the_block_at_mu_m_g_over_cos_less_mu_sin():
    # Pushed down at θ below the horizontal: N = m g + P sin θ, about to slip when
    # P cos θ = μs N → P = μs m g / (cos θ − μs sin θ) (Hibbeler-style hand derivation).
    got = answers(solve_text(BLOCK.format(find="P_s = slips(G, P), F_G"), "block.dyn"))
    t = math.radians(30)
    assert got["P_s"].value == pytest.approx(0.4 * 10 * G / (math.cos(t) - 0.4 * math.sin(t)))
    assert got["F_G"].value == pytest.approx(20 * math.cos(t))  # at P = 20 N it holds


def test_a_pull_up_at_sixty_degrees_lifts_the_block_at_m_g_over_sin():
    # N = m g − P sin φ = 0 → P = m g / sin 60° = 22.655 N (hand derivation).
    text = BLOCK.replace("angle -theta", "angle 2*theta").format(find="P_l = lifts(G, P)")
    got = answers(solve_text(text, "lift.dyn"))
    assert got["P_l"].value == pytest.approx(10 * G / math.sin(math.radians(60)), rel=1e-9)


def test_a_push_up_on_a_hanging_block_slackens_its_cord_at_m_g():
    # T = m g − P = 0 → P = m g = 49.05 N.
    text = """\
given:
  m = 5 kg
  P = 20 N
scene:
  body block: particle, mass m, at (0, 0)
  cord T: block at G, up, fixed
  force P on block at G: up
  gravity
find: P_0 = slack(T, P)
"""
    assert answers(solve_text(text, "hang.dyn"))["P_0"].value == pytest.approx(5 * G)


def test_a_threshold_names_an_element_of_the_right_kind_and_a_load():
    with pytest.raises(SpecError, match="'G' is not what tips needs") as error:
        solve_text(BLOCK.format(find="x = tips(G, P)"), "b.dyn")
    assert (error.value.position.line, error.value.position.column) == (12, 7)
    with pytest.raises(SpecError, match="'Q' is not a given or load"):
        solve_text(BLOCK.format(find="x = slips(G, Q)"), "b.dyn")
    with pytest.raises(SpecError, match="takes two names"):
        solve_text(BLOCK.format(find="x = slips(G)"), "b.dyn")
