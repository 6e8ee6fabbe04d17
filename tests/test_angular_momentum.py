"""Angular momentum from scenes (Hibbeler ch. 19): the finds H(B[, P][, k]) and p(B[, k]),
and a particle striking a pinned body (its angular momentum about the pin kept), through
the CLI in every mode. Expected numbers are hand derivations cited beside each test (the
bundled problems carry theirs in their comments).
"""

import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner, Result

from dynsolve.cli import app

ROOT = Path(__file__).resolve().parent.parent
BUNDLED = ROOT / "problems" / "angular_momentum"
MODES = ("exact", "numeric", "auto")


def run(*args: str | Path) -> Result:
    """Invoke the CLI; fail on any exception other than the normal exit."""
    result = CliRunner().invoke(app, [str(a) for a in args])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"uncaught {result.exception!r}") from result.exception
    assert "Traceback" not in result.output
    return result


def solved(path: Path, mode: str = "exact") -> dict:
    result = run("solve", path, "--mode", mode, "-f", "json")
    return json.loads(result.stdout)


def answers(report: dict) -> dict:
    return {a["name"]: a for a in report["answers"]}


def holds(report: dict) -> dict:
    return {a["name"]: a["holds"] for a in report["assumptions"]}


DISK = """\
problem: Bullet into a pinned disk's rim
units: SI
given:
  m = {m}
  v_0 = {v}
  M = {M}
  r = {r}
scene:
  point O: (0, 0)
  body disk: mass M, disk r, at (0, 0)
  body bullet: particle, mass m, at (0, r)
  pin disk at O
  velocity bullet: v_0, {sense}
  impact bullet with disk: e 0, line {sense}
find: w = omega_after(disk), v = v_after(bullet), dE = energy_lost
"""


def write(tmp_path: Path, text: str, name: str = "spec.dyn") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("path", sorted(BUNDLED.glob("*.dyn")), ids=lambda p: p.stem)
def test_every_bundled_problem_meets_its_hand_key_in_every_mode(path: Path, mode: str):
    result = run("check", path, "--mode", mode)
    assert result.exit_code == 0, result.output
    assert "1 passed, 0 failed" in result.output


@pytest.mark.parametrize("mode", MODES)
def test_the_bullet_into_the_disk_rim_is_hibbelers_formula(tmp_path: Path, mode: str):
    # 50 g at 400 m/s into the top of a 10-kg, 0.5-m disk pinned at its centre:
    # ω₂ = m v r/(½ M r² + m r²) = 10/1.2625 = 7.920792 rad/s, cw (the top moves right);
    # ΔE = ½ m v² − (m v r)²/(2 I) = 4000 − 100/2.525 = 3960.396 J
    path = write(tmp_path, DISK.format(m="50 g", v="400 m/s", M="10 kg", r="0.5 m", sense="right"))
    report = solved(path, mode)
    got = answers(report)
    assert got["w"]["value"] == pytest.approx(10 / 1.2625, rel=1e-9)
    assert got["w"]["direction"] == "cw"
    assert got["v"]["value"] == pytest.approx(0.5 * 10 / 1.2625, rel=1e-9)
    assert got["dE"]["value"] == pytest.approx(4000 - 100 / 2.525, rel=1e-9)
    assert all(holds(report).values()) and report["passed"]


def test_a_bullet_moving_away_fails_the_approach_check(tmp_path: Path):
    # the line of impact written right, the bullet moving left: it does not strike the disk
    text = DISK.format(m="50 g", v="400 m/s", M="10 kg", r="0.5 m", sense="right")
    text = text.replace("velocity bullet: v_0, right", "velocity bullet: v_0, left")
    result = run("solve", write(tmp_path, text), "-f", "json")
    assert result.exit_code == 1
    report = json.loads(result.stdout)
    assert holds(report)["approach in stage 1"] is False
    assert not report["passed"]


ROD = """\
problem: Ball strikes a hanging rod
units: SI
given:
  m = 0.5 kg
  v_0 = 5 m/s
  M = 3 kg
  L = 1 m
  e = 0.6
scene:
  point O: (0, 0)
  body rod: mass M, rod L, at (0, -L/2)
  body ball: particle, mass m, at (0, -L)
  pin rod at O
  velocity ball: v_0, right
  gravity
  {impact}
find: w = omega_after(rod), v = v_after(ball), dE = energy_lost
"""


@pytest.mark.parametrize(
    "impact", ["impact ball with rod: e e, line right", "impact rod with ball: e e, line left"]
)
def test_restitution_at_the_struck_point_either_way_round(tmp_path: Path, impact: str):
    # I_O = M L²/3 = 1; H_O: 2.5 = ω + 0.5 v_b; e: 0.6·5 = ω L − v_b → v_b = −1/3, ω = 8/3 ccw;
    # ΔE = 6.25 − (0.5/9 + 64/9)/2 = 8/3 J. The pinned body named first (the line then from
    # it toward the ball) is the same impact.
    report = solved(write(tmp_path, ROD.format(impact=impact)))
    got = answers(report)
    assert got["w"]["value"] == pytest.approx(8 / 3, rel=1e-9)
    assert got["w"]["direction"] == "ccw"
    assert got["v"]["value"] == pytest.approx(1 / 3, rel=1e-9)
    assert got["v"]["direction"] == "left"
    assert got["dE"]["value"] == pytest.approx(8 / 3, rel=1e-9)
    checks = holds(report)
    assert checks["separation in stage 1"] and checks["energy lost in stage 1"]


def test_a_rod_spinning_before_the_impact_keeps_its_own_angular_momentum(tmp_path: Path):
    # the rod already turns at 2 rad/s cw: H_O1 = I_O ω₁ + m v_0 L = −2 + 2.5 = 0.5,
    # e: 0.6 (5 − (−2)) = ω₂ − v_b, 0.5 = ω₂ + 0.5 v_b → 1.5 v_b = 0.5 − 4.2, v_b = −37/15,
    # ω₂ = 4.2 + v_b = 26/15 rad/s ccw
    text = ROD.format(impact="impact ball with rod: e e, line right")
    text = text.replace("  gravity\n", "  omega rod: w_1 cw\n  gravity\n")
    text = text.replace("  e = 0.6\n", "  e = 0.6\n  w_1 = 2 rad/s\n")
    got = answers(solved(write(tmp_path, text)))
    assert got["w"]["value"] == pytest.approx(26 / 15, rel=1e-9)
    assert got["w"]["direction"] == "ccw"
    assert got["v"]["value"] == pytest.approx(37 / 15, rel=1e-9)


def test_a_particle_held_by_a_cord_is_refused_with_its_line(tmp_path: Path):
    text = ROD.format(impact="impact ball with rod: e e, line right")
    text = text.replace(
        "  gravity\n", "  point Q: (-L, -L)\n  link cord: ball at G to Q\n  gravity\n"
    )
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2
    assert "cord would take part in the impulse" in result.output
    assert "spec.dyn:18:10:" in result.output  # the impact line, at its first body


@pytest.mark.parametrize(
    ("find", "message"),
    [
        ("H = H(rod, nowhere)", "no point 'nowhere'"),
        ("H = H(rod, O, 7)", "no state '7'"),
        ("H = H(rdo, O)", "did you mean 'rod'"),
    ],
)
def test_momentum_finds_report_bad_arguments(tmp_path: Path, find: str, message: str):
    text = ROD.format(impact="impact ball with rod: e e, line right")
    text = text.replace(
        "find: w = omega_after(rod), v = v_after(ball), dE = energy_lost", f"find: {find}"
    )
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2
    assert message in result.output


PINNED = """\
problem: Angular momentum of a pinned rod
units: SI
given:
  M = 3 kg
  L = 1 m
  w = 2 rad/s
scene:
  point O: (0, 0)
  body rod: mass M, rod L, at (L/2, 0)
  pin rod at O
  omega rod: w ccw
  gravity
find: H_G = H(rod), H_O = H(rod, O), p = p(rod)
"""


@pytest.mark.parametrize("mode", MODES)
def test_a_pinned_body_given_its_spin_moves_its_centre_with_it(tmp_path: Path, mode: str):
    # a horizontal rod about its end at 2 rad/s ccw: H_G = (M L²/12) ω = 0.5,
    # H_O = (M L²/3) ω = 2 kg·m²/s, p = M ω L/2 = 3 kg·m/s up (G moves with ω k × r_G/O)
    got = answers(solved(write(tmp_path, PINNED), mode))
    assert got["H_G"]["value"] == pytest.approx(0.5, rel=1e-9)
    assert got["H_O"]["value"] == pytest.approx(2, rel=1e-9)
    assert got["H_O"]["direction"] == "ccw" and got["H_O"]["unit"] == "kg*m^2/s"
    assert got["p"]["value"] == pytest.approx(3, rel=1e-9)
    assert got["p"]["direction"] == "up"


@settings(max_examples=5, deadline=None)
@given(
    m=st.floats(0.01, 1.0),
    v=st.floats(10.0, 500.0),
    M=st.floats(1.0, 50.0),
    r=st.floats(0.1, 2.0),
)
def test_the_embedded_bullet_meets_the_formula_and_never_creates_energy(
    tmp_path_factory: pytest.TempPathFactory, m: float, v: float, M: float, r: float
):
    # ω₂ = m v r/(½ M r² + m r²), cw; ΔE = ½ m v² − ½ I ω₂² ≥ 0 (always: I ω₂² = m v ω₂ r ·
    # m r²/I ≤ m v²)
    text = DISK.format(m=f"{m} kg", v=f"{v} m/s", M=f"{M} kg", r=f"{r} m", sense="right")
    path = write(tmp_path_factory.mktemp("disk"), text)
    got = answers(solved(path, "numeric"))
    inertia = 0.5 * M * r**2 + m * r**2
    omega = m * v * r / inertia
    assert got["w"]["value"] == pytest.approx(omega, rel=1e-9)
    assert got["dE"]["value"] == pytest.approx(0.5 * m * v**2 - 0.5 * inertia * omega**2, rel=1e-9)
    assert got["dE"]["value"] >= 0 and not math.isnan(got["dE"]["value"])
