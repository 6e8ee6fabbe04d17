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
from dynsolve.pipeline import solve_text

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


CLUTCH = """\
problem: Two rotors locked by a clutch
units: SI
given:
  m_A = {m_A}
  k_A = 0.3 m
  m_B = {m_B}
  k_B = 0.2 m
  w_A = {w_A}
  w_B = {w_B}
scene:
  point O: (0, 0)
  body A: mass m_A, gyration k_A, at (0, 0)
  body B: mass m_B, gyration k_B, at (0, 0)
  pin A at O
  pin B at O
  omega A: w_A ccw
  omega B: w_B cw
  clutch A with B
find: w = omega_after(A), w_2 = omega_after(B), dE = energy_lost
"""


@pytest.mark.parametrize("mode", MODES)
def test_a_clutch_gives_both_rotors_one_speed_and_loses_energy(tmp_path: Path, mode: str):
    # I_A = 20·0.09 = 1.8, I_B = 10·0.04 = 0.4: ω = (180 − 16)/2.2 = 74.545 ccw (both);
    # ΔE = 9320 − 1.1 ω² = 3207.27 J
    text = CLUTCH.format(m_A="20 kg", m_B="10 kg", w_A="100 rad/s", w_B="40 rad/s")
    report = solved(write(tmp_path, text), mode)
    got = answers(report)
    assert got["w"]["value"] == pytest.approx(164 / 2.2, rel=1e-9)
    assert got["w_2"]["value"] == pytest.approx(164 / 2.2, rel=1e-9)
    assert got["w"]["direction"] == got["w_2"]["direction"] == "ccw"
    assert got["dE"]["value"] == pytest.approx(9320 - 1.1 * (164 / 2.2) ** 2, rel=1e-9)
    assert holds(report)["energy lost in stage 1"] is True


@pytest.mark.parametrize(
    ("old", "new", "message"),
    [
        ("  pin B at O\n", "  point Q: (k_A, 0)\n  pin B at Q\n", "pin both at the same point"),
        ("  clutch A with B\n", "  couple M on B: ccw\n  clutch A with B\n", "M on B would"),
        ("body B: mass m_B, gyration k_B,", "body B: particle, mass m_B,", "B is a particle"),
    ],
)
def test_a_clutch_off_one_axis_or_under_a_load_is_refused(tmp_path: Path, old, new, message):
    text = CLUTCH.format(m_A="20 kg", m_B="10 kg", w_A="100 rad/s", w_B="40 rad/s")
    text = text.replace(old, new).replace("  w_B = 40 rad/s\n", "  w_B = 40 rad/s\n  M = 5 N*m\n")
    if "particle" in new:
        text = text.replace("  omega B: w_B cw\n", "")
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2
    assert message in result.output


SKATER = """\
problem: Skater on a pivot
units: SI
given:
  m = 60 kg
  I_1 = 3.5 kg*m^2
  I_2 = 1.2 kg*m^2
  w_1 = 3 rad/s
scene:
  point O: (0, 0)
  body skater: mass m, inertia I_1, at (0, 0)
  pin skater at O
  omega skater: w_1 ccw
  gravity
  change skater: inertia I_2
find: w_2 = omega_after(skater), dE = energy_lost, T_2 = T(skater, 2), H_2 = H(skater, O, 2)
"""


@pytest.mark.parametrize("mode", MODES)
def test_a_skater_pulling_in_the_arms_spins_faster_and_gains_energy(tmp_path: Path, mode: str):
    # I₁ω₁ = I₂ω₂: ω₂ = 3.5·3/1.2 = 8.75 rad/s ccw; T₂ = ½·1.2·8.75² = 45.9375 J with the
    # new inertia; T₁ − T₂ = 15.75 − 45.9375 = −30.1875 J; H₂ = 1.2·8.75 = 10.5 = I₁ω₁
    report = solved(write(tmp_path, SKATER), mode)
    got = answers(report)
    assert got["w_2"]["value"] == pytest.approx(8.75, rel=1e-9)
    assert got["w_2"]["direction"] == "ccw"
    assert got["T_2"]["value"] == pytest.approx(45.9375, rel=1e-9)
    assert got["dE"]["value"] == pytest.approx(-30.1875, rel=1e-9)
    assert got["H_2"]["value"] == pytest.approx(10.5, rel=1e-9)
    assert report["passed"]


def test_a_pinned_body_changing_its_inertia_with_its_weight_off_the_pin_is_refused(
    tmp_path: Path,
):
    # the pin 0.1 m above G: the weight's moment about it would change H_O over the change
    text = SKATER.replace("  point O: (0, 0)\n", "  point O: (0, r)\n").replace(
        "  w_1 = 3 rad/s\n", "  w_1 = 3 rad/s\n  r = 0.1 m\n"
    )
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2
    assert "moment about the pin" in result.output


def test_a_particle_cannot_change_its_inertia(tmp_path: Path):
    text = SKATER.replace("body skater: mass m, inertia I_1,", "body skater: particle, mass m,")
    text = text.replace("  pin skater at O\n  omega skater: w_1 ccw\n", "")
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2
    assert "skater is a particle" in result.output
    assert "spec.dyn:12:10:" in result.output  # the change line, at its body


@settings(max_examples=5, deadline=None)
@given(
    m_A=st.floats(1.0, 100.0),
    m_B=st.floats(1.0, 100.0),
    w_A=st.floats(1.0, 300.0),
    w_B=st.integers(0, 300),
)
def test_the_clutch_meets_the_formula_and_never_creates_energy(
    tmp_path_factory: pytest.TempPathFactory, m_A: float, m_B: float, w_A: float, w_B: int
):
    # I_A ω_A − I_B ω_B = (I_A + I_B) ω (B turns cw); ΔE = ½ I_A I_B (ω_A + ω_B)²/(I_A + I_B) ≥ 0
    text = CLUTCH.format(m_A=f"{m_A} kg", m_B=f"{m_B} kg", w_A=f"{w_A} rad/s", w_B=f"{w_B} rad/s")
    got = answers(solved(write(tmp_path_factory.mktemp("clutch"), text), "numeric"))
    I_A, I_B = m_A * 0.09, m_B * 0.04
    omega = (I_A * w_A - I_B * w_B) / (I_A + I_B)
    signed = got["w"]["value"] * (1 if got["w"]["direction"] != "cw" else -1)
    assert signed == pytest.approx(omega, rel=1e-9, abs=1e-9)
    lost = 0.5 * I_A * I_B * (w_A + w_B) ** 2 / (I_A + I_B)
    assert got["dE"]["value"] == pytest.approx(lost, rel=1e-9)


def test_h_about_a_point_after_a_travel_is_refused_not_taken_from_the_old_place(tmp_path: Path):
    # a ball dropped by h: its G at state 2 is h lower, which H(ball, O, 2) would need
    text = """\
problem: Dropped ball
units: SI
given:
  m = 1 kg
  h = 2 m
scene:
  point O: (h, 0)
  body ball: particle, mass m, at (0, h)
  gravity
  travel ball: by h, down
find: H = H(ball, O, 2)
"""
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2
    assert "not followed after a travel" in result.output


def test_h_about_g_after_a_travel_is_the_spin_alone(tmp_path: Path):
    # a particle has no H about its own G: 0 after its fall; H(ball, O, 1) = 0 (at rest)
    text = """\
problem: Dropped ball
units: SI
given:
  m = 1 kg
  h = 2 m
scene:
  point O: (h, 0)
  body ball: particle, mass m, at (0, h)
  gravity
  travel ball: by h, down
find: H_1 = H(ball, O, 1), p_2 = p(ball, 2)
"""
    got = answers(solved(write(tmp_path, text)))
    assert got["H_1"]["value"] == pytest.approx(0, abs=1e-12)
    # p₂ = m √(2 g h) = √(2·9.81·2) = 6.264184 kg·m/s down
    assert got["p_2"]["value"] == pytest.approx(math.sqrt(2 * 9.81 * 2), rel=1e-9)
    assert got["p_2"]["direction"] == "down"


def test_an_embedding_bullet_may_leave_the_line_out(tmp_path: Path):
    # the same bullet into the disk rim as above, struck along its velocity: 10/1.2625 cw
    text = DISK.format(m="50 g", v="400 m/s", M="10 kg", r="0.5 m", sense="right")
    text = text.replace("e 0, line right", "e 0")
    got = answers(solved(write(tmp_path, text)))
    assert got["w"]["value"] == pytest.approx(10 / 1.2625, rel=1e-9)
    assert got["w"]["direction"] == "cw"


def test_a_rebound_without_its_line_is_refused_at_the_impact(tmp_path: Path):
    # with e > 0 the line of impact is the contact's normal: it is not guessed
    text = ROD.format(impact="impact ball with rod: e e")
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2
    assert "needs its line of impact" in result.output
    assert "spec.dyn:16:10:" in result.output


def test_a_bullet_drawn_away_from_the_disk_fails_the_placement_check(tmp_path: Path):
    # drawn 4 r to the left on its line: H before is the same, but m r_A² after would be
    # 17 r² instead of r², a wrong answer; |r_A| = √17·0.5 = 2.06 m > the rim's 0.5 m
    text = DISK.format(m="50 g", v="400 m/s", M="10 kg", r="0.5 m", sense="right")
    text = text.replace("at (0, r)", "at (-4*r, r)")
    result = run("solve", write(tmp_path, text), "-f", "json")
    assert result.exit_code == 1
    report = json.loads(result.stdout)
    assert holds(report)["bullet on disk in stage 1"] is False
    assert not report["passed"]


def test_a_particle_carrying_another_into_a_pinned_body_is_refused(tmp_path: Path):
    # after the bullet embeds in the block they move as one (masses added): the pinned impact
    # would count the block alone, so it is refused with its line
    text = ROD.format(impact="impact bullet with ball: e 0, line right")
    text = text.replace(
        "  body ball: particle, mass m, at (0, -L)\n",
        "  body ball: particle, mass m, at (0, -L)\n  body bullet: particle, mass m, at (-L, -L)\n",
    ).replace("velocity ball: v_0, right", "velocity bullet: v_0, right")
    text = text.replace("find:", "  impact ball with rod: e 0, line right\nfind:")
    text = text.replace(
        "\nfind: w = omega_after(rod), v = v_after(ball), dE = energy_lost",
        "\nfind: w = omega_after(rod)",
    )
    result = run("solve", write(tmp_path, text))
    assert result.exit_code == 2, result.output
    assert "moves with bullet since a plastic impact" in result.output


def test_a_strike_on_a_body_with_no_size_is_not_shown_as_checked() -> None:
    """The disk given only its inertia has no rim to check the bullet's place against:
    "bullet on disk" was shown ✓ with the words "stated, not checked". It is not run (–).
    The answers are the rim problem's (I_O = ½ M r² = 1.25 kg·m² given directly):
    ω₂ = m v₀ r/(I_O + m r²) = 10/1.2625 = 7.920792 rad/s."""
    path = Path(__file__).parent.parent / "problems/angular_momentum/bullet_disk_rim.dyn"
    text = path.read_text().replace(
        "body disk: mass M, disk r, at (0, 0)", "body disk: mass M, inertia I_O, at (0, 0)"
    )
    text = text.replace("  r   = 0.5 m", "  I_O = 1.25 kg*m^2\n  r   = 0.5 m")
    solution = solve_text(text, "no_size.dyn")
    (placed,) = [a for a in solution.assumptions if a.name == "bullet on disk in stage 1"]
    assert placed.status == "not_run"
    omega = {a.name: float(a.value) for a in solution.answers}["omega_2"]
    assert omega == pytest.approx(7.920792, rel=1e-6)
