"""Thresholds: the size of a load that puts an assumption at its limit — tips(C, P),
slips(C, P), slack(T, P), lifts(A, P) — each from a hand derivation."""

import math
from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text
from dynsolve.system import SolveOptions

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


MODES = ["exact", "numeric", "auto"]

BLOCK_ON_FLOOR = """\
given:
  m = 10 kg
  b = {b} m
  h = 1 m
  mu_s = 0.6
scene:
  body blk: mass m, block b by h, at (0, h/2)
  base C on blk: from (-b/2, -h/2) to (b/2, -h/2), mu_s mu_s
  gravity
find: beta = steepest(C)
"""


@pytest.mark.parametrize("mode", MODES)
def test_steepest_is_the_smaller_of_the_slip_and_tip_angles(mode):
    # newcomer r7, 27: slips at tan β = μs = 0.6 (30.96°), tips at tan β = b/h = 0.5
    # (26.565°): it tips first, and the checks are evaluated at 26.565°, not on the level
    solution = solve_file(
        SCENES / "block_steepest_tips_first.dyn", SolveOptions(mode=mode, time_budget=60)
    )
    assert solution.passed
    beta = answers(solution)["beta"].value
    assert beta == pytest.approx(math.degrees(math.atan(0.5)), rel=1e-6)  # shown in deg
    steps = " ".join(s.heading + " " + s.note for s in solution.steps)
    assert "tips" in steps
    at_slope = [c for c in solution.checks if "at β = 26.57°" in c.name]
    assert len(at_slope) == 2 and all(c.passed for c in at_slope)


@pytest.mark.parametrize("mode", MODES)
def test_a_wide_block_still_slips_first(mode):
    # b = 2 m, h = 1 m: tips at tan β = 2 (63.4°), slips at tan β = 0.6 (30.96°) first
    solution = solve_text(BLOCK_ON_FLOOR.format(b=2), "wide.dyn", SolveOptions(mode=mode))
    beta = answers(solution)["beta"].value
    assert beta == pytest.approx(math.degrees(math.atan(0.6)), rel=1e-6)
    assert "slips" in " ".join(s.heading for s in solution.steps)


FRIDGE = """\
given:
  m = 160 kg
  b = 0.8 m
  h = 1.8 m
  d = 1.5 m
  P = 250 N
  mu_s = {mu_s}
{mu_k}
scene:
  body fridge: mass m, block b by h, at (0, h/2)
  base C on fridge: from (-b/2, -h/2) to (b/2, -h/2), mu_s mu_s{kinetic}
  force P on fridge at (-b/2, d - h/2): right
  gravity
find: {find}
"""


def fridge(mu_s: float, find: str, mu_k: bool = True) -> str:
    return FRIDGE.format(
        mu_s=mu_s,
        mu_k="  mu_k = 0.2" if mu_k else "",
        kinetic=", mu_k mu_k" if mu_k else "",
        find=find,
    )


@pytest.mark.parametrize("mode", MODES)
def test_a_crate_that_slides_first_tips_at_the_sliding_load(mode):
    # newcomer r7, 29 (hand derivation in problems/scenes/fridge_slides_then_tips.dyn):
    # static tipping (b/2) m g/d = 418.56 N > μs m g = 392.4 N: it slides first; sliding, it tips at
    # P = m g (b/2 − μk h/2)/(d − h/2) = 575.52 N
    solution = solve_file(
        SCENES / "fridge_slides_then_tips.dyn", SolveOptions(mode=mode, time_budget=60)
    )
    assert solution.passed
    assert answers(solution)["P_tip"].value == pytest.approx(1569.6 * 0.22 / 0.6, rel=1e-6)
    details = " ".join(c.detail for c in solution.checks)
    assert "it slides first, at P = 392.4" in details
    steps = [s for s in solution.steps if s.heading.startswith("P_tip")]
    assert steps and "slides" in steps[0].note
    # P_tip = m g (b − μk h)/(2d − h) depends on m: no "the mass cancels" remark for it
    assert not any("P_tip" in r.text for r in solution.remarks)


@pytest.mark.parametrize("mode", MODES)
def test_a_crate_that_tips_at_rest_checks_friction_at_the_tipping_load(mode):
    # μs = 0.3: at rest F = P and x N = P d, so it tips at x = b/2: P = (b/2) m g/d
    # = 418.56 N < μs m g = 470.9 N (no slip there)
    solution = solve_text(fridge(0.3, "P_tip = tips(C, P) [N]"), "f.dyn", SolveOptions(mode=mode))
    assert answers(solution)["P_tip"].value == pytest.approx(0.4 * 1569.6 / 1.5, rel=1e-6)
    check = next(c for c in solution.checks if "no slip at the tipping load" in c.name)
    assert check.passed and "470.9" in check.detail


@pytest.mark.parametrize("mode", MODES)
def test_sliding_first_without_mu_k_is_refused_with_the_reason(mode):
    solution = solve_text(
        fridge(0.25, "P_tip = tips(C, P) [N]", mu_k=False), "f.dyn", SolveOptions(mode=mode)
    )
    assert answers(solution)["P_tip"].value is None
    refused = next(c for c in solution.checks if "refused" in c.name)
    assert not refused.passed and "give mu_k" in refused.detail


@pytest.mark.parametrize("mode", MODES)
def test_slips_is_refused_where_the_body_tips_before_it_slips(mode):
    # μs = 0.3: it would slip at μs m g = 470.9 N, but tips at rest at (b/2) m g/d = 418.56 N
    solution = solve_text(fridge(0.3, "P_s = slips(C, P) [N]"), "f.dyn", SolveOptions(mode=mode))
    assert answers(solution)["P_s"].value is None
    refused = next(c for c in solution.checks if "refused" in c.name)
    assert not refused.passed and "tips before it slips" in refused.detail


@pytest.mark.parametrize("mode", MODES)
def test_slips_checks_tipping_at_the_slip_load(mode):
    # μs = 0.25: slips at μs m g = 392.4 N; there x = P d/(m g) = 0.375 m < b/2 = 0.4 m
    solution = solve_text(fridge(0.25, "P_s = slips(C, P) [N]"), "f.dyn", SolveOptions(mode=mode))
    assert answers(solution)["P_s"].value == pytest.approx(392.4, rel=1e-6)
    check = next(c for c in solution.checks if "no tipping on base C at the slip load" in c.name)
    assert check.passed


@pytest.mark.parametrize("mode", MODES)
def test_a_given_push_that_slides_the_crate_does_not_set_the_regime_of_its_threshold(mode):
    # μs = 0.3, P = 500 N > μs m g = 470.9 N: the scene as given slides, but the tipping
    # load lies below: at rest (F = P, x N = P d) it tips at (b/2) m g/d = 418.56 N,
    # where it does not slip (418.56 < 470.9); and it has no slip load (tips first)
    text = fridge(0.3, "P_tip = tips(C, P) [N], P_s = slips(C, P) [N]").replace(
        "P = 250 N", "P = 500 N"
    )
    found = answers(solve_text(text, "f.dyn", SolveOptions(mode=mode)))
    assert found["P_tip"].value == pytest.approx(0.4 * 1569.6 / 1.5, rel=1e-6)
    assert found["P_s"].value is None
