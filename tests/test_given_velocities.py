"""Velocities given for a connected scene must agree with its cords (newcomer round 5).

Block A on a table, a cord over a pulley (a disk pinned at O) to a hanging block B. With A
moving left at 2 m/s and the pulley turning ccw at v/r, the cord lifts B: B moves up at
2 m/s. A spec saying B moves *down* was solved as if it moved up, every check green (the
answer ignored a given); it is now refused. Hand work–energy for the consistent scene,
B rising 0.2 m: T1 = ½(10 + 6)2² + ½(½·4·0.1²)20² = 36 J, U = −6 g 0.2 − 0.2·10 g 0.2
= −15.696 J, T2 = ½(10 + 6 + 4/2) v² = 9 v² = 20.304 J: v = 1.501999 m/s.
"""

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text

SCENE = """given:
  m_A = 10 kg
  m_B = 6 kg
  m_p = 4 kg
  r = 0.1 m
  mu_k = 0.2
  v_1 = 2 m/s
  s = 0.2 m
  D = 1 m
scene:
  point O: (0, 0)
  body pulley: mass m_p, disk r, at (0, 0)
  body A: particle, mass m_A, at (-D, r)
  body B: particle, mass m_B, at (r, -D)
  point P on pulley: (0, r)
  point Q on pulley: (r, 0)
  pin pulley at O
  contact A at G: normal up, mu_k mu_k
  cord T_A: pulley at P to A, left
  cord T_B: pulley at Q to B, down
  velocity A: v_1, left
  velocity B: v_1, {b_moves}
  omega pulley: v_1/r ccw
  gravity
  travel B: by s, up
find: v = speed(B) [m/s]
"""


def test_consistent_velocities_are_solved() -> None:
    solution = solve_text(SCENE.format(b_moves="up"))
    (v,) = [float(a.value) for a in solution.answers]
    assert v == pytest.approx(1.501999, rel=1e-6)
    assert solution.passed


def test_velocities_that_stretch_a_cord_are_refused() -> None:
    with pytest.raises(SpecError) as info:
        solve_text(SCENE.format(b_moves="down"))
    assert "stretch or slacken the cord T_B" in info.value.message
    assert info.value.position is not None and info.value.position.line > 1
