"""A signed answer keyed with a direction word reads as the key does (newcomer report: a 3D
bearing reaction printed "A_y −2251 N down", a double negative).

The rotor of docs/scene-mode.md (body axes = scene axes, shaft along z, bearings at
z = ∓a, no gravity): Ḣ_G = ω × H_G = (I_yz ω², −I_zx ω², 0), so by hand
A_y = I_yz ω²/(2a) = 0.15 · 10²/1 = 15 N (up) = −B_y and B_x = −I_zx ω²/(2a) = −10 N
(left).
"""

from __future__ import annotations

from dynsolve.pipeline import solve_text

ROTOR = """\
given:
  m = 5 kg
  I_x = 1 kg*m^2
  I_y = 1 kg*m^2
  I_z = 1.2 kg*m^2
  I_xy = 0 kg*m^2
  I_yz = 0.15 kg*m^2
  I_zx = 0.1 kg*m^2
  w = 10 rad/s
  a = 0.5 m
scene:
  body rotor: mass m, at (0, 0, 0)
  inertia rotor: I_x, I_y, I_z, products I_xy, I_yz, I_zx
  rotates rotor: about (0, 0, 1), through (0, 0, 0), omega w
  bearing A: at (0, 0, -a), thrust
  bearing B: at (0, 0, a), journal
find: A_y [N], B_y [N], B_x [N]
answers:
  A_y = 15 N +- 0.01% up
  B_y = 15 N +- 0.01% down
  B_x = 10 N +- 0.01% left
"""


def test_a_keyed_signed_answer_is_a_magnitude_with_its_word():
    solution = solve_text(ROTOR, "rotor.dyn")
    rows = {a.name: a for a in solution.answers}
    assert (rows["A_y"].shown, rows["A_y"].direction) == ("15.0 N", "up")
    assert (rows["B_y"].shown, rows["B_y"].direction) == ("15.0 N", "down")
    assert (rows["B_x"].shown, rows["B_x"].direction) == ("10.0 N", "left")
    details = {c.name: c.detail for c in solution.checks}
    assert "got 15.00 N down" in details["answer B_y"] and "-15" not in details["answer B_y"]
    assert not any(c.failed for c in solution.checks)
