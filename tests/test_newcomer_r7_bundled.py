"""The newcomer's round-7 specs bundled as they were written, each against its own hand
derivation (the answers: key in the file), in every mode."""

from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file
from dynsolve.system import SolveOptions

SCENES = Path(__file__).parent.parent / "problems" / "scenes"

# rod: α = 3 g/(2 L) = 12.2625 rad/s² cw, O_y = m g/4 = 9.81 N; cylinder: a = (2/3) g sin30
# = 3.27 m/s², F = m g sin30/3 = 16.35 N; sliding fridge: P = (b/2 − μk h/2) m g/(d − h/2)
# = 287.76 N (the derivations are in the files)
BUNDLED = ["rod_released_horizontal", "cylinder_rolls_down_incline", "fridge_sliding_tips"]


@pytest.mark.parametrize("mode", ["exact", "numeric", "auto"])
@pytest.mark.parametrize("name", BUNDLED)
def test_the_bundled_newcomer_spec_meets_its_hand_key(name, mode):
    solution = solve_file(SCENES / f"{name}.dyn", SolveOptions(mode=mode, time_budget=60))
    assert solution.key and all(k.passed for k in solution.key)
    assert solution.passed
