"""Spin + nutation + precession in 3D scenes (issue 11, part 2): ω = φ̇ K + θ̇ i' + ψ̇ k.

Expected numbers: Hibbeler 12e Example 20.2 (the gyrotop's ω and α, textbook answers),
and hand derivations written below in Hibbeler's Ω-frame form (Eq. 21-26, the frame
x'y'z' with z' the spin axis and x' the nutation axis, turning at Ω = φ̇ K + θ̇ i'), which
dynsolve does not use to solve (it writes Euler's form I_G α + ω × H_G in scene axes).
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file, solve_text

PROBLEMS = Path(__file__).parent.parent / "problems"
G = 9.81


def answers(solution) -> dict:
    return {a.name: a.value for a in solution.answers}


def checks(solution) -> dict:
    return {c.name: c for c in solution.checks}


def test_the_gyrotop_of_hibbeler_example_20_2():
    # textbook answers: ω = {3i + 8.66j + 10k} rad/s, α = {−41.3i + 5.20j + 33.0k} rad/s²
    solution = solve_file(PROBLEMS / "rigid3d" / "gyrotop_nutation.dyn")
    found = answers(solution)
    s60, c60 = math.sin(math.radians(60)), math.cos(math.radians(60))
    assert found["w_i"] == pytest.approx(3, rel=1e-12)
    assert found["w_j"] == pytest.approx(10 * s60, rel=1e-12)
    assert found["w_k"] == pytest.approx(5 + 10 * c60, rel=1e-12)
    # the hand steps of the example: dw_s/dt = 6 (s60 j + c60 k) + (3i + 5k) × (10 s60 j + 10 c60 k)
    assert found["alpha_i"] == pytest.approx(2 - 5 * 10 * s60, rel=1e-12)
    assert found["alpha_j"] == pytest.approx(6 * s60 - 3 * 10 * c60 + 15, rel=1e-12)
    assert found["alpha_k"] == pytest.approx(6 * c60 + 3 * 10 * s60 + 4, rel=1e-12)
    assert (round(found["alpha_i"], 1), round(found["alpha_j"], 2), round(found["alpha_k"], 1)) == (
        -41.3,
        5.20,
        33.0,
    )
    assert solution.passed
    shown = checks(solution)
    assert shown["ω, α, a_G by differentiating the rotations"].passed
    assert shown["Ḣ_G in the Ω frame"].passed
    assert "a_p K + a_n i' + w_p K × w_n i'" in shown["angular acceleration of top"].detail


ARM = """\
given:
  m = 4 kg
  r = 0.15 m
  d = 0.4 m
  theta = {theta} deg
  w_p = {w_p} rad/s
  a_p = {a_p} rad/s^2
  w_n = {w_n} rad/s
  a_n = {a_n} rad/s^2
  w_s = {w_s} rad/s
  a_s = {a_s} rad/s^2
scene:
  body disk: mass m, disk r, at (d*cos(theta), d*sin(theta), 0)
  rotates disk: about (0, 1, 0), through (0, 0, 0), omega w_p, alpha a_p
  nutates disk: about (0, 0, 1), through (0, 0, 0), omega w_n, alpha a_n
  spins disk: about (cos(theta), sin(theta), 0), omega w_s, alpha a_s
  bearing O: at (0, 0, 0), fixed
  gravity
find: O_x, O_y, O_z, M_Ox, M_Oy, M_Oz, alpha_x = alpha_x(disk), alpha_y = alpha_y(disk), \
alpha_z = alpha_z(disk), H_x = Hdot_x(disk), H_y = Hdot_y(disk), H_z = Hdot_z(disk)
"""


def arm_by_hand(theta, w_p, a_p, w_n, a_n, w_s, a_s, m=4.0, r=0.15, d=0.4):
    """Hibbeler Eq. 21-26 in x' = i' (the pin, scene z), z' = k (the arm), y' = z' × x':
    ω = (θ̇, −φ̇ c, ψ̇ + φ̇ s), Ω = (θ̇, −φ̇ c, φ̇ s), (ω̇)_xyz = (θ̈, −φ̈ c + φ̇ θ̇ s,
    ψ̈ + φ̈ s + φ̇ θ̇ c); α = (ω̇)_xyz + Ω × ω; a_G = Ω̇ × r + Ω × (Ω × r) worked out in scene
    axes; O = m a_G + m g j, M_O = Ḣ_G − r_O/G × O. Returns scene-axis vectors."""
    t = math.radians(theta)
    s, c = math.sin(t), math.cos(t)
    I_t, I_z = m * r**2 / 4, m * r**2 / 2
    w = (w_n, -w_p * c, w_s + w_p * s)
    Om = (w_n, -w_p * c, w_p * s)
    dw = (a_n, -a_p * c + w_p * w_n * s, a_s + a_p * s + w_p * w_n * c)
    cross = (Om[1] * w[2] - Om[2] * w[1], Om[2] * w[0] - Om[0] * w[2], Om[0] * w[1] - Om[1] * w[0])
    alpha = tuple(a + b for a, b in zip(dw, cross, strict=True))
    M = (
        I_t * dw[0] - I_t * Om[2] * w[1] + I_z * Om[1] * w[2],
        I_t * dw[1] + I_t * Om[2] * w[0] - I_z * Om[0] * w[2],
        I_z * dw[2],
    )

    def scene(v):  # x' = (0, 0, 1), y' = (s, −c, 0), z' = (c, s, 0)
        return (v[1] * s + v[2] * c, -v[1] * c + v[2] * s, v[0])

    a_G = (
        d * (-a_n * s - (w_p**2 + w_n**2) * c),
        d * (a_n * c - w_n**2 * s),
        d * (2 * w_p * w_n * s - a_p * c),
    )
    F_O = (m * a_G[0], m * a_G[1] + m * G, m * a_G[2])
    r_OG = (-d * c, -d * s, 0.0)
    r_x_O = (
        r_OG[1] * F_O[2] - r_OG[2] * F_O[1],
        r_OG[2] * F_O[0] - r_OG[0] * F_O[2],
        r_OG[0] * F_O[1] - r_OG[1] * F_O[0],
    )
    H_dot = scene(M)
    return scene(alpha), H_dot, F_O, tuple(h - x for h, x in zip(H_dot, r_x_O, strict=True))


def test_the_rotor_on_a_raised_arm_matches_the_omega_frame_equations():
    # the bundled problem's numbers (its header has the hand derivation)
    solution = solve_file(PROBLEMS / "rigid3d" / "rotor_arm_nutation.dyn")
    found = answers(solution)
    alpha, _, F_O, M_O = arm_by_hand(30, 4, 0, 2, 0, 50, 10)
    for axis, a, f, mo in zip("xyz", alpha, F_O, M_O, strict=True):
        assert found[f"alpha_{axis}"] == pytest.approx(a, rel=1e-12)
        assert found[f"O_{axis}"] == pytest.approx(f, rel=1e-12)
        assert found[f"M_O{axis}"] == pytest.approx(mo, rel=1e-12)
    assert M_O[2] == pytest.approx(10.0771, rel=1e-5)  # the header's hand figure
    assert solution.passed
    shown = checks(solution)
    for name in ("Euler's equations in the principal axes", "Ḣ_G in the Ω frame"):
        assert shown[name].passed


@settings(max_examples=4, deadline=None)
@given(
    theta=st.integers(-60, 80),
    w_p=st.integers(-6, 6),
    a_p=st.integers(-3, 3),
    w_n=st.integers(-4, 4),
    a_n=st.integers(-3, 3),
    w_s=st.integers(-80, 80),
    a_s=st.integers(-10, 10),
)
def test_every_rate_and_its_change_enter_as_the_textbook_writes(
    theta, w_p, a_p, w_n, a_n, w_s, a_s
):
    rates = dict(theta=theta, w_p=w_p, a_p=a_p, w_n=w_n, a_n=a_n, w_s=w_s, a_s=a_s)
    solution = solve_text(ARM.format(**rates), "arm.dyn")
    found = answers(solution)
    alpha, H_dot, F_O, M_O = arm_by_hand(**rates)
    for i, axis in enumerate("xyz"):
        assert found[f"alpha_{axis}"] == pytest.approx(alpha[i], rel=1e-9, abs=1e-9)
        assert found[f"H_{axis}"] == pytest.approx(H_dot[i], rel=1e-9, abs=1e-9)
        assert found[f"O_{axis}"] == pytest.approx(F_O[i], rel=1e-9, abs=1e-9)
        assert found[f"M_O{axis}"] == pytest.approx(M_O[i], rel=1e-9, abs=1e-9)
    assert not any(c.failed for c in solution.checks)


GYRO = """\
given:
  m = 0.5 kg
  r = 40 mm
  d = 60 mm
  w_s = 300 rad/s
scene:
  body rotor: mass m, disk r, at (d, 0, 0)
  rotates rotor: about (0, 1, 0), through (0, 0, 0), omega Omega
  nutates rotor: about (0, 0, 1), through (0, 0, 0), omega 0
  spins rotor: about (1, 0, 0), omega w_s
  bearing O: at (0, 0, 0), ball
  gravity
find: Omega, O_x, O_y
"""


def test_without_nutation_the_steady_precession_is_the_gyroscopes():
    # θ̇ = 0: the gyroscope of problems/rigid3d/gyroscope.dyn, m g d = Ω I_s ω_s (Hibbeler 21.5)
    found = answers(solve_text(GYRO, "gyro.dyn"))
    omega = 0.5 * G * 0.06 / (0.5 * 0.04**2 / 2 * 300)
    assert found["Omega"] == pytest.approx(omega, rel=1e-12)
    assert found["O_x"] == pytest.approx(-0.5 * omega**2 * 0.06, rel=1e-12)
    bundled = answers(solve_file(PROBLEMS / "rigid3d" / "gyroscope.dyn"))
    assert found["Omega"] == pytest.approx(bundled["Omega"], rel=1e-12)


TOP = """\
given:
  m = 0.5 kg
  r = 25 mm
  h = 60 mm
  theta = {theta} deg
  w_p = {w_p} rad/s
scene:
  body top: mass m, cone r by h, at (3*h/4*sin(theta), 3*h/4*cos(theta), 0)
  rotates top: about (0, 1, 0), through (0, 0, 0), omega w_p
  spins top: about (sin(theta), cos(theta), 0), omega w_s
  bearing O: at (0, 0, 0), ball
  gravity
find: w_s
"""


@pytest.mark.parametrize(("theta", "w_p"), [(30, 5), (60, 2), (45, -3)])
def test_a_leaning_top_in_steady_precession(theta, w_p):
    # Hibbeler Eq. 21-30 about the tip O (θ̇ = 0): m g r_G sin θ =
    # −I φ̇² sin θ cos θ + I_z φ̇ sin θ (φ̇ cos θ + ψ̇), with the solid cone's moments about
    # its apex I = (3/5) m (r²/4 + h²), I_z = (3/10) m r², and r_G = 3h/4
    m, r, h = 0.5, 0.025, 0.06
    t = math.radians(theta)
    I_O, I_z, r_G = 0.6 * m * (r**2 / 4 + h**2), 0.3 * m * r**2, 0.75 * h
    spin = (m * G * r_G + I_O * w_p**2 * math.cos(t)) / (I_z * w_p) - w_p * math.cos(t)
    solution = solve_text(TOP.format(theta=theta, w_p=w_p), "top.dyn")
    assert answers(solution)["w_s"] == pytest.approx(spin, rel=1e-9)
    assert checks(solution)["Ḣ_G in the Ω frame"].passed


def test_a_body_not_symmetric_about_its_spin_axis_has_no_omega_frame_form():
    # a plate spinning about its normal is fine for Euler's form, but its I_G changes in the
    # frame that does not spin: no (Ḣ_G)_xyz check, the rotations check stays
    text = ARM.format(theta=30, w_p=4, a_p=0, w_n=2, a_n=0, w_s=50, a_s=0).replace(
        "disk r,", "plate r by d,"
    )
    text = text.replace(
        "  spins disk:", "  axes disk: (0, 0, 1), (-sin(theta), cos(theta), 0)\n  spins disk:"
    )
    found = checks(solve_text(text, "plate.dyn"))
    assert "Ḣ_G in the Ω frame" not in found
    assert found["ω, α, a_G by differentiating the rotations"].passed


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (("bearing O: at (0, 0, 0), fixed", "bearing O: at (0, 0, 0), journal"), "not along x"),
        (
            ("  bearing O:", "  nutates disk: about (1, 0, 0), through (0, 0, 0), omega w_n\n"),
            "one nutates line",
        ),
        (("nutates disk:", "nutates disc:"), "no body 'disc'"),
        (("omega w_n,", "omega w_N,"), "'w_N' is not a given"),
    ],
)
def test_a_bad_nutation_gets_a_positioned_error(change, message):
    text = ARM.format(theta=30, w_p=4, a_p=0, w_n=2, a_n=0, w_s=50, a_s=0)
    old, new = change
    if old.startswith("  bearing"):
        new += old
    with pytest.raises(SpecError, match=message) as error:
        solve_text(text.replace(old, new), "arm.dyn")
    assert error.value.position.line > 1


def test_a_pin_on_a_nutating_body_is_refused():
    # the arm horizontal (θ = 0): the spin axis is x, yet the pin at O turns about z (the
    # nutation): which axis it carries no couple about is ambiguous, so it is refused
    text = ARM.format(theta=0, w_p=4, a_p=0, w_n=2, a_n=0, w_s=50, a_s=0)
    text = text.replace("about (cos(theta), sin(theta), 0)", "about (1, 0, 0)")
    with pytest.raises(SpecError, match="turns about two") as error:
        solve_text(text.replace("), fixed", "), pin"), "arm.dyn")
    assert error.value.position.line == 17


def test_a_nutating_body_between_two_states_is_refused(tmp_path):
    text = ARM.format(theta=30, w_p=4, a_p=0, w_n=2, a_n=0, w_s=50, a_s=0)
    text = text.replace("  gravity\n", "  gravity\n  travel disk: turns 1 about (0, 1, 0)\n")
    path = tmp_path / "arm.dyn"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(app, ["solve", str(path)])
    assert result.exit_code == 2
    assert "arm.dyn:15" in result.output and "two states" in result.output
    assert "Traceback" not in result.output


def test_a_nutating_body_is_not_simulated(tmp_path):
    text = ARM.format(theta=30, w_p=4, a_p=0, w_n=2, a_n=0, w_s=50, a_s=0)
    path = tmp_path / "arm.dyn"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(app, ["simulate", str(path)])
    assert result.exit_code == 2
    assert "nutating body" in result.output and "Traceback" not in result.output


def test_a_scene_asked_only_for_its_motion_writes_no_equations():
    # the gyroscope with Ω given (2.4525 rad/s) and only H_G, v_G asked: H_G = I_G ω with
    # ω = (w_s, Ω, 0), I_s = m r²/2 about the spin axis x, I_t = m r²/4 across it:
    # H_G = (m r² w_s/2, m r² Ω/4, 0); v_G = Ω j × d i = (0, 0, −Ω d)
    text = GYRO.replace("omega Omega", "omega W").replace(
        "  w_s = 300 rad/s\n", "  w_s = 300 rad/s\n  W = 2.4525 rad/s\n"
    )
    text = text.replace("  nutates rotor: about (0, 0, 1), through (0, 0, 0), omega 0\n", "")
    text = text.replace(
        "find: Omega, O_x, O_y", "find: H_x = H_x(rotor), H_y = H_y(rotor), v_z = v_Gz(rotor)"
    )
    solution = solve_text(text, "gyro.dyn")
    found = answers(solution)
    m, r, d = 0.5, 0.04, 0.06
    assert found["H_x"] == pytest.approx(m * r**2 * 300 / 2, rel=1e-12)
    assert found["H_y"] == pytest.approx(m * r**2 * 2.4525 / 4, rel=1e-12)
    assert found["v_z"] == pytest.approx(-2.4525 * d, rel=1e-12)
    assert solution.equations == () and solution.passed


def test_a_tilted_top_precesses_slowly_or_fast_as_the_assume_line_says():
    # newcomer report: a top tilted 60° could not be written, nor its slow precession chosen.
    # Hand (Hibbeler eq. 21-30, problems/rigid3d/top_steady_precession.dyn):
    # −0.00039375 ω_p² + 0.10125 ω_p − 0.24525 = 0 → 2.445479 or 254.6974 rad/s
    from pathlib import Path

    from dynsolve.pipeline import solve_text

    path = Path(__file__).parent.parent / "problems" / "rigid3d" / "top_steady_precession.dyn"
    text = path.read_text().split("answers:")[0]
    a, b, c = -0.00039375, 0.10125, -0.24525
    slow = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    fast = (-b - math.sqrt(b * b - 4 * a * c)) / (2 * a)
    for bound, expected in (("W_p < w_s", slow), ("W_p > w_s", fast)):
        solution = solve_text(text.replace("W_p < w_s", bound), "top.dyn")
        assert not any(check.failed for check in solution.checks)
        W_p, O_x, O_y = solution.answers
        assert W_p.value == pytest.approx(expected, rel=1e-6)
        # signed (no key words here): O_x = m a_Gx = −m ω_p² r_G sin θ, toward the axis
        assert O_x.value == pytest.approx(-0.5 * expected**2 * 0.05 * math.sin(math.pi / 3))
        assert O_y.value == pytest.approx(0.5 * 9.81)
