"""Sections combined (issue 8, part 8): an ``equations:`` section beside ``kinematics:``
or ``scene:`` joins as definitions of new quantities, or is a positioned error; unused
givens in scene mode are named (part 7).

Expected numbers are derived by hand in the comments.
"""

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_text

# A braking car (b = 5 m/s², v_0 = 25 m/s) stops x_s = v_0²/(2 b) = 62.5 m later; a wall is
# h = 70 m ahead, so the gap left is c = h - x_s = 7.5 m (and twice it, 15 m).
CAR = """given:
  b = 5 m/s^2
  v_0 = 25 m/s
  h = 70 m
kinematics:
  a = -b
equations:
  c = h - x_s
  c_2 = 2*c
find: x_s = x_at(v, 0), c, c_2
"""

# Hibbeler 17.11 drum (see problems/seed/fa_hib_drum.dyn): T = 106 N for the block of
# m_b g = 196.2 N, so the cord carries W - T = 196.2 - 106.0 = 90.2 N less than the weight
# (W - T = m_b a = 20 × 4.52 = 90.4 N to the key's 0.5%).
DRUM = """given:
  m_d = 60 kg
  k_O = 0.25 m
  r   = 0.4 m
  m_b = 20 kg
  g   = 9.81 m/s^2
scene:
  point O: (0, 0)
  body drum: mass m_d, gyration k_O, at (0, 0)
  body block: particle, mass m_b, at (r, -2*r)
  point A on drum: (r, 0)
  pin drum at O
  cord T: drum at A to block, down
  gravity
equations:
  dW = m_b*g - T
find: T [N], dW [N]
"""


def value(solution, name: str) -> float:
    return float(next(a for a in solution.answers if a.name == name).value)


def test_equations_beside_kinematics_define_quantities_from_finds() -> None:
    solution = solve_text(CAR)
    assert value(solution, "x_s") == pytest.approx(62.5, rel=1e-9)
    assert value(solution, "c") == pytest.approx(7.5, rel=1e-9)
    assert value(solution, "c_2") == pytest.approx(15.0, rel=1e-9)


def test_equations_beside_a_scene_define_quantities_from_finds() -> None:
    solution = solve_text(DRUM)
    # α = m_b g r/(I_O + m_b r²) = 78.48/6.95 = 11.292 rad/s², a = α r = 4.5168 m/s²,
    # T = m_b (g - a) = 20 (9.81 - 4.5168) = 105.86 N; dW = m_b a = 90.34 N
    assert value(solution, "T") == pytest.approx(105.86, rel=1e-3)
    assert value(solution, "dW") == pytest.approx(90.34, rel=1e-3)


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ("  c*2 = h - x_s", "line 8 is not a definition NAME = expression"),
        ("  c >= 0", "line 8 is not a definition NAME = expression"),
        ("  h = c + x_s", "'h' is already a given"),
        ("  x_s = h - c", "'x_s' is already a find"),
    ],
)
def test_an_equation_that_is_not_a_definition_cannot_be_combined(line, message) -> None:
    text = CAR.replace("  c = h - x_s\n  c_2 = 2*c\n", line + "\n").replace(", c, c_2", "")
    with pytest.raises(SpecError, match="cannot be combined with the kinematics: section") as e:
        solve_text(text)
    assert message in e.value.message
    assert e.value.position.line == 8


def test_scene_equations_that_are_not_definitions_are_an_error() -> None:
    text = DRUM.replace("dW = m_b*g - T", "T = m_b*g")
    with pytest.raises(SpecError, match="'T' is already a quantity of the scene") as e:
        solve_text(text.replace(", dW [N]", ""))
    assert e.value.position.line == 16


def test_plane_kinematics_with_equations_is_an_error() -> None:
    text = (
        "given:\n  v_0 = 10 m/s\n  g = 9.81 m/s^2\nkinematics:\n  a_x = 0\n  a_y = -g\n"
        "  v_y0 = v_0\nequations:\n  h_2 = 2*h\nfind: h = max(y), h_2\n"
    )
    with pytest.raises(SpecError, match="cannot be combined with plane kinematics") as e:
        solve_text(text)
    assert e.value.position.line == 9


def test_define_beside_kinematics_is_accepted_by_the_parser() -> None:
    text = CAR.replace("equations:", "define:")
    assert value(solve_text(text), "c") == pytest.approx(7.5, rel=1e-9)


def test_scene_unused_given_is_named_in_the_json(tmp_path: Path) -> None:
    # k_0 is never read (the drum's gyration is k_O): a note names it with a did-you-mean.
    spec = tmp_path / "drum.dyn"
    spec.write_text(DRUM.replace("  g   = 9.81", "  k_0 = 0.3 m\n  g   = 9.81"))
    result = CliRunner().invoke(app, ["solve", str(spec), "--format", "json"])
    assert result.exit_code == 0, result.output
    checks = json.loads(result.output)["checks"]
    note = next(c for c in checks if c["name"] == "unused givens")
    assert note["detail"] == "k_0 (line 6; did you mean 'k_O'?) is given but not used"


def test_scene_with_every_given_read_has_no_unused_note() -> None:
    solution = solve_text(DRUM)
    assert not any(c.name == "unused givens" for c in solution.checks)
