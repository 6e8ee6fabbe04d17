"""A travel of unknown extent up an incline rising to the left (newcomer round 5, regression).

A cylinder rolling up a 15° incline that rises to the left, `travel cyl: by d, angle phi,
stops`: the sense of the motion toward state 2 was decided from v·Δr_G = d·(…) with d
unknown, so it was refused ("cannot tell which way the scene moves toward state 2").
Hand (Hibbeler 18.x style): T1 = ¾ m v₁² = m g d sin 15°, d = 3 v₁²/(4 g sin 15°).
"""

import math
from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file
from dynsolve.system import SolveOptions

PROBLEM = (
    Path(__file__).resolve().parent.parent / "problems/scenes/cylinder_rolls_up_incline_stops.dyn"
)


@pytest.mark.parametrize("mode", ["exact", "numeric", "auto"])
def test_a_cylinder_rolling_up_a_left_rising_incline_stops(mode: str) -> None:
    solution = solve_file(PROBLEM, SolveOptions(mode=mode))
    (d,) = [float(a.value) for a in solution.answers]
    assert d == pytest.approx(3 * 3**2 / (4 * 9.81 * math.sin(math.radians(15))), rel=1e-9)
    assert solution.passed
