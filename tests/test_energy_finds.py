"""Finds V(B, k) (potential energy of weights and springs), power(F) at the instant, and
F_avg(B, t_c) (an impact's impulse over a given contact time), from hand derivations."""

import math

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text

G = 9.81

BOUNCE = """\
given:
  m = 0.5 kg
  h = 2 m
  e = 0.6
  t_c = 0.002 s
scene:
  body ball: particle, mass m, at (0, h)
  gravity
  travel ball: by h, down
  impact ball with ground: e e, line down
find: {find}
"""

DISK = """\
given:
  m = 10 kg
  r = 0.3 m
  v_1 = 5 m/s
  P = 20 N
  M = 4 N*m
scene:
  point C: (0, 0)
  body disk: mass m, disk r, at (0, r)
  rolls disk at C: mu_s 0.5
  velocity disk: v_1, right
  force P on disk at (0, r): right
  couple M on disk: cw
  gravity
find: {find}
"""


def answers(text: str) -> dict:
    return {a.name: a for a in solve_text(text, "e.dyn").answers}


def test_potential_energy_of_the_ball_before_and_after_its_fall():
    # V = m g y with the datum at y = 0: V_1 = 0.5·9.81·2 = 9.81 J, V_2 = 0.
    got = answers(BOUNCE.format(find="V_1 = V(ball, 1), V_2 = V(ball, 2)"))
    assert got["V_1"].value == pytest.approx(9.81, rel=1e-12)
    assert got["V_2"].value == pytest.approx(0.0, abs=1e-12)
    assert got["V_1"].unit == "J"


def test_average_force_of_the_bounce_over_its_contact_time():
    # v_2 = √(2 g h) = 6.2642 m/s down, v_3 = e v_2 up: J = m (1 + e) v_2 = 5.0114 N·s up,
    # the net force J / t_c = 2505.7 N up; the floor's push (contact force) also holds the
    # weight over t_c: F_avg = J / t_c + m g = 2505.7 + 4.905 = 2510.6 N up (hand derivation).
    got = answers(BOUNCE.format(find="F = F_avg(ball, t_c), F_net = F_net_avg(ball, t_c)"))
    net = 0.5 * 1.6 * math.sqrt(2 * G * 2) / 0.002
    assert got["F_net"].value == pytest.approx(net, rel=1e-12)
    assert got["F"].value == pytest.approx(net + 0.5 * G, rel=1e-12)
    assert got["F"].direction == "up" and got["F_net"].direction == "up"


def test_f_avg_needs_a_given_time():
    with pytest.raises(SpecError, match="is not a time"):
        answers(BOUNCE.format(find="F = F_avg(ball, h)"))
    with pytest.raises(SpecError, match="F_avg takes the body and the contact time"):
        answers(BOUNCE.format(find="F = F_avg(ball)"))


def test_power_of_forces_and_couples_on_a_rolling_disk():
    # Rolling right at v = 5 m/s: ω = v/r = 16.67 rad/s cw; the top point moves at 2 v, so
    # P·v_top = 20·10 = 200 W; the cw couple turns with ω: M ω = 4·16.67 = 66.67 W; the
    # contact point is at rest, so friction does no work: 0 W (hand derivation).
    got = answers(DISK.format(find="p_P = power(P), p_M = power(M), p_F = power(F_C)"))
    assert got["p_P"].value == pytest.approx(200.0, rel=1e-12)
    assert got["p_M"].value == pytest.approx(4 * 5 / 0.3, rel=1e-12)
    assert got["p_F"].value == pytest.approx(0.0, abs=1e-12)
    assert got["p_P"].unit == "W"


def test_potential_energy_at_the_instant_and_a_power_typo():
    # V = m g y_G = 10·9.81·0.3 = 29.43 J (datum y = 0).
    assert answers(DISK.format(find="V = V(disk)"))["V"].value == pytest.approx(29.43)
    with pytest.raises(SpecError, match=r"not a force or couple .*forces: F_C, M, N_C, P, W"):
        answers(DISK.format(find="p = power(Q)"))


def test_a_spring_stores_half_k_s_squared():
    # The block hangs on a spring from (0, 0): length 0.5 m, unstretched 0.3 m, s = 0.2 m:
    # ½ k s² = ½ 200 (0.04) = 4 J; weight: m g y = 2·9.81·(−0.5) = −9.81 J; V = −5.81 J.
    text = """\
given:
  m = 2 kg
  k = 200 N/m
  L_0 = 0.3 m
  y = 0.5 m
scene:
  point O: (0, 0)
  body block: particle, mass m, at (0, -y)
  spring S: block at G to O, k k, unstretched L_0
  gravity
find: V = V(block)
"""
    assert answers(text)["V"].value == pytest.approx(4 - 9.81, rel=1e-12)
