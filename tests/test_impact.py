"""Central and oblique impact of two particles (scene mode): momentum and restitution."""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

SCENE = """\
given:
  m_A = {m_A}
  m_B = {m_B}
  v_A = {v_A}
  v_B = {v_B}
  e = {e}
scene:
  body A: particle, mass m_A, at (0, 0)
  body B: particle, mass m_B, at (0, 0)
  velocity A: v_A, {dir_A}
  velocity B: v_B, {dir_B}
  impact A with B: e e, line {line}
find: vA = v_after(A), vB = v_after(B)
"""


def solve(tmp_path: Path, **values: str) -> dict:
    text = SCENE.format(**{"dir_A": "right", "dir_B": "left", "line": "right", **values})
    path = tmp_path / "impact.dyn"
    path.write_text(text)
    return {a.name: a for a in solve_file(path).answers}


def test_central_impact_by_hand(tmp_path):
    # 2(5) - 3(2) = 2 vA + 3 vB and 0.6(5 + 2) = vB - vA: vA = -1.72 (left), vB = 2.48 (right)
    got = solve(tmp_path, m_A="2 kg", m_B="3 kg", v_A="5 m/s", v_B="2 m/s", e="0.6")
    assert got["vA"].value == pytest.approx(1.72) and got["vA"].direction == "left"
    assert got["vB"].value == pytest.approx(2.48) and got["vB"].direction == "right"


def test_plastic_impact_leaves_a_common_velocity(tmp_path):
    # e = 0: v = (2(5) - 3(2))/5 = 0.8 m/s to the right for both
    got = solve(tmp_path, m_A="2 kg", m_B="3 kg", v_A="5 m/s", v_B="2 m/s", e="0")
    assert got["vA"].value == pytest.approx(0.8) and got["vB"].value == pytest.approx(0.8)
    assert got["vA"].direction == got["vB"].direction == "right"


def test_elastic_impact_of_equal_masses_exchanges_velocities(tmp_path):
    got = solve(tmp_path, m_A="2 kg", m_B="2 kg", v_A="5 m/s", v_B="2 m/s", e="1")
    assert got["vA"].value == pytest.approx(2.0) and got["vA"].direction == "left"
    assert got["vB"].value == pytest.approx(5.0) and got["vB"].direction == "right"


def test_oblique_impact_keeps_the_velocity_across_the_line(tmp_path):
    # A moves up-right at 45° (5 m/s), B at rest, line of impact along x, e = 1, equal
    # masses: A keeps its y component 5/sqrt(2) and gives B its x component 5/sqrt(2).
    got = solve(tmp_path, m_A="1 kg", m_B="1 kg", v_A="5 m/s", v_B="0 m/s", e="1",
                dir_A="(1, 1)", dir_B="right")  # fmt: skip
    assert got["vA"].value == pytest.approx(5 / math.sqrt(2)) and got["vA"].direction == "up"
    assert got["vB"].value == pytest.approx(5 / math.sqrt(2)) and got["vB"].direction == "right"


def test_a_restitution_outside_zero_one_is_refused(tmp_path):
    with pytest.raises(SpecError) as caught:
        solve(tmp_path, m_A="2 kg", m_B="3 kg", v_A="5 m/s", v_B="2 m/s", e="1.2")
    assert "[0, 1]" in caught.value.message and caught.value.position is not None


@settings(max_examples=10, deadline=None)
@given(
    m_A=st.integers(1, 50), m_B=st.integers(1, 50), v_A=st.integers(1, 30), v_B=st.integers(0, 30)
)
def test_elastic_impacts_keep_kinetic_energy(tmp_path_factory, m_A, m_B, v_A, v_B):
    tmp = tmp_path_factory.mktemp("elastic")
    got = solve(tmp, m_A=f"{m_A} kg", m_B=f"{m_B} kg", v_A=f"{v_A} m/s", v_B=f"{v_B} m/s", e="1")
    before = m_A * v_A**2 + m_B * v_B**2
    after = m_A * got["vA"].value ** 2 + m_B * got["vB"].value ** 2
    assert after == pytest.approx(before, rel=1e-9)
