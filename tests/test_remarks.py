"""Remarks on the answers: a mass that cancels (issue 12 part 4, "one-line remarks where a
cancelled quantity tells the reader something"). Hand results: a pendulum's speed at the
bottom, √(2 g L (1 − cos θ)), holds for any bob, while the cord's tension m g (3 − 2 cos θ)
does not; a disk rolling down an incline accelerates at (2/3) g sin β whatever its mass
(seed notes, the incline example); the drum's α depends on both masses.
"""

import json
from pathlib import Path

from dynsolve.pipeline import solve_file
from dynsolve.render.json import render_json
from dynsolve.render.latex import render_latex
from dynsolve.render.markdown import render_markdown
from dynsolve.system import SolveOptions

PROBLEMS = Path(__file__).parent.parent / "problems"


def test_the_speed_of_a_pendulum_holds_for_any_bob_but_its_tension_does_not():
    solution = solve_file(PROBLEMS / "stages" / "pendulum_tension_bottom.dyn")
    (remark,) = solution.remarks
    assert remark.answers == ("v_2",) and remark.masses == ("m",)
    assert remark.text == "v_2 does not depend on m: the mass cancels"


def test_a_disk_rolling_down_an_incline_accelerates_whatever_its_mass():
    solution = solve_file(PROBLEMS / "seed" / "gpm_seed_incline_threshold.dyn")
    assert any("a_G" in r.answers and "m" in r.masses for r in solution.remarks)


def test_no_remark_where_every_mass_matters():
    assert solve_file(PROBLEMS / "seed" / "fa_hib_drum.dyn").remarks == ()


def test_numeric_mode_makes_no_remark_from_formulas_it_did_not_derive():
    # a block solved in floats has no letters left: a missing mass there says nothing
    path = PROBLEMS / "stages" / "pendulum_tension_bottom.dyn"
    assert solve_file(path, SolveOptions(mode="numeric")).remarks == ()


def test_every_renderer_shows_the_remark():
    solution = solve_file(PROBLEMS / "stages" / "pendulum_tension_bottom.dyn")
    assert json.loads(render_json(solution))["remarks"] == [
        "v_2 does not depend on m: the mass cancels"
    ]
    assert "*Remark:* v\\_2 does not depend on m" in render_markdown(solution)
    assert "\\textit{Remark:} $v_{2}$ does not depend on $m$: the mass cancels" in (
        render_latex(solution)
    )


# ---- limit cases. Hand results: a block leaving a smooth dome of radius R after a start
# speed v_1 at the top leaves at cos θ = 2/3 + v_1²/(3 g R) (problems/scenes/
# dome_contact_lost.dyn): as v_1 → 0 it leaves at acos(2/3) = 48.19°, whatever R and g,
# R/3 below the top. A bob given v_1 at the bottom of its cord goes slack only for
# 2 g L < v_1² < 5 g L: its slack angle's formula has a limit at v_1 → 0 that is no case
# of the problem at all (the bob never leaves the bottom), and must not be remarked.


def test_a_dome_started_nearly_from_rest_is_left_at_cos_two_thirds_whatever_its_radius():
    from dynsolve.results import LimitRemark

    solution = solve_file(PROBLEMS / "scenes" / "dome_contact_lost.dyn")
    limits = [r for r in solution.remarks if isinstance(r, LimitRemark)]
    theta = next(r for r in limits if r.answer == "theta")
    assert (theta.given, theta.case, theta.formula) == ("v_1", "nearly from rest", "acos(2/3)")
    assert theta.whatever == ("R", "g")
    assert theta.value.startswith("48.2")  # acos(2/3) = 48.19°
    h = next(r for r in limits if r.answer == "h")
    assert (h.formula, h.direction) == ("R/3", "down") and h.value == "0.667 m"
    assert h.text == "as v_1 → 0 (nearly from rest), h → R/3 = 0.667 m down, whatever g"


def test_a_limit_outside_the_problems_own_case_is_not_remarked():
    # the bob at 1 m at 6 m/s goes slack (2 g L = 19.6 < 36 < 49.1 = 5 g L); the formula's
    # v_1 → 0 limit (acos(2/3)) is confirmed by no re-solve: the bob would stay at the bottom
    from dynsolve.results import LimitRemark

    solution = solve_file(PROBLEMS / "scenes" / "bob_cord_slack.dyn")
    assert not [r for r in solution.remarks if isinstance(r, LimitRemark)]


def test_a_limit_of_a_friction_coefficient_is_nearly_smooth():
    # block_bounce_slides: on a nearly smooth floor the block keeps v_2 = v_1 = 6 m/s
    from dynsolve.results import LimitRemark

    solution = solve_file(PROBLEMS / "stages" / "block_bounce_slides.dyn")
    v_2 = next(r for r in solution.remarks if isinstance(r, LimitRemark) and r.answer == "v_2")
    assert (v_2.given, v_2.case, v_2.formula, v_2.value) == (
        "mu_k", "nearly smooth", "v_1", "6.00 m/s"
    )  # fmt: skip
    assert "\\textit{Remark:} as $\\mu_{k}$ $\\to$ 0 (nearly smooth), $v_{2}$ $\\to$ $v_{1}$" in (
        render_latex(solution)
    )


# ---- false remarks (issue 25 item 8): a remark is printed only where the derivation used
# the mass and a re-solve with the mass halved and doubled bears it out.


def test_a_mass_of_another_body_never_entered_and_is_not_said_to_cancel():
    # pile_driver, stage 1: m_r g h = ½ m_r v_2² gives v_2 = √(2 g h): m_r cancels, but the
    # pile's m_p is in no equation of the fall; T_2 = ½ m_r v_2² holds m_r and never saw m_p
    solution = solve_file(PROBLEMS / "stages" / "pile_driver.dyn")
    assert [(r.answers, r.masses) for r in solution.remarks] == [(("v_2",), ("m_r",))]


def test_only_the_mass_that_cancels_is_remarked_in_a_two_body_scene():
    # pendulum_block: v_2 = √(2 g L (1 − cos θ)) from the bob's swing alone: m_A cancels;
    # the block's m_B enters only the impact, after v_2; v_A = (m_A − e m_B) v_2/(m_A + m_B)
    # and v_B hold both masses
    solution = solve_file(PROBLEMS / "stages" / "pendulum_block.dyn")
    assert [(r.answers, r.masses) for r in solution.remarks] == [(("v_2",), ("m_A",))]


def test_a_mass_that_sets_a_slip_threshold_is_not_said_to_cancel():
    # crate_push_too_weak: at rest F_C = P = 90 N for m = 50 kg (μs m g = 147 N > 90 N),
    # but a 25-kg crate slides (μs m g = 73.6 N < 90 N) and F_C = μk m g = 49.05 N: F_C
    # depends on m through the slip threshold
    solution = solve_file(PROBLEMS / "scenes" / "crate_push_too_weak.dyn")
    assert not [r for r in solution.remarks if "F_C" in getattr(r, "answers", ())]


def test_a_kinematic_answer_is_not_said_to_be_free_of_masses_it_never_used():
    # gears_couple_needed: α_B follows from the gear ratio; no equation of it holds a mass
    solution = solve_file(PROBLEMS / "linkages" / "gears_couple_needed.dyn")
    assert not [r for r in solution.remarks if "alpha_B" in getattr(r, "answers", ())]


CONSTANT_SPEED = """\
given:
  m = 1200 kg
  v = 10 m/s
  c = 50 m
scene:
  path road: y = -x^2/(2*c)
  body car: particle, mass m, at (0, 0)
  moves car: along road, speed v, constant
  gravity
find: N = N_road [N]
"""


def test_a_constant_speed_is_no_start_and_gets_no_from_rest_remark():
    # the car over the hump's top (radius of curvature c): N = m (g − v²/c)
    # = 1200 (9.81 − 100/50) = 9372 N, → m g as v → 0 whatever c; but v is the speed the car
    # keeps, not one it starts from: "nearly from rest" would be a false reading
    from dynsolve.pipeline import solve_text
    from dynsolve.results import LimitRemark

    solution = solve_text(CONSTANT_SPEED)
    assert abs(solution.answers[0].value - 9372) < 1e-6
    assert not [r for r in solution.remarks if isinstance(r, LimitRemark)]


def test_a_spinning_disk_whose_centre_starts_at_rest_is_not_from_rest():
    # disk_backspin_rolls: v_1 → 0 leaves the disk spinning at ω_1 = 10 rad/s: not at rest
    from dynsolve.results import LimitRemark

    solution = solve_file(PROBLEMS / "scenes" / "disk_backspin_rolls.dyn")
    assert not [r for r in solution.remarks if isinstance(r, LimitRemark) and r.given == "v_1"]


def test_a_scenes_starting_velocity_is_still_from_rest():
    # bumper_spring_compression: d = gap + v_1 √(m/k) → gap = 0.2 m as v_1 → 0, whatever
    # k and m; v_1 is the block's starting velocity, and the block has no spin
    from dynsolve.results import LimitRemark

    solution = solve_file(PROBLEMS / "scenes" / "bumper_spring_compression.dyn")
    (remark,) = [r for r in solution.remarks if isinstance(r, LimitRemark)]
    assert remark.text == "as v_1 → 0 (nearly from rest), d → gap = 0.200 m, whatever k and m"
