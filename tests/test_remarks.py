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
