"""The seed's bar on a shaft as one scene (issue 11, part 2): ``theta_s = steady(theta)``.

The scene is drawn at the given angle θ (part (a): θ̈ there); part (b)'s steady angle is
the same scene at rest in the turning frame, part (c) its onset. Expected numbers: the
seed notes' hand derivation (problems/seed/3d_seed_bar_shaft.dyn, solved side by side):
I_B θ̈ − I_B Ω² sin θ cos θ = −m g (L/2) sin θ with I_B = m L²/3, so
θ̈ = Ω² sin θ cos θ − (3 g/(2 L)) sin θ, cos θ_s = 3 g/(2 L Ω²), Ω_min = √(3 g/(2 L)).
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

PROBLEMS = Path(__file__).parent.parent / "problems"
G = 9.81


def answers(solution) -> dict:
    return {a.name: a.value for a in solution.answers}


def test_one_scene_answers_all_three_parts_of_the_seed():
    scene = solve_file(PROBLEMS / "rigid3d" / "bar_on_shaft_seed.dyn")
    seed = answers(solve_file(PROBLEMS / "seed" / "3d_seed_bar_shaft.dyn"))
    assert scene.mode == "3D scene" and scene.passed
    found = answers(scene)
    s, c = math.sin(math.radians(30)), math.cos(math.radians(30))
    theta_ddot = 36 * s * c - 3 * G / (2 * 0.8) * s  # 6.391582 rad/s²
    assert found["theta_ddot"] == pytest.approx(theta_ddot, rel=1e-12)
    assert found["B_x"] == pytest.approx(2 * (-36 * 0.4 * s + theta_ddot * 0.4 * c), rel=1e-12)
    assert found["B_y"] == pytest.approx(2 * G + 2 * theta_ddot * 0.4 * s, rel=1e-12)
    steady = math.degrees(math.acos(3 * G / (2 * 0.8 * 36)))  # 59.2737°
    assert found["theta_s"] == pytest.approx(steady, rel=1e-12)
    assert found["Omega_min"] == pytest.approx(math.sqrt(3 * G / 1.6), rel=1e-12)
    for name in ("theta_ddot", "theta_s", "Omega_min"):
        assert found[name] == pytest.approx(seed[name], rel=1e-9)
    checks = {c.name: c for c in scene.checks}
    assert checks["onset Omega_min"].passed and checks["second moment point: G"].passed


def test_the_steady_angle_is_the_one_the_separate_scene_finds():
    one = answers(solve_file(PROBLEMS / "rigid3d" / "bar_on_shaft_seed.dyn"))
    apart = answers(solve_file(PROBLEMS / "rigid3d" / "bar_on_shaft_steady.dyn"))
    assert one["theta_s"] == pytest.approx(apart["theta_s"], rel=1e-12)
    assert one["Omega_min"] == pytest.approx(apart["Omega_min"], rel=1e-12)


def test_the_symbolic_scene_gives_the_seed_formulas():
    solution = solve_file(PROBLEMS / "rigid3d" / "bar_on_shaft_seed-symbolic.dyn")
    assert solution.passed
    assert {k.name for k in solution.key if k.passed} == {"theta_ddot", "theta_s", "Omega_min"}


BAR = """\
given:
  m = 2 kg
  L = {L} m
  Omega = {Omega} rad/s
  theta = {theta} deg
  w = 0 rad/s
scene:
  body bar: mass m, rod L, at (L/2*sin(theta), -L/2*cos(theta), 0)
  axis bar: (sin(theta), -cos(theta), 0)
  rotates bar: about (0, 1, 0), through (0, 0, 0), omega Omega
  spins bar: about (0, 0, 1), through (0, 0, 0), omega w, alpha theta_ddot
  bearing B: at (0, 0, 0), pin
  gravity
  assume theta_s > 0
  assume theta_s < pi/2
find: {find}
"""
FIND = "theta_ddot, theta_s = steady(theta), Omega_min = onset(theta_s, Omega)"


@settings(max_examples=5, deadline=None)
@given(
    L=st.sampled_from([0.5, 0.8, 1.2]),
    Omega=st.integers(6, 20),
    theta=st.integers(5, 85),
)
def test_every_part_follows_the_hand_formulas(L, Omega, theta):
    text = BAR.format(L=L, Omega=Omega, theta=theta, find=FIND)
    found = answers(solve_text(text, "bar.dyn"))
    t = math.radians(theta)
    expected = Omega**2 * math.sin(t) * math.cos(t) - 3 * G / (2 * L) * math.sin(t)
    assert found["theta_ddot"] == pytest.approx(expected, rel=1e-9, abs=1e-9)
    assert found["theta_s"] == pytest.approx(math.acos(3 * G / (2 * L * Omega**2)), rel=1e-9)
    assert found["Omega_min"] == pytest.approx(math.sqrt(3 * G / (2 * L)), rel=1e-9)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (("theta_s = steady(theta)", "theta_s = steady(Theta)"), "one given"),
        (("theta_s = steady(theta)", "theta_s = steady(theta, L)"), "one given"),
        (("alpha theta_ddot", "alpha 0"), "angular acceleration unknown"),
        (
            (
                "  bearing B: at (0, 0, 0), pin\n",
                "  bearing B: at (0, 0, 0), pin\n  bearing C: at (0, 0, L), ball\n",
            ),
            "no moment equation holds",
        ),
    ],
)
def test_a_steady_angle_the_scene_cannot_give_is_refused(change, message):
    text = BAR.format(L=0.8, Omega=6, theta=30, find=FIND)
    old, new = change
    if "alpha 0" in new:
        text = text.replace("theta_ddot, theta_s", "theta_s")
    with pytest.raises(SpecError, match=message) as error:
        solve_text(text.replace(old, new), "bar.dyn")
    assert error.value.position is not None and error.value.position.line > 1
