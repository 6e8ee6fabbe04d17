"""Axes that fit the problem (issue 12, part 3): a body on an incline has its force
equations written along (t) and normal (n) to the incline, with x–y kept for level problems.

Every expected equation and number below is derived by hand in the comments (Hibbeler's
method for a wheel on an incline, as in seed 001, 'Example Based-On Hibbeler 17-94'); none
is copied from dynsolve's output. A printed equation is read back through dynsolve's safe
spec parser (never ``eval`` or ``sympify``) and compared with the hand equation up to a
constant factor, as ``tests/test_fidelity.py`` does.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
import sympy
from test_fidelity import ascii_name, parse_printed

from dynsolve.pipeline import solve_file
from dynsolve.render.json import render_json

S = sympy.Symbol
alpha, F_C, N_C, a_Gt = S("alpha"), S("F_C"), S("N_C"), S("a_Gt")
m, r, g, theta, mu_k = S("m"), S("r"), S("g"), S("theta"), S("mu_k")

# A uniform solid sphere (I_G = 2/5 m r²) released on an incline that falls to the RIGHT at
# θ = 30°; G at the origin, the outward normal n = (sin θ, cos θ), the contact C = −r n.
# The friction F_C is positive along the normal turned 90° clockwise, (cos θ, −sin θ): DOWN
# the slope; α is counterclockwise positive (rolling down to the right is clockwise).
SPHERE = """\
problem: Solid sphere rolling down an incline
units: SI
given:
  m     = 2 kg
  r     = 0.1 m
  theta = 30 deg
  mu_s  = 0.3
  mu_k  = 0.25
  g     = 9.81 m/s^2
scene:
  body ball: mass m, sphere r, at (0, 0)
  point C on ball: (-r*sin(theta), -r*cos(theta))
  rolls ball at C: normal (sin(theta), cos(theta)), mu_s mu_s, mu_k mu_k
  gravity
find: a_G = a_G(ball) [m/s^2], alpha = alpha(ball), F = F_C [N], N = N_C [N]
"""

# Hand derivation, axes t down the slope (cos θ, −sin θ) and n out of it (sin θ, cos θ),
# moments about G, rolling without slip: a_C·t = 0 gives (a_G)_t = −α r (α ccw):
#   ΣF_t = m (a_G)_t:  F_C + m g sin θ = −m r α
#   ΣF_n = 0:          N_C − m g cos θ = 0
#   ΣM_G = I_G α:      F_C r = (2/5) m r² α    (the arm of F_C about G is r, ccw)
# Solved: α = −(5/7) g sin θ / r, so a_G = (5/7) g sin θ = 3.50357 m/s² down the slope,
# |α| = 35.0357 rad/s² clockwise, F_C = (2/5) m r α = −(2/7) m g sin θ: |F| = 2.80286 N (up
# the slope), N = m g cos θ = 16.9914 N; |F| ≤ μ_s N = 5.097 N, so it rolls.
SPHERE_EQUATIONS = {
    "ΣF_t: F_C + m g sin θ = −m r α": F_C + m * g * sympy.sin(theta) + m * r * alpha,
    "ΣF_n: N_C − m g cos θ = 0": N_C - m * g * sympy.cos(theta),
    "ΣM_G: F_C r = (2/5) m r² α": F_C * r - sympy.Rational(2, 5) * m * r**2 * alpha,
}
SPHERE_VALUES = {
    "a_G": 5 / 7 * 9.81 * 0.5,
    "alpha": 5 / 7 * 9.81 * 0.5 / 0.1,
    "F": 2 / 7 * 2 * 9.81 * 0.5,
    "N": 2 * 9.81 * math.cos(math.pi / 6),
}

# The same sphere on a steeper, slipperier incline, θ = 40°, μ_s = 0.1, μ_k = 0.08: rolling
# would need |F| = (2/7) m g sin 40° = 3.603 N > μ_s N = 0.1 (15.03 N) = 1.503 N, so it slips
# and F = μ_k N acts up the slope (F_C = −μ_k N_C). Then (a_G)_t is an unknown of its own:
#   ΣF_t = m (a_G)_t:  −μ_k N_C + m g sin θ = m a_Gt
#   ΣF_n = 0:          N_C − m g cos θ = 0
#   ΣM_G = I_G α:      −μ_k N_C r = (2/5) m r² α
# a_G = g (sin θ − μ_k cos θ) = 9.81 (0.642788 − 0.08 × 0.766044) = 5.70465 m/s²,
# |α| = μ_k N r / I_G = 5 μ_k g cos θ/(2 r) = 7.51489 rad/s² (clockwise).
SLIPPING_EQUATIONS = {
    "ΣF_t: −μ_k N_C + m g sin θ = m a_Gt": -mu_k * N_C + m * g * sympy.sin(theta) - m * a_Gt,
    "ΣF_n: N_C − m g cos θ = 0": N_C - m * g * sympy.cos(theta),
    "ΣM_G: −μ_k N_C r = (2/5) m r² α": -mu_k * N_C * r - sympy.Rational(2, 5) * m * r**2 * alpha,
}
SLIPPING_VALUES = {
    "a_G": 9.81 * (math.sin(math.radians(40)) - 0.08 * math.cos(math.radians(40))),
    "alpha": 5 * 0.08 * 9.81 * math.cos(math.radians(40)) / (2 * 0.1),
}


def _solved(tmp_path: Path, text: str) -> dict:
    path = tmp_path / "incline.dyn"
    path.write_text(text, encoding="utf-8")
    return json.loads(render_json(solve_file(path)))


def _proportional(expected: sympy.Expr, printed: sympy.Expr) -> bool:
    """The two residuals are the same equation: their ratio is a nonzero constant."""
    ratio = sympy.simplify(expected / printed)
    return bool(ratio.free_symbols == set() and ratio != 0)


def _printed(data: dict) -> list[tuple[str, sympy.Expr]]:
    return [(e["text"], parse_printed(e["text"])) for e in data["equations"]]


@pytest.mark.parametrize(
    ("spec", "equations", "values"),
    [
        (SPHERE, SPHERE_EQUATIONS, SPHERE_VALUES),
        (
            SPHERE.replace("30 deg", "40 deg")
            .replace("mu_s  = 0.3", "mu_s  = 0.1")
            .replace("mu_k  = 0.25", "mu_k  = 0.08"),
            SLIPPING_EQUATIONS,
            SLIPPING_VALUES,
        ),
    ],
    ids=["rolls", "slips"],
)
def test_a_body_on_an_incline_is_written_along_and_normal_to_it(
    tmp_path: Path, spec: str, equations: dict[str, sympy.Expr], values: dict[str, float]
) -> None:
    data = _solved(tmp_path, spec)
    printed = _printed(data)
    shown = "\n".join(text for text, _ in printed)
    missing = [
        label
        for label, expected in equations.items()
        if not any(_proportional(expected, residual) for _, residual in printed)
    ]
    assert not missing, f"not printed: {missing}\nprinted:\n{shown}"
    # no x–y components and no slope quotients: the incline's angle, as the textbook writes it
    assert "a_Gx" not in shown and "a_Gy" not in shown and "sqrt" not in shown
    notes = " ".join(e["note"] for e in data["equations"])
    assert "ΣF_t = m (a_G)_t" in notes and "ΣF_n = m (a_G)_n" in notes and "ΣM_G" in notes
    # the derivation says which axes it uses and why
    motion = data["free_body"][0]["motion"]
    assert "t down the incline and n normal to it" in motion and "contact normal at C" in motion
    answers = {a["name"]: a for a in data["answers"]}
    for name, value in values.items():
        assert answers[name]["value"] == pytest.approx(value, rel=1e-9), name
    assert answers["alpha"]["direction"] == "cw"
    slope = "30.0" if "30 deg" in spec else "40.0"
    assert answers["a_G"]["direction"] == f"{slope}° below the horizontal, to the right"
    assert data["passed"] is not False


def test_the_rolling_sphere_shows_a_g_from_alpha_and_a_second_moment_point(
    tmp_path: Path,
) -> None:
    # (a_G)_t = α r is stated as a step (a_G = r α = 3.50 m/s²); about C, the second moment
    # point: m g sin θ r = I_G α + m r² α in magnitudes, i.e. with α ccw and the weight's
    # arm about C equal to −r sin θ:  −m g r sin θ = (2/5 + 1) m r² α = (7/5) m r² α
    data = _solved(tmp_path, SPHERE)
    steps = [(res["name"], res["formula"]) for s in data["steps"] for res in s["results"]]
    assert ("a_G", "r*α") in steps or ("a_G", "-r*α") in steps, steps
    second = data["second_moments"]
    assert len(second) == 1 and "ΣM_C" in second[0]["note"]
    expected = -m * g * r * sympy.sin(theta) - sympy.Rational(7, 5) * m * r**2 * alpha
    assert _proportional(expected, parse_printed(second[0]["text"])), second[0]["text"]


def test_a_level_rolling_sphere_keeps_x_y(tmp_path: Path) -> None:
    # level ground (normal up) and a horizontal push: the textbook keeps x–y, as before
    level = (
        SPHERE.replace("(-r*sin(theta), -r*cos(theta))", "(0, -r)")
        .replace("normal (sin(theta), cos(theta))", "normal up")
        .replace("  gravity\n", "  force P on ball at G: right\n  gravity\n")
        .replace("  g     = 9.81 m/s^2\n", "  g     = 9.81 m/s^2\n  P     = 5 N\n")
        .replace("  theta = 30 deg\n", "")
    )
    data = _solved(tmp_path, level)
    notes = " ".join(e["note"] for e in data["equations"])
    assert "ΣF_x = m (a_G)_x" in notes and "ΣF_y = m (a_G)_y" in notes and "ΣF_t" not in notes
    assert "incline" not in data["free_body"][0]["motion"]
    # ΣF_x: P + F_C = m a_G; ΣM_C: −P r = (7/5) m r² α (α ccw): a_G = −r α = 5P/(7m)
    answers = {a["name"]: a for a in data["answers"]}
    assert answers["a_G"]["value"] == pytest.approx(5 * 5 / (7 * 2), rel=1e-9)


def test_ascii_names_read_back() -> None:
    # the printed θ and α are the spec's theta and alpha (the residuals above rely on it)
    assert ascii_name("θ") == "theta" and ascii_name("α") == "alpha"


def test_impulse_and_momentum_on_an_incline_keeps_its_velocity_unknowns(tmp_path: Path) -> None:
    # a block sliding down a rough 30° incline at v0 = 1 m/s, for Δt = 2 s (μ_k = 0.2):
    # m v0 + (m g sin θ − μ_k m g cos θ) Δt = m v2, so v2 = 1 + (4.905 − 0.2 × 8.49571)(2)
    # = 7.41172 m/s. Over an interval the equations stay in x–y velocity unknowns.
    spec = """\
problem: Block slides down a rough incline for 2 s
units: SI
given:
  m = 10 kg
  theta = 30 deg
  mu_k = 0.2
  dt = 2 s
  v0 = 1 m/s
  g = 9.81 m/s^2
scene:
  body block: particle, mass m, at (0, 0)
  contact block at G: normal (-sin(theta), cos(theta)), mu_k mu_k
  velocity block: v0, (-cos(theta), -sin(theta))
  gravity
  travel block: for dt
find: v = speed(block) [m/s]
"""
    data = _solved(tmp_path, spec)
    shown = " ".join(e["text"] for e in data["equations"])
    assert "nan" not in shown and "a_Gt" not in shown
    theta_ = math.radians(30)
    expected = 1 + (9.81 * math.sin(theta_) - 0.2 * 9.81 * math.cos(theta_)) * 2
    answer = next(a for a in data["answers"] if a["name"] == "v")
    assert answer["value"] == pytest.approx(expected, rel=1e-9)
