"""Answers that must not change when a problem is restated at another scale (issue 10, item 5)."""

import math
from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file

PLATFORM = """\
units: FPS
given:
  W      = {W} lb
  l      = {l} ft
  M      = {M} ft*lb
  theta2 = 60 deg
  h      = {h} ft
  g      = {g} ft/s^2
scene:
  point A: (0, 0)
  point C: (0, -h)
  body platform: weight W, at (l, -h/2)
  point B on platform: (0, h/2)
  point D on platform: (0, -h/2)
  link AB: platform at B to A
  link CD: platform at D to C
  motion platform: translation
  couple M on AB: ccw
  gravity
  travel AB: turns theta2 ccw
find: omega = omega2(AB)
"""


@pytest.mark.parametrize("k", [-8, -4, 0, 4, 8])
def test_the_platform_keeps_gravitys_work_at_any_scale(tmp_path: Path, k: int) -> None:
    # The seed platform (rwe_seed_platform) with lengths and g scaled by s = 10^k and the mass
    # kept: W = m g and M (a force times a length) scale by s and s², ω does not change.
    # By hand: M θ₂ − W l sin θ₂ = ½ (W/g) (l ω)²  with the seed's numbers
    #   942.48 − 692.82 = 49.689 ω²  ->  ω = 2.2415 rad/s.
    # Regression: at s = 1e-8 gravity's work fell under an absolute 1e-12 and was dropped as
    # "G moves across the weight", giving ω = 4.355 rad/s with every check green.
    s = 10.0**k
    text = PLATFORM.format(W=200 * s, l=4 * s, M=900 * s * s, h=2 * s, g=32.2 * s)
    path = tmp_path / "platform.dyn"
    path.write_text(text)
    solution = solve_file(path)
    (answer,) = solution.answers
    work = 900 * math.pi / 3 - 200 * 4 * math.sin(math.pi / 3)
    expected = math.sqrt(work / (0.5 * (200 / 32.2) * 16))
    assert answer.value == pytest.approx(expected, rel=1e-9)
    assert solution.passed
