"""A link at an instant when its ends move: |r| fixed gives r·a + v·v = 0, so the end's
acceleration along it is v²/ℓ toward the fixed point, not zero. Regression: a bob moving
at v at the bottom of its cord got a_Gy = 0 and the tension m g with every check green.

Hand results (g = 9.81 m/s²): at the bottom, T − m g = m v²/L; with the cord horizontal
(bob at (L, 0) moving up at v), T = m v²/L and a_y = −g; two particles on a light rod
spinning freely about their centre have the rod's tension m v²/(ℓ/2) each.
"""

from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

G = 9.81
BOB = """\
given:
  m = 2 kg
  L = 1.2 m
  v = 3 m/s
scene:
  point O: (0, 0)
  body bob: particle, mass m, at {at}
  link cord: bob at G to O
  velocity bob: v, {way}
  gravity
find: T = cord, a = a_G(bob)
"""


def solve(tmp_path: Path, text: str):
    path = tmp_path / "link.dyn"
    path.write_text(text)
    return solve_file(path)


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def test_a_bob_moving_at_the_bottom_pulls_its_cord_by_m_g_plus_m_v2_over_L(tmp_path):
    # hand: T = m (g + v²/L) = 2 (9.81 + 9/1.2) = 34.62 N; a = v²/L = 7.5 m/s² up
    got = answers(solve(tmp_path, BOB.format(at="(0, -L)", way="right")))
    assert got["T"].value == pytest.approx(2 * (G + 9 / 1.2), rel=1e-12)
    assert got["a"].value == pytest.approx(7.5, rel=1e-12) and got["a"].direction == "up"


def test_with_the_cord_horizontal_the_tension_is_m_v2_over_L_alone(tmp_path):
    # hand: T = m v²/L = 15 N toward O; a = (−v²/L, −g) = (−7.5, −9.81), |a| = 12.349 m/s²
    got = answers(solve(tmp_path, BOB.format(at="(L, 0)", way="up")))
    assert got["T"].value == pytest.approx(2 * 9 / 1.2, rel=1e-12)
    assert got["a"].value == pytest.approx((7.5**2 + G**2) ** 0.5, rel=1e-12)


def test_a_bob_at_rest_keeps_the_old_answer(tmp_path):
    # hand: at rest at the bottom, T = m g = 19.62 N, a = 0
    text = BOB.format(at="(0, -L)", way="right").replace("  velocity bob: v, right\n", "")
    got = answers(solve(tmp_path, text.replace("  v = 3 m/s\n", "")))
    assert got["T"].value == pytest.approx(2 * G, rel=1e-12)


def test_a_velocity_along_the_link_is_refused(tmp_path):
    with pytest.raises(SpecError, match="stretch the link cord"):
        solve(tmp_path, BOB.format(at="(0, -L)", way="down"))


def test_two_masses_on_a_spinning_rod_pull_it_by_m_v2_over_half_its_length(tmp_path):
    # hand: each end moves at v = 3 m/s about the centre, radius ℓ/2 = 0.5 m:
    # the rod pulls each mass inward with m v²/(ℓ/2) = 1·9/0.5 = 18 N (no gravity)
    text = """\
given:
  m = 1 kg
  v = 3 m/s
  l = 1 m
scene:
  body A: particle, mass m, at (-l/2, 0)
  body B: particle, mass m, at (l/2, 0)
  link rod: A at G to B at G
  velocity A: v, down
  velocity B: v, up
find: F = rod
"""
    got = answers(solve(tmp_path, text))
    assert got["F"].value == pytest.approx(18.0, rel=1e-12)


def test_a_fixed_cord_that_its_body_moves_across_is_refused_with_the_link_hint(tmp_path):
    text = """\
given:
  m = 2 kg
  v = 3 m/s
scene:
  body block: particle, mass m, at (0, 0)
  cord T: block at G, up, fixed
  velocity block: v, right
  gravity
find: T
"""
    with pytest.raises(SpecError, match="write it as a link"):
        solve(tmp_path, text)
