"""A bar or a slider's block given by its weight (FPS linkages; newcomer report: `weight` was
accepted on a body but refused on a bar): m = W/g, the same problem as with `mass W/g`."""

from __future__ import annotations

from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text

SPEC = """\
units: FPS
given:
  L_AB = 0.25 ft
  L_BC = 0.75 ft
  W_BC = 3 lbf
  W_C = 2 lbf
  theta = 60 deg
  omega_0 = 20 rad/s
scene:
  point A: (0, 0)
  bar AB: A to B, length L_AB, angle theta
  bar BC: B to C, length L_BC, weight W_BC
  slider C: along right, through A, weight W_C
  joint C: near (L_BC, 0)
  omega AB: omega_0 cw
  alpha AB: 0
  couple M on AB: ccw
  gravity
find: M, N_C
"""


def test_a_weight_is_a_mass_of_w_over_g():
    by_weight = solve_text(SPEC, "weights.dyn")
    by_mass = solve_text(
        SPEC.replace("weight W_BC", "mass W_BC/g").replace("weight W_C", "mass W_C/g"),
        "masses.dyn",
    )
    assert not any(c.failed for c in by_weight.checks)
    for a, b in zip(by_weight.answers, by_mass.answers, strict=True):
        assert a.value == pytest.approx(b.value, rel=1e-12) and a.direction == b.direction
    assert by_weight.answers[0].value > 0


def test_a_bar_with_a_mass_and_a_weight_is_refused(tmp_path: Path):
    with pytest.raises(SpecError) as info:
        solve_text(SPEC.replace("weight W_BC", "weight W_BC, mass W_BC/g"), "both.dyn")
    assert "a mass and a weight" in info.value.message
