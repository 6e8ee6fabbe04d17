"""Planar linkages in scenes (issue 11): bars, joints, sliders, loop closure, assemblies,
relative velocity and acceleration, toggle positions and degrees of freedom.

Every expected number is from the textbook (Hibbeler 12e Example 16.6) or from a hand
derivation written out below, independent of dynsolve (circle intersections and 2×2
solves in plain Python/mpmath).
"""

import math
from pathlib import Path

import mpmath
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

PROBLEMS = Path(__file__).parent.parent / "problems" / "linkages"


def answers(solution) -> dict:
    return {a.name: a for a in solution.answers}


def signed(answer, positive: str) -> float:
    """An answer's value with the sign its direction word gives (ccw/right positive)."""
    return answer.value if answer.direction == positive else -answer.value


# ---- the three bundled problems ------------------------------------------------------


def test_blocks_in_slots_hibbeler_16_6():
    """Hibbeler 12e Example 16.6: v_B = 2 m/s →, ω_AB = 14.1 rad/s (by hand:
    0 = −v_A + ω L cos 45°, v_B = ω L sin 45°)."""
    solution = solve_file(PROBLEMS / "blocks_in_slots.dyn")
    found = answers(solution)
    assert not any(c.failed for c in solution.checks)
    omega = 2 / (0.2 * math.cos(math.radians(45)))
    assert found["omega"].value == pytest.approx(omega, rel=1e-12)
    assert found["omega"].direction == "ccw"
    assert found["v_B"].value == pytest.approx(omega * 0.2 * math.sin(math.radians(45)))
    assert found["v_B"].direction == "right"


def slider_crank_by_hand(L_AB, L_BC, theta, omega_AB, alpha_AB=0.0):
    """Slider-crank with the piston on the horizontal through A (Hibbeler 16.5, 16.7):
    B = L_AB (cos θ, sin θ); C = (x_B + √(L_BC² − y_B²), 0);
    v_B = ω_AB k × r_B; y: 0 = v_By + ω_BC (x_C − x_B); x: v_C = v_Bx − ω_BC (0 − y_B);
    a_B = α_AB k × r_B − ω_AB² r_B;
    y: 0 = a_By + α_BC (x_C − x_B) − ω_BC² (0 − y_B); x: a_C = a_Bx + α_BC y_B − ω_BC² (x_C − x_B).
    """
    xB, yB = L_AB * math.cos(theta), L_AB * math.sin(theta)
    xC = xB + math.sqrt(L_BC**2 - yB**2)
    vBx, vBy = -omega_AB * yB, omega_AB * xB
    w = -vBy / (xC - xB)
    vC = vBx + w * yB
    aBx = -alpha_AB * yB - omega_AB**2 * xB
    aBy = alpha_AB * xB - omega_AB**2 * yB
    alpha = -(aBy + w**2 * yB) / (xC - xB)
    aC = aBx + alpha * yB - w**2 * (xC - xB)
    return w, vC, alpha, aC


def test_slider_crank_rpm_input():
    solution = solve_file(PROBLEMS / "slider_crank_rpm.dyn")
    found = answers(solution)
    assert not any(c.failed for c in solution.checks), [c for c in solution.checks if c.failed]
    omega_AB = -2000 * 2 * math.pi / 60  # 2000 rpm clockwise
    w, vC, alpha, aC = slider_crank_by_hand(0.075, 0.2, math.radians(60), omega_AB)
    assert signed(found["w_BC"], "ccw") == pytest.approx(w, rel=1e-12)
    assert signed(found["v_C"], "right") == pytest.approx(vC, rel=1e-12)
    assert signed(found["alpha_BC"], "ccw") == pytest.approx(alpha, rel=1e-12)
    assert signed(found["a_C"], "right") == pytest.approx(aC, rel=1e-12)
    closure = next(c for c in solution.checks if c.name == "loop closure")
    assert "nearest the sketch" in closure.detail and "other assembly" in closure.detail


def four_bar_by_hand(d, L_AB, L_BC, L_CD, theta, omega_AB, upper=True):
    """Four-bar A(0,0), D(d,0): C where the circles about B (L_BC) and D (L_CD) meet,
    the upper point for the open assembly; then
    v_B + ω_BC k × r_C/B = ω_CD k × r_C/D and
    a_B + α_BC k × r_C/B − ω_BC² r_C/B = α_CD k × r_C/D − ω_CD² r_C/D, each a 2×2 solve."""
    xB, yB = L_AB * math.cos(theta), L_AB * math.sin(theta)
    dx, dy = d - xB, -yB
    dist = math.hypot(dx, dy)
    a = (L_BC**2 - L_CD**2 + dist**2) / (2 * dist)
    h = math.sqrt(L_BC**2 - a**2)
    px, py = xB + a * dx / dist, yB + a * dy / dist
    sign = 1 if upper else -1
    xC, yC = px - sign * h * dy / dist, py + sign * h * dx / dist
    if (yC > 0) != upper:
        xC, yC = px + sign * h * dy / dist, py - sign * h * dx / dist
    rCB, rCD = (xC - xB, yC - yB), (xC - d, yC)
    vB = (-omega_AB * yB, omega_AB * xB)

    def solve2(m11, m12, m21, m22, b1, b2):
        det = m11 * m22 - m12 * m21
        return (b1 * m22 - m12 * b2) / det, (m11 * b2 - b1 * m21) / det

    # unknowns (ω_BC, ω_CD): x: −ω_BC rCB_y + ω_CD rCD_y = −v_Bx; y: ω_BC rCB_x − ω_CD rCD_x = −v_By
    wBC, wCD = solve2(-rCB[1], rCD[1], rCB[0], -rCD[0], -vB[0], -vB[1])
    aB = (-(omega_AB**2) * xB, -(omega_AB**2) * yB)
    bx = -aB[0] + wBC**2 * rCB[0] - wCD**2 * rCD[0]
    by = -aB[1] + wBC**2 * rCB[1] - wCD**2 * rCD[1]
    aBC, aCD = solve2(-rCB[1], rCD[1], rCB[0], -rCD[0], bx, by)
    vC = (-wCD * rCD[1], wCD * rCD[0])
    return wBC, wCD, vC, aBC, aCD, (xC, yC)


def test_four_bar_open_assembly():
    solution = solve_file(PROBLEMS / "four_bar_open.dyn")
    found = answers(solution)
    assert not any(c.failed for c in solution.checks)
    wBC, wCD, vC, aBC, aCD, _ = four_bar_by_hand(0.25, 0.1, 0.25, 0.15, math.radians(60), 6.0)
    assert signed(found["w_BC"], "ccw") == pytest.approx(wBC, rel=1e-12)
    assert signed(found["w_CD"], "ccw") == pytest.approx(wCD, rel=1e-12)
    assert found["v_C"].value == pytest.approx(math.hypot(*vC), rel=1e-12)
    assert "to the left" in found["v_C"].direction and vC[0] < 0
    assert signed(found["alpha_BC"], "ccw") == pytest.approx(aBC, rel=1e-12)
    assert signed(found["alpha_CD"], "ccw") == pytest.approx(aCD, rel=1e-12)


FOUR_BAR = """\
given:
  d = 250 mm
  L_AB = 100 mm
  L_BC = 250 mm
  L_CD = 150 mm
  theta = 60 deg
  omega_0 = 6 rad/s
scene:
  point A: (0, 0)
  point D: (d, 0)
  bar AB: A to B, length L_AB, angle theta
  bar BC: B to C, length L_BC
  bar CD: C to D, length L_CD
  omega AB: omega_0 ccw
{rule}
find: w_CD = omega(CD), y_C = v_y(C), angle_CD = theta(CD)
"""


def test_crossed_branch_is_the_other_assembly():
    solution = solve_text(FOUR_BAR.format(rule="  branch crossed"), "crossed.dyn")
    _, wCD, vC, *_ = four_bar_by_hand(0.25, 0.1, 0.25, 0.15, math.radians(60), 6.0, upper=False)
    assert signed(answers(solution)["w_CD"], "ccw") == pytest.approx(wCD, rel=1e-12)
    assert answers(solution)["y_C"].value == pytest.approx(vC[1], rel=1e-12)


def test_sketch_position_picks_the_assembly():
    solution = solve_text(FOUR_BAR.format(rule="  joint C: near (d, -L_CD)"), "near.dyn")
    _, wCD, _, _, _, (xC, yC) = four_bar_by_hand(
        0.25, 0.1, 0.25, 0.15, math.radians(60), 6.0, upper=False
    )
    assert signed(answers(solution)["w_CD"], "ccw") == pytest.approx(wCD, rel=1e-12)
    angle = math.degrees(math.atan2(0 - yC, 0.25 - xC))  # from C to D
    assert answers(solution)["angle_CD"].value == pytest.approx(angle, rel=1e-9)


def test_two_assemblies_without_a_rule_is_an_error_listing_both():
    with pytest.raises(SpecError) as error:
        solve_text(FOUR_BAR.format(rule=""), "norule.dyn")
    message = str(error.value)
    assert "2 ways" in message and "branch open" in message and "near" in message


# ---- the seed notes' slider-crank, in general ---------------------------------------

SEED_SLIDER_CRANK = """\
given:
  L: m
  theta_1: rad
  theta_2: rad
  omega_1: rad/s
  alpha_1: rad/s^2
scene:
  point A: (0, 0)
  bar AB: A to B
  bar BC: B to C
  joint B: (L*cos(theta_1), L*sin(theta_1))
  joint C: (L*cos(theta_1) + L*cos(theta_2), 0)
  slider C: along right, through A
  omega AB: omega_1 ccw
  alpha AB: alpha_1 ccw
find: w_BC = omega(BC), v_C = v(C)
"""


def test_seed_slider_crank_symbolic():
    """Seed notes 001, slider-crank with L_AB = L_BC = L, eq. (5):
    ω_BC = −(cos θ₁ / cos θ₂) ω_AB. By hand, x_C = L cos θ₁ + L cos θ₂ with BC's
    direction at −θ₂ gives v_C = −L ω_AB sin θ₁ (1 + cos θ₁ / cos θ₂)."""

    solution = solve_text(SEED_SLIDER_CRANK, "seed.dyn")
    found = answers(solution)
    L, t1, t2, w = sympy.symbols("L theta_1 theta_2 omega_1", positive=True)
    names = {"L": L, "theta_1": t1, "theta_2": t2, "omega_1": w}
    from dynsolve.expressions import to_sympy
    from dynsolve.spec.parser import parse_spec

    def formula(text):  # the answer's printed formula, read back with the real parser
        expr = parse_spec(f"equations:\n  y = {text}\nfind: y\n").equations[0].rhs
        return to_sympy(expr, names)

    got_w = formula(found["w_BC"].formula.replace("θ_", "theta_").replace("ω_", "omega_"))
    assert sympy.simplify(got_w + sympy.cos(t1) / sympy.cos(t2) * w) == 0
    got_v = formula(found["v_C"].formula.replace("θ_", "theta_").replace("ω_", "omega_"))
    assert sympy.simplify(got_v + L * w * sympy.sin(t1) * (1 + sympy.cos(t1) / sympy.cos(t2))) == 0


# ---- toggle positions -----------------------------------------------------------------

TOGGLE = """\
given:
  d = 4 m
  L_AB = 3 m
  L_BC = 2 m
  L_CD = 3 m
  theta = {theta} deg
  w = 1 rad/s
scene:
  point A: (0, 0)
  point D: (d, 0)
  bar AB: A to B, length L_AB, angle theta
  bar BC: B to C, length L_BC
  bar CD: C to D, length L_CD
  branch open
  omega AB: w ccw
find: w_BC = omega(BC), w_CD = omega(CD)
"""


def test_exactly_at_toggle_the_error_says_so():
    """A(0,0), AB = 3 at 90° puts B at (0, 3), 5 from D(4, 0) = BC + CD: BC and CD in line."""
    with pytest.raises(SpecError) as error:
        solve_text(TOGGLE.format(theta="90"), "toggle.dyn")
    assert "toggle" in str(error.value) and "BC and CD lie in one line" in str(error.value)


def test_near_toggle_stays_accurate_and_reports_conditioning():
    """θ = 89.987°: BC and CD meet at an angle whose cosine is ≈ −0.99 (sin ≈ 0.03 from
    the toggle). Reference: the same hand derivation in 50-digit arithmetic."""
    theta = mpmath.mpf("89.987")
    with mpmath.workdps(50):
        t = theta * mpmath.pi / 180
        xB, yB = 3 * mpmath.cos(t), 3 * mpmath.sin(t)
        dx, dy = 4 - xB, -yB
        dist = mpmath.sqrt(dx**2 + dy**2)
        a = (4 - 9 + dist**2) / (2 * dist)
        h = mpmath.sqrt(4 - a**2)
        candidates = [
            (xB + a * dx / dist - s * h * dy / dist, yB + a * dy / dist + s * h * dx / dist)
            for s in (1, -1)
        ]
        xC, yC = max(candidates, key=lambda c: c[1])  # open: C above AD
        rCB, rCD = (xC - xB, yC - yB), (xC - 4, yC)
        sine = (rCB[0] * rCD[1] - rCB[1] * rCD[0]) / (2 * 3)
        vB = (-yB, xB)
        m = mpmath.matrix([[-rCB[1], rCD[1]], [rCB[0], -rCD[0]]])
        wBC, wCD = mpmath.lu_solve(m, mpmath.matrix([-vB[0], -vB[1]]))
    assert 0.02 < abs(float(sine)) < 0.04
    solution = solve_text(TOGGLE.format(theta="89.987"), "near_toggle.dyn")
    found = answers(solution)
    assert signed(found["w_BC"], "ccw") == pytest.approx(float(wBC), rel=1e-9)
    assert signed(found["w_CD"], "ccw") == pytest.approx(float(wCD), rel=1e-9)
    note = next(c for c in solution.checks if c.name == "conditioning")
    assert "condition number" in note.detail


# ---- bad input: the error says why -----------------------------------------------------

SLIDER_CRANK = """\
given:
  L_AB = {L_AB}
  L_BC = 200 mm
  theta = 60 deg
  n = 2000 rpm
scene:
  point A: (0, 0)
  bar AB: A to B, length L_AB, angle theta
  bar BC: B to C, length L_BC
  slider C: along {guide}, through A
  joint C: near (L_BC, 0)
{drives}
find: {find}
"""


def crank(L_AB="75 mm", guide="right", drives="  omega AB: n cw", find="w = omega(BC)"):
    return SLIDER_CRANK.format(L_AB=L_AB, guide=guide, drives=drives, find=find)


@pytest.mark.parametrize(
    ("text", "words"),
    [
        (crank(drives=""), ["1 degree of freedom", "0 drives", "omega AB"]),
        (
            crank(drives="  omega AB: n cw\n  omega BC: n ccw"),
            ["1 degree of freedom", "2 drives", "drop a drive"],
        ),
        (crank(find="a = a(C)"), ["accelerations are asked", "alpha AB: 0"]),
        (crank(L_AB="300 mm"), ["cannot be assembled"]),
        (crank(find="w = omega(CD)"), ["no bar 'CD'"]),
        (crank(find="w = speed(C)"), ["not a linkage quantity"]),
    ],
)
def test_bad_linkages_get_a_clear_error(text, words):
    with pytest.raises(SpecError) as error:
        solve_text(text, "bad.dyn")
    for word in words:
        assert word in str(error.value)


def test_a_rigid_triangle_cannot_move():
    text = """\
given:
  L = 1 m
  w = 1 rad/s
scene:
  point A: (0, 0)
  point C: (L, 0)
  bar AB: A to B
  bar BC: B to C
  joint B: (L, L)
  omega AB: w ccw
find: w_BC = omega(BC)
"""
    with pytest.raises(SpecError) as error:
        solve_text(text, "rigid.dyn")
    assert "rigid structure" in str(error.value)


def test_a_five_bar_with_one_drive_has_two_degrees_of_freedom():
    """Four moving bars between two fixed pivots: Gruebler's count 3(n − 1) − 2 j with
    n = 5 links (ground included) and j = 5 pins gives 12 − 10 = 2 degrees of freedom;
    one drive leaves 9 velocity unknowns for 8 equations."""
    text = """\
given:
  L = 1 m
  d = 2 m
  theta = 60 deg
  w = 1 rad/s
scene:
  point A: (0, 0)
  point E: (d, 0)
  bar AB: A to B, length L, angle theta
  bar BC: B to C
  bar CD: C to D
  bar DE: D to E, length L
  joint C: (L, 1.5*L)
  joint D: (d, L)
  omega AB: w ccw
find: w_BC = omega(BC)
"""
    with pytest.raises(SpecError) as error:
        solve_text(text, "five_bar.dyn")
    message = str(error.value)
    assert "2 degrees of freedom" in message and "1 drive" in message
    assert "9 unknowns" in message and "8 equations" in message


def test_placed_joints_must_match_the_lengths():
    text = """\
given:
  L = 0.2 m
  v_A = 2 m/s
scene:
  point O: (0, 0)
  bar AB: A to B, length L
  joint A: (0, L)
  joint B: (L, 0)
  slider A: along up, through O
  slider B: along right, through O
  velocity A: v_A, down
find: v_B = v(B)
"""
    with pytest.raises(SpecError) as error:
        solve_text(text, "mismatch.dyn")
    assert "bar AB" in str(error.value) and "length" in str(error.value)


def test_body_lines_are_refused_in_a_linkage():
    text = crank().replace("  point A: (0, 0)\n", "  point A: (0, 0)\n  body piston: mass m\n")
    with pytest.raises(SpecError) as error:
        solve_text(text, "body.dyn")
    assert "'body' line cannot go in a linkage scene" in str(error.value)


# ---- through the command line ---------------------------------------------------------


def test_cli_solves_a_linkage_and_positions_errors(tmp_path):
    runner = CliRunner()
    result = runner.invoke(app, ["solve", str(PROBLEMS / "four_bar_open.dyn")])
    assert result.exit_code == 0, result.output
    assert "linkage mode" in result.output and "loop closure" in result.output
    bad = tmp_path / "bad.dyn"
    bad.write_text(TOGGLE.format(theta="90"))
    result = runner.invoke(app, ["solve", str(bad)])
    assert result.exit_code == 2
    assert "bad.dyn:12:" in result.output and "toggle" in result.output


# ---- properties -------------------------------------------------------------------------


@settings(max_examples=12, deadline=None)
@given(k=st.integers(-3, 3), degrees=st.integers(5, 175))
def test_scaling_lengths_keeps_omega_and_scales_speeds(k, degrees):
    """Lengths × 10^k: every ω is unchanged, every speed is × 10^k (same crank ω)."""
    scale = 10.0**k

    def run(factor):
        text = crank(L_AB=f"{75 * factor} mm", find="w = omega(BC), v = v(C)")
        text = text.replace("L_BC = 200 mm", f"L_BC = {200 * factor} mm")
        text = text.replace("theta = 60 deg", f"theta = {degrees} deg")
        return answers(solve_text(text, "scaled.dyn"))

    base, scaled = run(1.0), run(scale)
    assert signed(scaled["w"], "ccw") == pytest.approx(signed(base["w"], "ccw"), rel=1e-9)
    assert scaled["v"].value * 1 == pytest.approx(base["v"].value * scale, rel=1e-9)


# ---- a pin sliding in the slot of a rotating bar (rotating axes) ---------------------


def test_quick_return_slot_with_coriolis():
    """Crank AB (0.2 m, 3 rad/s ccw, θ = 30°) drives the slotted link CD, C 0.4 m below A.
    By hand (Hibbeler 16.8): r = r_B/C, e = r/|r|, e⊥ = k × e; v_B = ω_AB k × r_B;
    u = v_B·e, ω_CD = v_B·e⊥/|r|; a_B = −ω_AB² r_B;
    a_rel = a_B·e + ω_CD² |r|, α_CD = (a_B·e⊥ − 2 ω_CD u)/|r|."""
    solution = solve_file(PROBLEMS / "quick_return.dyn")
    assert not any(c.failed for c in solution.checks)
    found = answers(solution)
    B = (0.2 * math.cos(math.radians(30)), 0.2 * math.sin(math.radians(30)))
    r = (B[0], B[1] + 0.4)
    size = math.hypot(*r)
    e, perp = (r[0] / size, r[1] / size), (-r[1] / size, r[0] / size)
    vB = (-3 * B[1], 3 * B[0])
    u = vB[0] * e[0] + vB[1] * e[1]
    w = (vB[0] * perp[0] + vB[1] * perp[1]) / size
    aB = (-9 * B[0], -9 * B[1])
    a_rel = aB[0] * e[0] + aB[1] * e[1] + w**2 * size
    alpha = (aB[0] * perp[0] + aB[1] * perp[1] - 2 * w * u) / size
    assert signed(found["w_CD"], "ccw") == pytest.approx(w, rel=1e-12)
    assert signed(found["alpha_CD"], "ccw") == pytest.approx(alpha, rel=1e-12)
    assert found["u"].value == pytest.approx(abs(u), rel=1e-12)
    assert found["a_r"].value == pytest.approx(abs(a_rel), rel=1e-12)
    assert "to the right" in found["u"].direction  # along e (up the slot): u > 0
    assert "to the left" in found["a_r"].direction and a_rel < 0


# ---- kinetics: Newton–Euler on each bar -------------------------------------------------


def test_slider_crank_forces_by_hand():
    """Light crank AB, uniform rod BC (m = 1.5 kg, L = 0.2 m), light piston (Hibbeler
    17.5). Kinematics as above (ω_AB = −100 rad/s); a_G = a_B + α_BC k × h − ω_BC² h with
    h = r_G/B = (r_C − r_B)/2; on BC the pin pushes −B, the guide (0, N_C), gravity −m g:
    B_x = −m a_Gx; −B_y + N_C − m g = m a_Gy; h × B + h_x N_C = I_G α_BC (I_G = m L²/12);
    the light crank: (r_B − r_A) × B + M = 0."""
    solution = solve_file(PROBLEMS / "slider_crank_forces.dyn")
    assert not any(c.failed for c in solution.checks)
    found = answers(solution)
    m, L, g = 1.5, 0.2, 9.81
    theta, w_AB = math.radians(60), -100.0
    w, _, alpha, _ = slider_crank_by_hand(0.075, L, theta, w_AB)
    xB, yB = 0.075 * math.cos(theta), 0.075 * math.sin(theta)
    xC = xB + math.sqrt(L**2 - yB**2)
    h = ((xC - xB) / 2, -yB / 2)
    aB = (-(w_AB**2) * xB, -(w_AB**2) * yB)
    aG = (aB[0] - alpha * h[1] - w**2 * h[0], aB[1] + alpha * h[0] - w**2 * h[1])
    I_G = m * L**2 / 12
    Bx = -m * aG[0]
    By = (I_G * alpha + h[1] * Bx - h[0] * m * (aG[1] + g)) / (2 * h[0])
    N = m * aG[1] + m * g + By
    M = -(xB * By - yB * Bx)
    assert found["M"].value == pytest.approx(M, rel=1e-9)
    assert found["F_B"].value == pytest.approx(math.hypot(Bx, By), rel=1e-9)
    assert found["N_C"].value == pytest.approx(abs(N), rel=1e-9)
    assert found["N_C"].direction == ("up" if N > 0 else "down")


def test_a_driven_linkage_without_its_driving_couple_is_refused():
    text = (PROBLEMS / "slider_crank_forces.dyn").read_text()
    text = text.replace("  couple M on AB: ccw\n", "").replace("find: M, ", "find: ")
    with pytest.raises(SpecError) as error:
        solve_text(text, "no_couple.dyn")
    assert "driving couple or force is missing" in str(error.value)


def test_the_power_check_catches_a_wrong_moment_equation(monkeypatch):
    """Regression guard for the second method: with I_G α dropped from ΣM_G (a wrong
    model), the power equation (no pin forces in it) fails."""
    from dynsolve.linkage import kinetics

    original = kinetics.free_bodies

    def without_inertia(*args, **kwargs):
        free = original(*args, **kwargs)
        wrong = tuple(
            kinetics.Equation(e.lhs, sympy.Integer(0), e.label, e.line, e.note)
            if e.note.startswith("ΣM_G")
            else e
            for e in free.equations
        )
        return kinetics.FreeBodies(wrong, free.unknowns, free.at_joint, free.dims, free.normals)

    monkeypatch.setattr("dynsolve.linkage.problem.free_bodies", without_inertia)
    solution = solve_file(PROBLEMS / "slider_crank_forces.dyn")
    power = next(c for c in solution.checks if c.name == "power equation")
    assert not power.passed


# ---- rolling wheels and gears -------------------------------------------------------------


def test_bar_driven_by_a_rolling_wheel():
    """Wheel r = 0.5 m rolling, ω = 4 rad/s cw; A at 45° on the rim; AB = 1.5 m, B on the
    ground. By hand: K the contact point, v_A = ω k × r_A/K; B = (x_A + √(L² − y_A²), 0);
    y: 0 = v_Ay + ω_AB (x_B − x_A); x: v_B = v_Ax − ω_AB (0 − y_A)."""
    solution = solve_file(PROBLEMS / "wheel_and_bar.dyn")
    assert not any(c.failed for c in solution.checks)
    found = answers(solution)
    w, r, L = -4.0, 0.5, 1.5
    xA, yA = r * math.cos(math.pi / 4), r + r * math.sin(math.pi / 4)
    vA = (-w * yA, w * xA)
    xB = xA + math.sqrt(L**2 - yA**2)
    w_AB = -vA[1] / (xB - xA)
    assert signed(found["w_AB"], "ccw") == pytest.approx(w_AB, rel=1e-12)
    v_B = vA[0] + w_AB * yA
    assert signed(found["v_B"], "right") == pytest.approx(v_B, rel=1e-12)
    # the instantaneous centre of AB: above B (v_B horizontal), at v_B/ω_AB
    assert found["x_IC"].value == pytest.approx(xB, rel=1e-12)
    assert found["y_IC"].value == pytest.approx(v_B / w_AB, rel=1e-12)
    centre = next(c for c in solution.checks if c.name == "instantaneous centre of AB")
    assert centre.passed and "r_B/IC" in centre.detail


def test_planet_gear_on_a_rotating_arm():
    """Fixed sun (r_S = 0.1 m), arm at ω_0 = 5 rad/s ccw, planet r_P = 0.05 m: the planet's
    pitch point on the sun is at rest, so v_B = ω_0 (r_S + r_P) = ω_P r_P."""
    solution = solve_file(PROBLEMS / "planetary.dyn")
    assert not any(c.failed for c in solution.checks)
    found = answers(solution)
    assert signed(found["w_P"], "ccw") == pytest.approx(5 * 0.15 / 0.05, rel=1e-12)
    assert found["v_B"].value == pytest.approx(5 * 0.15, rel=1e-12)


def test_a_gear_train_of_three_gears_on_fixed_centres():
    """A drives B drives C in external mesh, centres fixed: at each pitch point the rims'
    speeds agree, ω_A r_A = ω_B r_B = ω_C r_C, each mesh turning the sense (Hibbeler 16.3),
    so C turns as A does, at ω_A r_A/r_C; the same for α. ω_A = 300 rpm = 10π rad/s cw:
    ω_B = 10π (40/100) = 12.566 rad/s ccw, ω_C = 10π (40/60) = 20.944 rad/s cw,
    α_C = 2 (40/60) = 1.3333 rad/s² cw."""
    text = """\
given:
  r_A = 40 mm
  r_B = 100 mm
  r_C = 60 mm
  n = 300 rpm
  a = 2 rad/s^2
scene:
  point O_A: (0, 0)
  point O_B: (r_A + r_B, 0)
  point O_C: (r_A + 2*r_B + r_C, 0)
  bar gA: O_A
  bar gB: O_B
  bar gC: O_C
  mesh gA with gB: radii r_A, r_B
  mesh gB with gC: radii r_B, r_C
  omega gA: n cw
  alpha gA: a cw
find: w_B = omega(gB), w_C = omega(gC), al_C = alpha(gC)
"""
    solution = solve_text(text, "train.dyn")
    assert not any(c.failed for c in solution.checks)
    found = answers(solution)
    assert signed(found["w_B"], "ccw") == pytest.approx(10 * math.pi * 0.4, rel=1e-12)
    assert signed(found["w_C"], "ccw") == pytest.approx(-10 * math.pi * 40 / 60, rel=1e-12)
    assert signed(found["al_C"], "ccw") == pytest.approx(-2 * 40 / 60, rel=1e-12)


def test_rolling_disk_driven_by_a_couple():
    """A uniform disk rolling with α given: M = (I_G + m r²) α, F = −m α r (against the
    roll), N = m g (Hibbeler 17.5)."""
    text = """\
given:
  m = 10 kg
  r = 0.3 m
  alpha_0 = 2 rad/s^2
scene:
  bar disk: O, mass m
  joint O: (0, r)
  rolls disk: radius r
  omega disk: 0
  alpha disk: alpha_0 ccw
  couple M on disk: ccw
  gravity
find: M, F = F_disk, N = N_disk
"""
    found = answers(solve_text(text, "disk.dyn"))
    assert found["M"].value == pytest.approx((10 * 0.09 / 2 + 10 * 0.09) * 2, rel=1e-12)
    assert found["F"].value == pytest.approx(10 * 2 * 0.3) and found["F"].direction == "left"
    assert found["N"].value == pytest.approx(10 * 9.81) and found["N"].direction == "up"


def test_gears_whose_centres_do_not_fit_their_radii_are_refused():
    text = (
        (PROBLEMS / "planetary.dyn")
        .read_text()
        .replace("joint B: (r_S + r_P, 0)", "joint B: (r_S + 2*r_P, 0)")
    )
    with pytest.raises(SpecError) as error:
        solve_text(text, "gears.dyn")
    assert "radii add up" in str(error.value)


def test_linkage_lines_in_a_scene_of_bodies_are_not_ignored():
    text = """\
given:
  m = 1 kg
scene:
  body b: particle, mass m, at (0, 0)
  alpha b: 0
  gravity
find: a = a_G(b)
"""
    with pytest.raises(SpecError) as error:
        solve_text(text, "bodies.dyn")
    assert "'alpha' describes a linkage" in str(error.value)


# ---- the solution sheet -------------------------------------------------------------------


def test_the_sheet_draws_the_linkage_at_the_instant():
    from dynsolve.render.latex import render_latex

    solution = solve_file(PROBLEMS / "wheel_and_bar.dyn")
    assert solution.linkage is not None
    joints = {name: (x, y, fixed) for name, x, y, fixed in solution.linkage.joints}
    assert joints["O"][:2] == pytest.approx((0.0, 0.5)) and not joints["O"][2]
    assert solution.linkage.grounds == (pytest.approx((0.0, 0.0, 0.0, 1.0)),)
    tex = render_latex(solution, "handout")
    assert "The linkage at the instant" in tex and "\\begin{tikzpicture}" in tex


def test_the_other_assembly_is_reported_and_is_the_mirror_in_bd():
    """A four-bar closes two ways, mirror images of C in the line BD (by hand: reflect
    the open assembly's C in BD); both are found and the one not taken is reported."""
    from dynsolve.linkage.model import read_linkage
    from dynsolve.linkage.position import place
    from dynsolve.spec.parser import parse_file

    placed = place(read_linkage(parse_file(PROBLEMS / "four_bar_open.dyn")))
    *_, (xC, yC) = four_bar_by_hand(0.25, 0.1, 0.25, 0.15, math.radians(60), 6.0)
    B = (0.1 * math.cos(math.radians(60)), 0.1 * math.sin(math.radians(60)))
    D = (0.25, 0.0)
    ux, uy = D[0] - B[0], D[1] - B[1]
    length = math.hypot(ux, uy)
    ux, uy = ux / length, uy / length
    along = (xC - B[0]) * ux + (yC - B[1]) * uy
    mirror = (2 * (B[0] + along * ux) - xC, 2 * (B[1] + along * uy) - yC)
    (other,) = placed.others
    assert other["C"] == pytest.approx(mirror, rel=1e-9)


def test_a_joint_placed_by_loop_closure_is_listed_with_its_unit():
    # x_C = x_B + sqrt(L_BC² − y_B²) = 0.0375 + sqrt(0.04 − 0.06495²) = 0.226659 m (hand);
    # it was listed as a bare number in the givens (sheet issue 12)
    solution = solve_file(PROBLEMS / "slider_crank_forces.dyn")
    row = next(g for g in solution.givens if g.name == "x_C")
    assert row.written == "= 0.226659 m" and "\\qty" not in row.latex_value
