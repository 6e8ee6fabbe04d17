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
