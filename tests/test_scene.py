"""Scene mode: equations written from bodies, supports and loads (docs/scene-mode.md)."""

import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import DimensionError, SpecError
from dynsolve.pipeline import solve_file

# Hibbeler 12e Example 17.11 as a scene: alpha = 11.3 rad/s^2 (cw with the block on the
# right), T = 106 N, a = 4.52 m/s^2 down.
DRUM_SCENE = """\
problem: Drum and hanging block (scene)
units: SI
given:
  m_d = 60 kg
  k_O = 0.25 m
  r = 0.4 m
  m_b = 20 kg
scene:
  point O: (0, 0)
  body drum: mass m_d, gyration k_O, at (0, 0)
  body block: particle, mass m_b, at (r, -r)
  pin drum at O
  cord T: drum at (r, 0) to block, down
  gravity
find: alpha = alpha(drum), T, a = a_G(block)
answers:
  alpha = 11.3 rad/s^2 +- 0.5% cw
  T = 106 N +- 0.5%
  a = 4.52 m/s^2 +- 0.5% down
"""

# Hibbeler 12e Example 17.7 (crate, mu_k = 0.2, P = 600 N at 0.8 m): x = 0.467 m, no tip.
# With P at the top (1.0 m): sum of moments about G (translation, ccw +):
# 490.5 x - 600(0.5) - 98.1(0.5) = 0  ->  x = 0.712 m > b/2 = 0.5 m: the crate tips.
CRATE = """\
units: SI
given:
  m = 50 kg
  b = 1 m
  h = 1 m
  P = 600 N
  h_P = {h_P}
  mu_k = 0.2
scene:
  body crate: mass m, block b by h, at (0, 0)
  base C on crate: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, slides right
  force P on crate at (-b/2, h_P - h/2): right
  gravity
find: x = x_C, N_C
answers:
  x = {x} m +- 0.5%
"""


def write(tmp_path: Path, text: str, name: str = "scene.dyn") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def failed(solution) -> list[str]:
    return [f"{c.name}: {c.detail}" for c in solution.checks if c.failed]


def test_drum_scene_reproduces_the_textbook(tmp_path):
    solution = solve_file(write(tmp_path, DRUM_SCENE))
    assert solution.mode == "scene"
    assert not failed(solution), failed(solution)
    shown = {a.name: (a.value, a.direction) for a in solution.answers}
    assert shown["alpha"][1] == "cw" and shown["a"][1] == "down"
    assert all(value > 0 for value, _ in shown.values())  # magnitudes


def test_drum_scene_writes_textbook_equations_and_diagrams(tmp_path):
    solution = solve_file(write(tmp_path, DRUM_SCENE))
    notes = [e.note for e in solution.equations]
    assert any(n.startswith("ΣM_O = I_G α") for n in notes)  # the moment point is the pin
    assert any("cord T inextensible" in n for n in notes)
    bodies = {b.body: b for b in solution.free_body}
    assert {f.name for f in bodies["drum"].forces} >= {"W_drum", "T", "O_x", "O_y"}
    assert not next(f for f in bodies["drum"].forces if f.name == "O_x").known
    assert "rotation about O" in bodies["drum"].motion
    # the pin's reactions are not needed for alpha, T and a: they are not solved
    assert any(c.name == "model only what is asked" for c in solution.checks)


def test_no_tipping_is_checked_for_the_textbook_crate(tmp_path):
    solution = solve_file(write(tmp_path, CRATE.format(h_P="0.8 m", x="0.467")))
    assert not failed(solution), failed(solution)
    tip = next(a for a in solution.assumptions if a.name.startswith("no tipping"))
    assert tip.holds
    # regression: the moment point was once N_C's own (unknown) point; the textbook sums
    # moments about G, where translation gives ΣM_G = 0
    assert any(e.note.startswith("ΣM_G = 0 (translation)") for e in solution.equations)
    assert solution.free_body[0].moment_point.startswith("G (translation")


def test_a_crate_pushed_at_the_top_tips(tmp_path):
    solution = solve_file(write(tmp_path, CRATE.format(h_P="1 m", x="0.712")))
    tip = next(a for a in solution.assumptions if a.name.startswith("no tipping"))
    assert not tip.holds and "tips" in tip.detail
    assert not solution.passed  # a failed assumption fails the solve


def test_slip_is_detected_and_resolved_with_kinetic_friction():
    seed = Path(__file__).resolve().parent.parent / "problems" / "seed" / "gpm_seed_pole_slip.dyn"
    solution = solve_file(seed)
    trial = next(a for a in solution.assumptions if a.name == "no slip at A")
    assert not trial.holds and "re-solved with F = μk N" in trial.detail
    assert solution.passed


def test_json_has_scene_fields(tmp_path):
    result = CliRunner().invoke(app, ["solve", str(write(tmp_path, DRUM_SCENE)), "-f", "json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["mode"] == "scene"
    assert {b["body"] for b in data["free_body"]} == {"drum", "block"}
    assert all({"name", "holds", "detail"} <= set(a) for a in data["assumptions"])


@pytest.mark.parametrize(
    ("replace", "by", "error", "message"),
    [
        ("force", "force", None, ""),
        ("cord T: drum at (r, 0) to block", "cord T: drum at (r, 0) to blok", SpecError,
         "there is no body 'blok'"),
        ("pin drum at O", "pin drum at Q", SpecError, "no fixed point 'Q'"),
        ("body drum: mass m_d,", "body drum: mass r,", DimensionError, "must be a mass"),
        ("find: alpha = alpha(drum)", "find: alpha = alpha(drum2)", SpecError,
         "there is no body 'drum2'"),
        ("find: alpha = alpha(drum), T", "find: alpha = alpha(drum), Tension", SpecError,
         "not a quantity of this scene"),
    ],
)  # fmt: skip
def test_scenes_that_make_no_sense_get_clear_errors(tmp_path, replace, by, error, message):
    text = DRUM_SCENE.replace(replace, by)
    if error is None:
        assert solve_file(write(tmp_path, text)).passed
        return
    with pytest.raises(error) as caught:
        solve_file(write(tmp_path, text))
    assert message in caught.value.message
    assert caught.value.position is not None and caught.value.hint


def test_too_few_supports_names_the_free_unknowns_and_a_fix(tmp_path):
    text = """\
given:
  m = 2 kg
  r = 0.1 m
scene:
  body block: mass m, disk r
  force Q on block at (r, 0): up
  gravity
find: Q
"""
    solution = solve_file(write(tmp_path, text))
    structure = next(c for c in solution.checks if c.name == "structure")
    assert not structure.passed
    assert "cannot determine" in structure.detail and "Q" in structure.detail
    assert "add a support" in structure.detail


ROTATED_DRUM = """\
units: {system}
given:
  m_d = {m_d}
  k_O = {k_O}
  r = {r}
  m_b = {m_b}
  phi = {phi}
scene:
  point O: (0, 0)
  body drum: mass m_d, gyration k_O, at (0, 0)
  body block: particle, mass m_b, at (r*cos(phi) + r*sin(phi), r*sin(phi) - r*cos(phi))
  pin drum at O
  cord T: drum at (r*cos(phi), r*sin(phi)) to block, angle phi - pi/2
  gravity: angle phi - pi/2
find: alpha = alpha(drum), T [N], a = a_G(block) [m/s^2]
"""


@settings(max_examples=8, deadline=None)
@given(degrees=st.integers(min_value=0, max_value=359))
def test_rotating_the_scene_axes_leaves_every_magnitude_unchanged(tmp_path_factory, degrees):
    # The drum problem with every position, direction and gravity rotated by phi:
    # magnitudes are those of Hibbeler 17.11 (alpha = 7848/695, T = 14715/139,
    # a = 15696/3475, from solving the linear system by hand).
    tmp = tmp_path_factory.mktemp("rotated")
    values = dict(m_d="60 kg", k_O="0.25 m", r="0.4 m", m_b="20 kg", phi=f"{degrees} deg")
    solution = solve_file(write(tmp, ROTATED_DRUM.format(system="SI", **values)))
    got = {a.name: a.value for a in solution.answers}
    assert got["alpha"] == pytest.approx(7848 / 695, rel=1e-9)
    assert got["T"] == pytest.approx(14715 / 139, rel=1e-9)
    assert got["a"] == pytest.approx(15696 / 3475, rel=1e-9)


def test_the_scene_restated_in_fps_gives_the_same_magnitudes(tmp_path):
    si = dict(m_d="60 kg", k_O="0.25 m", r="0.4 m", m_b="20 kg", phi="0.3")
    fps = dict(
        m_d=f"{60 / 14.593902937206364!r} slug",
        k_O=f"{0.25 / 0.3048!r} ft",
        r=f"{0.4 / 0.3048!r} ft",
        m_b=f"{20 / 14.593902937206364!r} slug",
        phi="0.3",
    )
    text_si = ROTATED_DRUM.format(system="SI", **si)
    text_fps = ROTATED_DRUM.format(system="FPS", **fps).replace(
        "given:\n", "given:\n  g = 9.81 m/s^2\n"
    )
    a = {x.name: x.value for x in solve_file(write(tmp_path, text_si, "si.dyn")).answers}
    b = {x.name: x.value for x in solve_file(write(tmp_path, text_fps, "fps.dyn")).answers}
    for name in a:
        assert b[name] == pytest.approx(a[name], rel=1e-9)


ATWOOD = """\
given:
  m1 = 3 kg
  m2 = 5 kg
  r = 0.1 m
  L = 1 m
  M = {M}
scene:
  point O: (0, 0)
  body pulley: mass M, disk r, at (0, 0)
  body A: particle, mass m1, at (-r, -L)
  body B: particle, mass m2, at (r, -L)
  pin pulley at O
  cord T1: pulley at (-r, 0) to A, down
  cord T2: pulley at (r, 0) to B, down
  gravity
find: a = a_G(B), T1, T2
"""


@pytest.mark.parametrize(
    ("M", "a", "T1", "T2"),
    [
        # massless pulley: a = (m2 - m1) g/(m1 + m2) = 2(9.81)/8; T = 2 m1 m2 g/(m1 + m2)
        ("0 kg", 2.4525, 36.7875, 36.7875),
        # 2-kg disk pulley, I = M r^2/2: a = (m2 - m1) g/(m1 + m2 + M/2) = 19.62/9;
        # T1 = m1 (g + a), T2 = m2 (g - a)
        ("2 kg", 19.62 / 9, 3 * (9.81 + 19.62 / 9), 5 * (9.81 - 19.62 / 9)),
    ],
)
def test_atwood_machine_over_a_pulley(tmp_path, M, a, T1, T2):
    solution = solve_file(write(tmp_path, ATWOOD.format(M=M)))
    got = {x.name: x for x in solution.answers}
    assert got["a"].value == pytest.approx(a, rel=1e-9) and got["a"].direction == "down"
    assert got["T1"].value == pytest.approx(T1, rel=1e-9)
    assert got["T2"].value == pytest.approx(T2, rel=1e-9)


def test_a_spring_pulls_with_k_times_its_stretch(tmp_path):
    # stretch 0.5 - 0.3 = 0.2 m, force 100(0.2) = 20 N toward the wall: a = 20/2 = 10 m/s^2 left
    text = """\
given:
  m = 2 kg
  d = 0.5 m
  k = 100 N/m
  L0 = 0.3 m
scene:
  point W: (0, 0)
  body block: particle, mass m, at (d, 0)
  contact block at G: normal up, smooth
  spring S: block at G to W, k k, unstretched L0
  gravity
find: a = a_G(block), N = N_G
"""
    got = {x.name: x for x in solve_file(write(tmp_path, text)).answers}
    assert got["a"].value == pytest.approx(10.0) and got["a"].direction == "left"
    assert got["N"].value == pytest.approx(2 * 9.81)


def test_a_link_carries_the_weight_of_what_hangs_on_it(tmp_path):
    text = """\
given:
  m = 2 kg
  h = 0.5 m
scene:
  point O: (0, 0)
  body block: particle, mass m, at (0, -h)
  link AB: block at G to O
  gravity
find: F = AB, a = a_G(block)
"""
    got = {x.name: x for x in solve_file(write(tmp_path, text)).answers}
    assert got["F"].value == pytest.approx(2 * 9.81) and got["F"].direction == "up"
    assert got["a"].value == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        # a block stays put up to tan(theta) = mu_s: theta = atan(0.5) = 26.565 deg
        ("particle", math.degrees(math.atan(0.5))),
        # a solid disk rolls without slipping up to tan(beta) = 3 mu_s (seed 001 / Hibbeler
        # 17-94: tan(beta) <= mu_s (1 + m R^2/I_G)): beta = atan(1.5) = 56.31 deg
        ("disk R", math.degrees(math.atan(1.5))),
    ],
)
def test_steepest_slope_without_slip(tmp_path, body, expected):
    contact = "contact" if body == "particle" else "rolls"
    text = f"""\
given:
  m = 5 kg
  R = 0.2 m
  mu_s = 0.5
scene:
  body thing: mass m, {body}, at (0, R)
  point C on thing: (0, -R)
  {contact} thing at C: normal up, mu_s mu_s
  gravity
find: theta = steepest(C)
"""
    answer = solve_file(write(tmp_path, text)).answers[0]
    assert answer.unit == "deg"
    assert answer.value == pytest.approx(expected, rel=1e-9)


def test_a_given_velocity_sets_omega_for_pinned_and_rolling_bodies(tmp_path):
    # rod20 of the seed notes with v_G = 7.5 m/s down instead of omega = 5 rad/s cw:
    # omega = v_G/r_G = 7.5/1.5 = 5 rad/s cw, so O_n = m omega^2 r_G = 20(25)(1.5) = 750 N.
    rod = """\
given:
  m = 20 kg
  L = 3 m
  v = 7.5 m/s
  R = 0.5 m
  v_d = 2 m/s
  m_d = 4 kg
scene:
  point O: (0, 0)
  body rod: mass m, rod L, at (L/2, 0)
  pin rod at O
  velocity rod: v, down
  body disk: mass m_d, disk R, at (5*L, R)
  point C on disk: (0, -R)
  rolls disk at C: normal up, mu_s 1
  velocity disk: v_d, right
  gravity
find: w = omega(rod), O_n, w_d = omega(disk)
"""
    got = {a.name: a for a in solve_file(write(tmp_path, rod)).answers}
    assert got["w"].value == pytest.approx(5.0) and got["w"].direction == "cw"
    assert got["O_n"].value == pytest.approx(750.0)
    # rolling to the right at 2 m/s on a 0.5-m disk: omega = v/R = 4 rad/s cw
    assert got["w_d"].value == pytest.approx(4.0) and got["w_d"].direction == "cw"


def test_kinetic_friction_opposes_a_slide_given_by_a_vector_of_givens(tmp_path):
    # regression: the sense of kinetic friction was found by putting 1 for every symbol
    # of the sliding direction, so slides (d, 0) with d = -1 (to the left) got friction
    # to the left too. Pushed left by 600 N: a = (600 - 0.2(50)(9.81))/50 = 10.04 m/s^2 left.
    text = """\
given:
  m = 50 kg
  b = 1 m
  h = 1 m
  P = 600 N
  mu_k = 0.2
  d = -1
scene:
  body crate: mass m, block b by h, at (0, 0)
  base C on crate: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, slides (d, 0)
  force P on crate at (b/2, 0): left
  gravity
find: a = a_G(crate), F = F_C
"""
    got = {a.name: a for a in solve_file(write(tmp_path, text)).answers}
    assert got["a"].value == pytest.approx((600 - 0.2 * 50 * 9.81) / 50)
    assert got["a"].direction == "left" and got["F"].direction == "right"
