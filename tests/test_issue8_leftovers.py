"""Regressions for issue 8's leftover bugs: a renamed contact in steepest(), the free-body
table's kinetic friction, state-1 reactions beside a stage find, a single impact's checks."""

import math

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text

G = 9.81

TWO_AT_G = """\
given:
  m = 2 kg
  d = 1 m
scene:
  body A: particle, mass m, at (0, 0)
  body B: particle, mass m, at (d, 0)
  contact A at G: normal up, {A}
  contact B at G: normal up, mu_s 0.4
  gravity
find: s = steepest({name})
"""


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def test_steepest_finds_a_renamed_contact_by_its_full_or_shared_name():
    # A block with μs = 0.4 is about to slip on a slope of atan(0.4) = 21.80° (statics).
    for text in (
        TWO_AT_G.format(A="mu_s 0.3", name="G_B"),
        TWO_AT_G.format(A="smooth", name="G"),  # the one rough contact at G
    ):
        got = answers(solve_text(text, "two.dyn"))
        assert got["s"].value == pytest.approx(math.degrees(math.atan(0.4)), rel=1e-9)


def test_steepest_of_a_shared_point_name_says_which_names_to_use():
    with pytest.raises(SpecError, match=r"several supports are at G .*G_A, G_B"):
        solve_text(TWO_AT_G.format(A="mu_s 0.3", name="G"), "two.dyn")


def test_the_free_body_table_shows_kinetic_friction_as_the_equations_write_it():
    # Spinning disk sliding right at its contact (problems/scenes/disk_spinning_slides.dyn):
    # F_C = μk N_C = 0.2 (98.1) = 19.62 N to the left, in the table and the equations alike.
    from pathlib import Path

    from dynsolve.pipeline import solve_file

    path = Path(__file__).parent.parent / "problems" / "scenes" / "disk_spinning_slides.dyn"
    solution = solve_file(path)
    (row,) = [f for body in solution.free_body for f in body.forces if f.name == "F_C"]
    assert row.kind == "friction = μk N_C"
    assert row.direction == "left" and row.value == "19.6 N"
    assert any("N_C*μ_k" in e.text for e in solution.equations)


def test_a_stage_find_in_a_single_travel_keeps_the_state_one_reactions():
    # P = 30 N pushes a 2 kg block on a smooth floor 3 m: at state 1 N = m g = 19.62 N,
    # a = P/m = 15 m/s²; T_2 = P d = 90 J, v_2 = √(2·90/2) = 9.487 m/s (hand derivation).
    text = """\
given:
  m = 2 kg
  d = 3 m
  P = 30 N
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal up, smooth
  force P on block at G: right
  gravity
  travel block: by d, right
find: v = speed(block, 2), T2 = T(block, 2), N_G, a = a_G(block)
"""
    solution = solve_text(text, "push.dyn")
    got = answers(solution)
    assert got["N_G"].value == pytest.approx(2 * G)
    assert got["a"].value == pytest.approx(15.0)
    assert got["T2"].value == pytest.approx(90.0)
    assert got["v"].value == pytest.approx(math.sqrt(90.0))
    names = {a.name for a in solution.assumptions}
    assert {"reaches state 2", "contact at G kept"} <= names


def test_a_single_impact_checks_that_the_bodies_close():
    # A at 2 m/s right, B at 5 m/s right ahead of it along the line A→B: they separate,
    # so the impact never happens: (v_A − v_B)·n = −3 < 0 must fail its check.
    text = """\
given:
  m_A = 1 kg
  m_B = 1 kg
  d = 1 m
scene:
  body A: particle, mass m_A, at (0, 0)
  body B: particle, mass m_B, at (d, 0)
  velocity A: 2 m/s, right
  velocity B: 5 m/s, right
  impact A with B: e 0.5, line right
find: v = v_after(A)
"""
    text = text.replace("2 m/s", "v_A").replace("5 m/s", "v_B")
    text = text.replace("  d = 1 m\n", "  d = 1 m\n  v_A = 2 m/s\n  v_B = 5 m/s\n")
    solution = solve_text(text, "apart.dyn")
    approach = next(a for a in solution.assumptions if a.name.startswith("approach"))
    assert not approach.holds
    assert not solution.passed


# ---- a rigid body rebounding off a fixed point (e > 0)
ROD = """\
given:
  m = 2 kg
  L = 1 m
  v_1 = 3 m/s
  e = {e}
scene:
  point P: (L/2, 0)
  body rod: mass m, rod L, at (0, 0)
  velocity rod: v_1, down
  impact rod at P: e e{line}
find: v_2 = v_after(rod), omega_2 = omega_after(rod), J_P
"""


def test_the_bundled_rod_rebounds_off_its_ledge():
    from pathlib import Path

    from dynsolve.pipeline import solve_file

    path = Path(__file__).parent.parent / "problems" / "scenes" / "rod_rebounds_off_ledge.dyn"
    assert solve_file(path).passed


@pytest.mark.parametrize("e", [0.0, 0.3, 0.5, 1.0])
def test_a_smooth_rebound_loses_half_one_minus_e_squared_of_the_relative_energy(e):
    # Effective mass at P: 1/m* = 1/m + r²/I_G = 1/2 + 0.25·6 = 2 → m* = 0.5 kg; closing speed
    # 3 m/s: J = (1 + e) m* 3 and T1 − T2 = ½ (1 − e²) m* 3² (hand derivation).
    got = answers(solve_text(ROD.format(e=e, line=", line down"), "rod.dyn"))
    v2, w2, impulse = got["v_2"].value, got["omega_2"].value, got["J_P"].value
    assert impulse == pytest.approx((1 + e) * 0.5 * 3, rel=1e-9)
    before, after = 0.5 * 2 * 9, 0.5 * 2 * v2**2 + 0.5 * (1 / 6) * w2**2
    assert before - after == pytest.approx(0.5 * (1 - e**2) * 0.5 * 9, abs=1e-9)


def test_a_rebound_off_a_point_needs_its_line_and_e_at_most_one():
    with pytest.raises(SpecError, match="needs its line of impact"):
        solve_text(ROD.format(e=0.5, line=""), "rod.dyn")
    with pytest.raises(SpecError, match="between 0 and 1"):
        solve_text(ROD.format(e=1.5, line=", line down"), "rod.dyn")
