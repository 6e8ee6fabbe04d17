"""Work and energy of a particle between two states (scene mode, `travel`)."""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

DROP = """\
given:
  m = 3 kg
  h = 5 m
  v_1 = {v_1}
scene:
  body ball: particle, mass m, at (0, h)
  velocity ball: v_1, right
  gravity
  travel ball: to (0, 0)
find: v = speed(ball)
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "energy.dyn"
    path.write_text(text)
    return path


@pytest.mark.parametrize("v_1", ["0 m/s", "4 m/s"])
def test_a_drop_gains_two_g_h(tmp_path, v_1):
    # (1/2) m v² = (1/2) m v_1² + m g h  ->  v = sqrt(v_1² + 2 g h)
    speed = float(v_1.split()[0])
    answer = solve_file(write(tmp_path, DROP.format(v_1=v_1))).answers[0]
    assert answer.value == pytest.approx(math.sqrt(speed**2 + 2 * 9.81 * 5), rel=1e-12)


def test_the_collar_seed_from_its_scene():
    seed = Path(__file__).resolve().parent.parent / "problems" / "seed" / "we_seed_collar.dyn"
    solution = solve_file(seed)
    assert solution.mode == "scene" and solution.passed
    note = next(e.note for e in solution.equations if e.note.startswith("T1 + ΣU"))
    assert "N_G (normal to the motion)" in note  # the guide's normal force does no work


@pytest.mark.parametrize(
    ("scene", "message"),
    [
        # a free rigid body: x, y and its turn are all free
        ("body ball: mass m, disk h, at (0, h)", "has 3 degrees of freedom"),
        # a floor under the ball: the drop would go through it
        ("contact ball at G: normal up, mu_s 0.3", "would leave its contact G"),
    ],
)
def test_unsupported_states_say_so(tmp_path, scene, message):
    text = DROP.format(v_1="0 m/s")
    if scene.startswith("body"):
        text = text.replace("body ball: particle, mass m, at (0, h)", scene)
    else:
        text = text.replace("  gravity\n", f"  gravity\n  {scene}\n")
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, text))
    assert message in caught.value.message


SPRING_DROP = """\
given:
  m = {m} kg
  k = {k} N/m
  L0 = {L0} m
  x1 = {x1} m
  y1 = {y1} m
  x2 = {x2} m
  y2 = {y2} m
  v_1 = {v1} m/s
scene:
  point A: (0, 0)
  body ball: particle, mass m, at (x1, y1)
  velocity ball: v_1, right
  spring S: ball at G to A, k k, unstretched L0
  gravity
  travel ball: to (x2, y2)
find: v = speed(ball)
"""

coordinate = st.integers(min_value=-20, max_value=20).map(lambda n: n / 10)


@settings(max_examples=12, deadline=None)
@given(
    m=st.integers(1, 10), k=st.integers(1, 200), L0=st.integers(1, 10).map(lambda n: n / 10),
    x1=coordinate, y1=coordinate, x2=coordinate, y2=coordinate, v1=st.integers(5, 30),
)  # fmt: skip
def test_conservative_scenes_keep_t_plus_v_constant(tmp_path_factory, m, k, L0, x1, y1, x2, y2, v1):
    # T + V with V = m g y + (1/2) k (|r - A| - L0)^2 must be the same in both states
    def V(x: float, y: float) -> float:
        return m * 9.81 * y + k * (math.hypot(x, y) - L0) ** 2 / 2

    total = m * v1**2 / 2 + V(x1, y1)
    if total - V(x2, y2) < 1e-6:
        return  # state 2 cannot be reached: no real speed there
    text = SPRING_DROP.format(m=m, k=k, L0=L0, x1=x1, y1=y1, x2=x2, y2=y2, v1=v1)
    path = tmp_path_factory.mktemp("tv") / "tv.dyn"
    path.write_text(text)
    v = solve_file(path).answers[0].value
    assert m * v**2 / 2 + V(x2, y2) == pytest.approx(total, rel=1e-9)


@pytest.mark.parametrize("angle", ["30 deg", "0.5235987755982988 rad", "0.08333333333333333 rev"])
def test_angles_in_deg_rad_or_rev_give_the_same_answer(tmp_path, angle):
    # a 2-kg particle pushed by P = 10 N at 30° above the horizontal, no gravity:
    # a = P/m = 5 m/s^2 at 30°: the x component is 5 cos 30° = 4.330 m/s^2
    text = f"""\
given:
  m = 2 kg
  P = 10 N
  phi = {angle}
scene:
  body ball: particle, mass m
  force P on ball at G: angle phi
find: a = a_G(ball)
"""
    answer = solve_file(write(tmp_path, text)).answers[0]
    assert answer.value == pytest.approx(5.0, rel=1e-12)
    assert answer.direction == "30.0° above the horizontal, to the right"


def test_a_state_of_an_unknown_body_is_an_error(tmp_path):
    text = DROP.format(v_1="0 m/s").replace("travel ball:", "travel bal:")
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, text))
    assert "there is no body 'bal'" in caught.value.message and "ball" in caught.value.hint


def test_a_spring_without_an_unstretched_length_is_an_error(tmp_path):
    text = SPRING_DROP.format(m=1, k=1, L0=1, x1=1, y1=1, x2=0, y2=0, v1=5).replace(
        ", unstretched L0", ""
    )
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, text))
    assert caught.value.position is not None and caught.value.position.line == 14


@pytest.mark.parametrize("v_1", ["0 m/s", "4 m/s"])
def test_the_drop_is_checked_by_integrating_f_equals_ma(tmp_path, v_1):
    # second method: m v dv/ds = m g along the fall, v² = v_1² + 2 g h, the same speed
    solution = solve_file(write(tmp_path, DROP.format(v_1=v_1)))
    check = next(c for c in solution.checks if c.name == "second method: speed of ball")
    assert check.passed
    speed = float(v_1.split()[0])
    assert f"{math.sqrt(speed**2 + 2 * 9.81 * 5):.7g}" in check.detail


def test_the_collar_is_checked_by_integrating_the_spring_force():
    # F_t(s) = −k(√(s² + L²) − L) s/√(s² + L²) along the rod, integrated numerically from
    # s = 2 ft to 0, gives the work–energy speed 11.09022 ft/s (seed we_seed_collar)
    seed = Path(__file__).resolve().parent.parent / "problems" / "seed" / "we_seed_collar.dyn"
    solution = solve_file(seed)
    check = next(c for c in solution.checks if c.name.startswith("second method"))
    assert check.passed and "11.09022" in check.detail


def test_a_path_through_the_springs_anchor_does_not_break_the_second_method(tmp_path_factory):
    # regression (found by the T + V property): the path from (0, −0.1) to (0, 0.1) passes
    # the anchor at the origin, where the spring's direction is undefined; the numeric
    # integral used to divide by zero there. Both ends are 0.1 m from the anchor, so the
    # stretch is the same and, with no weight, v₂ = v₁ = 5 m/s.
    text = SPRING_DROP.format(m=1, k=1, L0=0.1, x1=0.0, y1=-0.1, x2=0.0, y2=0.1, v1=5)
    text = text.replace("  gravity\n", "")
    path = tmp_path_factory.mktemp("anchor") / "energy.dyn"
    path.write_text(text)
    solution = solve_file(path)
    assert solution.answers[0].value == pytest.approx(5.0, rel=1e-12)
    check = next(c for c in solution.checks if c.name.startswith("second method"))
    assert check.passed


def test_a_rigid_body_between_two_states_gets_its_free_body_diagram_in_state_1():
    # issue 12: work-and-energy sheets had no free-body diagram; the seed's disk rolled by a
    # couple against a spring shows the forces whose work enters T1 + ΣU = T2 (the weight,
    # the floor's N and F at C, the spring, the couple), and no kinetic diagram
    solution = solve_file(Path(__file__).parent.parent / "problems/seed/rwe_seed_disk40lb.dyn")
    (disk,) = solution.free_body
    names = {f.name for f in disk.forces}
    assert {"N_C", "F_C", "M"} <= names and any(f.kind == "weight" for f in disk.forces)
    assert any(f.kind == "spring" for f in disk.forces)
    assert disk.kinetic == () and "state 1" in disk.motion


def test_a_spring_along_a_rough_floor_leaves_the_normal_force_alone():
    # regression (newcomer report): refused with "the normal force changes along the path";
    # by hand ½ m v² = ½ k δ² − μk m g δ = 16 − 0.7848 J, v = 3.90067 m/s
    from dynsolve.pipeline import solve_file

    path = Path(__file__).parent.parent / "problems" / "scenes" / "spring_launch_rough_floor.dyn"
    (v,) = solve_file(path).answers
    assert v.value == pytest.approx(math.sqrt(16 - 0.2 * 2 * 9.81 * 0.2), rel=1e-12)


def test_a_spring_across_the_surface_is_still_refused_where_its_line_is(tmp_path):
    # a spring pulling the block up off the floor changes N along the way: U_F = −μk N s
    # would not hold, and the error points at the contact's line
    from dynsolve.errors import SpecError
    from dynsolve.pipeline import solve_file

    text = (
        Path(__file__).parent.parent / "problems" / "scenes" / "spring_launch_rough_floor.dyn"
    ).read_text()
    text = text.replace("point E: (0, 0)", "point E: (0, L_0)").split("answers:")[0]
    file = tmp_path / "up.dyn"
    file.write_text(text)
    with pytest.raises(SpecError, match="the normal force would change") as error:
        solve_file(file)
    assert error.value.position is not None and error.value.position.line == 24
