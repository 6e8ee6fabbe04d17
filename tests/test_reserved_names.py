"""Names as statements write them (issues 25 items 1–3 and 6, 26 deliverable 5): a find
that renames a solved unknown answers that unknown, never a reserved or given value of the
same name; a given named as a motion's own variable (t, x, v, a) is refused, not ignored;
the position written ``s`` is pointed at ``x``; ``units: US`` is FPS; a scene beside a
kinematics section is refused rather than dropped; an unused given of plane motion is named.

Expected numbers come from the hand derivations in the comments.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner, Result

from dynsolve.cli import app

MODES = ("exact", "numeric", "auto")

# A pendulum's measured period gives local gravity: T = 2π√(L/g_p), so
# g_p = 4π² L / T² = 4π² × 1 / 2.2² = 39.478 / 4.84 = 8.1566 m/s² (not the default 9.81).
PENDULUM = """\
problem: local g from a pendulum
given:
  L = 1 m
  T = 2.2 s
equations:
  T = 2*pi*sqrt(L/g_p)
find: g = g_p [m/s^2]
"""
G_LOCAL = 4 * math.pi**2 * 1 / 2.2**2


def run(tmp_path: Path, text: str, *args: str) -> Result:
    path = tmp_path / "spec.dyn"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(app, ["solve", str(path), *args])
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert "Traceback" not in result.output
    return result


@pytest.mark.parametrize("mode", MODES)
def test_a_find_named_g_answers_the_solved_unknown_not_gravity(tmp_path: Path, mode: str):
    result = run(tmp_path, PENDULUM, "--mode", mode, "--format", "json")
    assert result.exit_code == 0, result.output
    (answer,) = json.loads(result.stdout)["answers"]
    assert answer["name"] == "g"
    assert answer["value"] == pytest.approx(G_LOCAL, rel=1e-9)
    terminal = run(tmp_path, PENDULUM, "--mode", mode)
    assert "8.16 m/s²" in terminal.stdout and "9.81" not in terminal.stdout


@pytest.mark.parametrize("mode", MODES)
def test_a_find_renaming_onto_the_gravity_the_equations_use_is_refused(tmp_path: Path, mode: str):
    # here g is the equations' gravity: answering g = g_p would show two values of g
    text = PENDULUM.replace("T = 2*pi*sqrt(L/g_p)", "T = 2*pi*sqrt(L/g_p)*g/g")
    result = run(tmp_path, text, "--mode", mode)
    assert result.exit_code == 2
    assert "spec.dyn:7:7" in result.output
    assert "gravitational acceleration the equations use" in result.output


def test_a_find_renaming_onto_a_given_is_refused(tmp_path: Path):
    text = PENDULUM.replace("find: g = g_p", "find: L = g_p")
    result = run(tmp_path, text)
    assert result.exit_code == 2
    assert "'L' in find would name g_p, but L is a given (line 3)" in result.output


def test_a_scene_quantity_in_an_equation_mode_find_is_refused(tmp_path: Path):
    # it was silently ignored: find: g = speed(B) answered the default gravity
    result = run(tmp_path, PENDULUM.replace("g = g_p", "g = speed(B)"))
    assert result.exit_code == 2
    assert "spec.dyn:7:11" in result.output and "scene quantity" in result.output


BRAKING = """\
given:
  b = 5 m/s^2
  v_0 = 25 m/s
kinematics:
  a = -b
find: t_s = t_at(v, 0), {find}
"""


@pytest.mark.parametrize("name", ["b", "g"])
def test_a_kinematics_find_named_as_a_given_is_refused(tmp_path: Path, name: str):
    # 'b = x_at(v, 0)' answered "b = 62.5 m" beside the given b = 5 m/s²
    result = run(tmp_path, BRAKING.format(find=f"{name} = x_at(v, 0)"))
    assert result.exit_code == 2
    assert f"'{name}' in find would name x_at(v, 0)" in result.output
    assert f"{name}_1 = x_at(v, 0)" in result.output


def test_a_scene_find_named_as_a_given_is_refused(tmp_path: Path):
    text = """\
given:
  m = 10 kg
  theta = 30 deg
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal (-sin(theta), cos(theta)), smooth
  gravity
find: m = a_G(block) [m/s^2]
"""
    result = run(tmp_path, text)
    assert result.exit_code == 2
    assert "spec.dyn:8:7" in result.output and "m is a given (line 2)" in result.output


PROJECTILE = """\
given:
  v_0 = 20 m/s
  theta_0 = 30 deg
  g = 9.81 m/s^2
{extra}kinematics:
  v_x0 = v_0*cos(theta_0)
  v_y0 = v_0*sin(theta_0)
  a_x = 0
  a_y = -g
find: {find}
"""


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("name", ["t", "x", "y", "v", "a", "v_x"])
def test_a_given_named_as_a_plane_motion_variable_is_refused(tmp_path: Path, mode: str, name: str):
    # x(t) came back as a formula in t (JSON value null), exit 0, the given t = 2 s ignored
    unit = {"t": "s", "x": "m", "y": "m", "v": "m/s", "v_x": "m/s", "a": "m/s^2"}[name]
    text = PROJECTILE.format(extra=f"  {name} = 2 {unit}\n", find="X = x(t)")
    result = run(tmp_path, text, "--mode", mode, "--format", "json")
    assert result.exit_code == 2
    assert "spec.dyn:5:3" in result.output
    assert f"a given cannot be named {name}" in result.output


def test_the_fix_the_error_names_gives_the_answer(tmp_path: Path):
    # x(t_1) = v_0 cos 30° t_1 = 17.3205 × 2 = 34.641 m
    text = PROJECTILE.format(extra="  t_1 = 2 s\n", find="X = x(t_1)")
    result = run(tmp_path, text, "--format", "json")
    assert result.exit_code == 0, result.output
    (answer,) = json.loads(result.stdout)["answers"]
    assert answer["value"] == pytest.approx(20 * math.cos(math.radians(30)) * 2, rel=1e-9)


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("name", ["t", "x", "v", "a"])
def test_a_given_named_as_a_rectilinear_motion_variable_is_refused(
    tmp_path: Path, mode: str, name: str
):
    unit = {"t": "s", "x": "m", "v": "m/s", "a": "m/s^2"}[name]
    text = BRAKING.format(find="X = x(t)").replace(
        "kinematics:", f"  {name} = 2 {unit}\nkinematics:"
    )
    result = run(tmp_path, text, "--mode", mode)
    assert result.exit_code == 2
    assert f"spec.dyn:4:3: a given cannot be named {name}" in result.output


@pytest.mark.parametrize(
    "relations",
    ["  s = v_0*t - 2*t^2\n", "  a = -k*s\n", "  s_x = v_0*t\n  s_y = 3*t\n"],
)
def test_position_written_s_is_pointed_at_x(tmp_path: Path, relations: str):
    text = f"given:\n  v_0 = 25 m/s\n  k = 4 1/s^2\nkinematics:\n{relations}find: X = x(1)\n"
    result = run(tmp_path, text)
    assert result.exit_code == 2
    assert "dynsolve names the position x" in result.output


@pytest.mark.parametrize("word", ["US", "us", "USCS"])
def test_units_us_is_fps(tmp_path: Path, word: str):
    # W = m g with m = 2 slug and g = 32.2 ft/s² (the FPS default): 64.4 lb
    text = f"units: {word}\ngiven:\n  m = 2 slug\nequations:\n  W = m*g\nfind: W\n"
    result = run(tmp_path, text, "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["units"] == "FPS"
    assert data["answers"][0]["value"] == pytest.approx(64.4)
    assert data["answers"][0]["unit"] == "lb"


@pytest.mark.parametrize("mode", MODES)
def test_a_scene_beside_kinematics_is_refused_not_dropped(tmp_path: Path, mode: str):
    text = BRAKING.format(find="x_s = x_at(v, 0)").replace(
        "kinematics:",
        "scene:\n  body block: particle, mass b, at (0, 0)\n  gravity\nkinematics:",
    )
    result = run(tmp_path, text, "--mode", mode, "--format", "json")
    assert result.exit_code == 2
    assert "spec.dyn:4:1: a scene: section cannot yet be combined with a kinematics:" in (
        result.output
    )


@pytest.mark.parametrize("mode", MODES)
def test_an_unused_given_of_plane_motion_is_named(tmp_path: Path, mode: str):
    # the mass m is read only by a force find (F_x, …); h by nothing
    extra = "  m = 2 kg\n  h = 3 m\n"
    text = PROJECTILE.format(extra=extra, find="t_f = t_at(y, y_0)")
    result = run(tmp_path, text, "--mode", mode, "--format", "json")
    assert result.exit_code == 0, result.output
    notes = {c["name"]: c["detail"] for c in json.loads(result.stdout)["checks"]}
    assert notes["unused givens"] == "m (line 5), h (line 6) are given but not used"
    forces = run(tmp_path, PROJECTILE.format(extra=extra, find="F = F_y(t)"), "--mode", mode)
    assert "h (line 6) is given but not used" in forces.stdout
    assert "m (line 5)" not in forces.stdout
