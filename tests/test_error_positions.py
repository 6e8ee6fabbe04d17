"""Errors point at the line that caused them, not at 1:1 (newcomer report): a linkage that
can be assembled two ways points at the bar that names the joint, a work–energy scene with
too many degrees of freedom at its travel line."""

from __future__ import annotations

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text

FOUR_BAR = """\
given:
  d = 0.6 m
  L_AB = 0.2 m
  L_BC = 0.5 m
  L_CD = 0.4 m
  theta = 60 deg
  w = 4 rad/s
scene:
  point A: (0, 0)
  point D: (d, 0)
  bar AB: A to B, length L_AB, angle theta
  bar BC: B to C, length L_BC
  bar CD: C to D, length L_CD
  omega AB: w cw
find: w_BC = omega(BC)
"""

FREE_BAR = """\
given:
  m = 2 kg
  L = 1 m
  h = 0.5 m
scene:
  body bar: mass m, rod L, at (0, 0)
  gravity
  travel bar: by h, down
find: v = speed(bar)
"""


def test_a_linkage_assembled_two_ways_points_at_the_bar_naming_the_joint():
    with pytest.raises(SpecError) as info:
        solve_text(FOUR_BAR, "fourbar.dyn")
    assert "can be assembled 2 ways" in info.value.message
    assert info.value.position.line == 12  # 'bar BC: B to C', where C is first named


def test_too_many_degrees_of_freedom_for_work_energy_points_at_the_travel():
    with pytest.raises(SpecError) as info:
        solve_text(FREE_BAR, "free.dyn")
    assert "degrees of freedom" in info.value.message
    assert info.value.position.line == 8


def test_a_start_read_off_a_figure_is_told_how_far_it_is_from_the_circle():
    # newcomer report: G at (0.513, 1.40954) m, 1.5e-5 m inside R = 1.5 m, got only
    # "needs a circular path through G"; |G| = √(0.513² + 1.40954²) = 1.499991 m (hand)
    from pathlib import Path

    text = (
        (Path(__file__).parent.parent / "problems" / "scenes")
        .joinpath("cylinder_block_released_off_top.dyn")
        .read_text()
    )
    text = text.replace("at (R*sin(phi_0), R*cos(phi_0))", "at (x_0, y_0)")
    text = text.replace("  phi_0 = 20 deg", "  phi_0 = 20 deg\n  x_0 = 0.513 m\n  y_0 = 1.40954 m")
    with pytest.raises(SpecError) as info:
        solve_text(text, "off.dyn")
    assert "1.499991 from its centre" in info.value.message and "R = 1.5" in info.value.message
