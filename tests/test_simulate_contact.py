"""dynsolve simulate --until 'lost(PATH)': a particle leaving its circular path (issue 11
part 3, events: contact lost), against hand derivations; the normal force in the history."""

import csv
import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.simulate.run import simulate_spec
from dynsolve.spec.parser import parse_spec

ROOT = Path(__file__).resolve().parent.parent
SCENES = ROOT / "problems" / "scenes"
G = 9.81
G_FPS = 32.2

DOME = """\
problem: Block on a smooth dome
units: SI
given:
  m = {m}
  R = {R}
  v_0 = {v_0}
scene:
  path dome: x^2 + y^2 = R^2
  body block: particle, mass m, at (0, R)
  velocity block: v_0, right
  gravity
"""

LOOP = """\
problem: Ball inside a vertical loop
units: SI
given:
  m = 0.2 kg
  R = 1.5 m
  v_b = {v_b}
scene:
  path loop: x^2 + y^2 = R^2
  body ball: particle, mass m, at (0, -R)
  velocity ball: v_b, right
  gravity
"""


def run_cli(*args: object) -> object:
    return CliRunner().invoke(app, ["simulate", *map(str, args)])


def dome_cos(v_0: float, R: float, g: float = G) -> float:
    # Hand (θ from the top): energy v² = v_0² + 2 g R (1 − cos θ); radial, toward the
    # centre, m g cos θ − N = m v²/R; N = 0 → cos θ = 2/3 + v_0²/(3 g R) (Hibbeler 13-…)
    return 2 / 3 + v_0**2 / (3 * g * R)


def test_the_nudged_block_leaves_the_hemisphere_at_cos_two_thirds(tmp_path: Path) -> None:
    # problems/scenes/hemisphere_nudge_leaves.dyn: R = 0.5 m, a 1-mm/s nudge at the top;
    # hand: cos θ = 2/3 + v_0²/(3 g R) → θ = 48.18968°, v = √(g R cos θ) = 1.808314 m/s
    out = tmp_path / "h.json"
    spec = SCENES / "hemisphere_nudge_leaves.dyn"
    result = run_cli(spec, "--until", "lost(hemisphere)", "-o", out)
    assert result.exit_code == 0, result.output
    assert "contact with hemisphere lost" in result.output
    lost = json.loads(out.read_text())["contact"]["lost"]
    c = dome_cos(0.001, 0.5)
    assert lost["angle_from_top_deg"] == pytest.approx(math.degrees(math.acos(c)), rel=1e-8)
    assert lost["angle_turned_deg"] == pytest.approx(math.degrees(math.acos(c)), rel=1e-8)
    assert lost["speed"] == pytest.approx(math.sqrt(G * 0.5 * c), rel=1e-8)
    assert lost["rise"] == pytest.approx(-0.5 * (1 - c), rel=1e-8)


def test_the_travel_line_names_the_default_event_and_fps_gives_n_in_lb(tmp_path: Path) -> None:
    # problems/scenes/cylinder_block_leaves_fps.dyn: W = 2 lb, R = 3 ft, v_0 = 4 ft/s; its
    # 'travel block: until contact lost' is the run's event. Hand: cos θ = 2/3 + 16/289.8
    # → θ = 43.79032°; N at the top = W − (W/g) v_0²/R = 2 − 2·16/96.6 = 1.668737 lb
    out = tmp_path / "h.csv"
    result = run_cli(SCENES / "cylinder_block_leaves_fps.dyn", "-o", out)
    assert result.exit_code == 0, result.output
    assert "stopped by 'lost(cylinder)'" in result.output
    rows = list(csv.reader(out.read_text().splitlines()))
    header, first, last = rows[0], rows[1], rows[-1]
    column = header.index("N_cylinder [lb]")
    assert float(first[column]) == pytest.approx(2 - 2 * 16 / (G_FPS * 3), rel=1e-12)
    assert abs(float(last[column])) < 1e-9
    theta = math.acos(dome_cos(4.0, 3.0, G_FPS))
    assert abs(float(last[header.index("q [rad]")])) == pytest.approx(theta, rel=1e-9)


def test_the_ball_falls_off_the_inside_of_the_loop_where_n_is_zero() -> None:
    # problems/scenes/loop_ball_falls_off.dyn, hand (θ from the bottom): energy
    # v² = v_b² − 2 g R (1 − cos θ); toward the centre N − m g cos θ = m v²/R; N = 0 →
    # cos θ = (2 g R − v_b²)/(3 g R) = −0.4433118 → θ = 116.3154°, v = √(−g R cos θ)
    result = run_cli(SCENES / "loop_ball_falls_off.dyn", "--until", "contact lost")
    assert result.exit_code == 0, result.output
    history = simulate_spec(parse_spec(LOOP.format(v_b="7 m/s"), "loop.dyn"), "lost(loop)")
    assert history.stopped_by == "lost(loop)"
    ((_, _, q, qd),) = [e for e in history.events if e[0] == "lost(loop)"]
    c = (2 * G * 1.5 - 49) / (3 * G * 1.5)
    assert q == pytest.approx(math.acos(c), rel=1e-9)  # ccw from the bottom, moving right
    assert abs(1.5 * qd) == pytest.approx(math.sqrt(-G * 1.5 * c), rel=1e-8)
    assert history.contact is not None and history.contact.side == 1  # inside


def test_the_normal_force_in_the_history_is_the_closed_form() -> None:
    # Hand, on the dome (θ from the top): N = m g cos θ − m v²/R with
    # v² = v_0² + 2 g R (1 − cos θ): N = m g (3 cos θ − 2) − m v_0²/R
    m, R, v_0 = 0.5, 2.0, 1.0
    text = DOME.format(m="0.5 kg", R="2 m", v_0="1 m/s")
    history = simulate_spec(parse_spec(text, "dome.dyn"), "lost(dome)", samples=51)
    column = history.columns().index("N_dome [N]")
    for row in history.rows():
        c = math.cos(row[1])
        assert row[column] == pytest.approx(m * G * (3 * c - 2) - m * v_0**2 / R, abs=1e-9)
    assert history.run.drift < 1e-8


@settings(max_examples=20, deadline=None)
@given(
    R=st.floats(min_value=0.2, max_value=20.0),
    fraction=st.floats(min_value=0.01, max_value=0.95),
)
def test_the_leaving_angle_matches_the_closed_form_over_v0_and_r(R: float, fraction: float):
    # cos θ = 2/3 + v_0²/(3 g R) (hand derivation above) for any start speed the dome
    # holds at its top, v_0 < √(g R)
    v_0 = fraction * math.sqrt(G * R)
    text = DOME.format(m="1 kg", R=f"{R!r} m", v_0=f"{v_0!r} m/s")
    history = simulate_spec(parse_spec(text, "dome.dyn"), "lost(dome)", t_end=200.0)
    assert history.stopped_by == "lost(dome)"
    ((_, _, q, _),) = [e for e in history.events if e[0] == "lost(dome)"]
    assert math.cos(q) == pytest.approx(dome_cos(v_0, R), rel=1e-6)


def test_a_ball_that_goes_round_the_loop_never_loses_contact(tmp_path: Path) -> None:
    # v_b² = 81 ≥ 5 g R = 73.6: N = m (v_b² − 5 g R)/R ≥ 0.99 N at the top; it goes round,
    # and asked for the loss the run says it never happens (exit 2, the history written)
    spec = tmp_path / "round.dyn"
    spec.write_text(LOOP.format(v_b="9 m/s"))
    out = tmp_path / "h.csv"
    result = run_cli(spec, "--until", "lost(loop)", "--t-end", "3 s", "-o", out)
    assert result.exit_code == 2
    assert "contact with loop is never lost by t = 3 s" in result.output
    assert "goes round" in result.output
    assert out.exists()
    low = 0.2 * (81 - 5 * G * 1.5) / 1.5
    assert f"between {low:.6g}" in result.output


def test_a_dome_that_cannot_hold_the_block_at_the_start_is_refused(tmp_path: Path) -> None:
    # v_0² = 25 > g R = 19.6: N = m (g − v_0²/R) < 0 at the top, it leaves at once
    spec = tmp_path / "fast.dyn"
    spec.write_text(DOME.format(m="0.5 kg", R="2 m", v_0="5 m/s"))
    result = run_cli(spec, "--until", "lost(dome)")
    assert result.exit_code == 2
    assert "N_dome = -1.345 N at the start" in result.output
    wrong = run_cli(spec, "--until", "lost(loop)")
    assert wrong.exit_code == 2 and "no circular path 'loop'" in wrong.output


def test_without_the_event_a_sign_change_of_n_is_shown_not_passed_over(tmp_path: Path) -> None:
    spec = tmp_path / "dome.dyn"
    spec.write_text(DOME.format(m="0.5 kg", R="2 m", v_0="1 m/s"))
    result = run_cli(spec, "--t-end", "1 s")
    assert result.exit_code == 0, result.output
    assert "note: N_dome changes sign at t = 0.907255" in result.output


def test_the_help_names_the_event() -> None:
    result = CliRunner().invoke(app, ["simulate", "--help"], terminal_width=200)
    assert "lost(PATH)" in result.output and "slack(CORD)" in result.output


def test_released_from_rest_off_the_top_of_a_dome_not_at_the_origin() -> None:
    # Hand (θ from the top, released from rest at θ₀): v² = 2 g R (cos θ₀ − cos θ) and
    # m g cos θ = m v²/R at N = 0 → cos θ = (2/3) cos θ₀; θ₀ = 30°: θ = 54.73561°, turned
    # θ − θ₀ = 24.73561° ccw (it starts left of the top); drop R (cos θ₀ − cos θ) = R cos θ₀/3
    text = (
        "given:\n  m = 1 kg\n  R = 2 m\n  c = 1 m\n  d = 3 m\n  a = 30 deg\nscene:\n"
        "  path dome: (x - c)^2 + (y - d)^2 = R^2\n"
        "  body block: particle, mass m, at (c - R*sin(a), d + R*cos(a))\n  gravity\n"
    )
    history = simulate_spec(parse_spec(text, "off.dyn"), "lost(dome)")
    ((_, _, q, _),) = [e for e in history.events if e[0] == "lost(dome)"]
    theta = math.acos(2 / 3 * math.cos(math.radians(30)))
    assert q == pytest.approx(theta - math.radians(30), rel=1e-9)
    assert history.contact is not None
    assert history.contact.from_top(q) == pytest.approx(theta, rel=1e-9)
    assert history.contact.rise(q) == pytest.approx(-2 * math.cos(math.radians(30)) / 3, rel=1e-9)


def test_uniform_motion_round_a_ring_never_loses_contact(tmp_path: Path) -> None:
    # no gravity: N = m v²/R = 1·9/2 = 4.5 N throughout, the contact is never lost
    spec = tmp_path / "ring.dyn"
    spec.write_text(
        "given:\n  m = 1 kg\n  R = 2 m\n  v = 3 m/s\nscene:\n  path ring: x^2 + y^2 = R^2\n"
        "  body bead: particle, mass m, at (R, 0)\n  velocity bead: v, up\n"
    )
    result = run_cli(spec, "--until", "lost(ring)", "--t-end", "1 s")
    assert result.exit_code == 2
    assert "stays between 4.5 and 4.5 N (N does not change: it never will)" in result.output


def test_an_until_event_not_met_by_a_chain_is_said_too(tmp_path: Path) -> None:
    # a double pendulum released level cannot swing its top rod to −90° in 0.1 s
    spec = tmp_path / "double.dyn"
    spec.write_text(
        "given:\n  m = 2 kg\n  L = 1 m\n  level = 0 deg\nscene:\n  point O: (0, 0)\n"
        "  bar OA: O to A, length L, angle level, mass m\n"
        "  bar AB: A to B, length L, angle level, mass m\n  gravity\n"
    )
    result = run_cli(spec, "--t-end", "0.1 s", "--until", "theta(OA) = -90 deg")
    assert result.exit_code == 2
    assert "the event 'theta(OA) = -90 deg' was not met by t = 0.1 s" in result.output
