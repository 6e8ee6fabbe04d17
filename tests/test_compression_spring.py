"""Springs a body rests against, not fixed to: `spring …, compression only` (newcomer
report: "a spring that launches a block keeps pulling it back afterwards").

Hand derivations, cited in each bundled file:
- spring_pushes_up_rough_incline: ½ m v² = ½ k δ² − m g s sin 30° − μk m g cos 30° s
  = 16 − 4.905 − 1.69910 J → v = 3.06527 m/s (an attached spring would pull back: −20 J);
- spring_shoots_ball_up: h = k δ² / (2 m g) = 1.01937 m (the spring clear at the top);
- bumper_spring_compression: x = v √(m/k) = 0.15 m, d = 0.2 + 0.15 = 0.35 m (one root: the
  block does not pass through the wall the bumper is fixed to).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

SCENES = Path(__file__).parent.parent / "problems" / "scenes"


def test_a_spring_the_block_leaves_stops_pushing_at_its_free_length():
    solution = solve_file(SCENES / "spring_pushes_up_rough_incline.dyn")
    (v,) = solution.answers
    work = 16 - 2 * 9.81 * 0.5 * 0.5 - 0.2 * 2 * 9.81 * math.cos(math.pi / 6) * 0.5
    assert v.value == pytest.approx(math.sqrt(work), rel=1e-12)
    spring = next(t for t in solution.energy if t.name == "U_S")
    assert spring.formula == "k*δ^2/2"  # ½ k δ², as by hand (no |L_0 − δ|)


def test_a_ball_rises_past_the_spring_that_shot_it():
    solution = solve_file(SCENES / "spring_shoots_ball_up.dyn")
    (h,) = solution.answers
    assert h.value == pytest.approx(400 * 0.1**2 / (2 * 0.2 * 9.81), rel=1e-12)
    (clear,) = [a for a in solution.assumptions if a.name.startswith("spring S")]
    assert clear.name == "spring S clear at state 2" and clear.holds


def test_a_bumper_has_one_compression_not_a_root_through_the_wall():
    solution = solve_file(SCENES / "bumper_spring_compression.dyn")
    d, x = solution.answers
    assert d.value == pytest.approx(0.2 + 3 * math.sqrt(5 / 2000), rel=1e-12)
    assert x.value == pytest.approx(0.15, rel=1e-12)
    assert not any(c.failed for c in solution.checks)  # no "several roots remain"


def test_a_spring_is_tension_only_or_compression_only_not_both():
    text = (SCENES / "bumper_spring_compression.dyn").read_text()
    text = text.replace("compression only", "compression only, tension only")
    with pytest.raises(SpecError):
        solve_text(text, "both.dyn")


@pytest.mark.parametrize("k", [-2, 8])
def test_the_simulation_finds_the_top_at_any_scale(k):
    # regression (DYNSOLVE_SLOW scale sweep): scaled by 10^-2 or 10^8 the simulation check
    # took one step over the ball's whole flight, past its top and back onto the spring,
    # and missed the top; h scales as 10^k (h = k δ²/(2 m g), every given scaled)
    from dynsolve.pipeline import solve_spec
    from dynsolve.scaling import scale_spec
    from dynsolve.spec.parser import parse_file

    solution = solve_spec(scale_spec(parse_file(SCENES / "spring_shoots_ball_up.dyn"), k))
    (h,) = solution.answers
    assert h.value == pytest.approx(1.0193679918 * 10**k, rel=1e-9)
    assert not any(c.failed for c in solution.checks), [c for c in solution.checks if c.failed]
