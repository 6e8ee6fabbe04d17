"""Simulation benchmark: dynsolve's integrator against a hand-written lambdify + solve_ivp script.

For each system (a compound pendulum released from 60°; the seed's 40-lb disk rolling
against a wound spring under a couple, from problems/seed/rwe_seed_disk40lb.dyn; a double
pendulum of two rods, an open chain of bars in two coordinates), the
equation of motion is built once by dynsolve from the scene and once by hand (the
Lagrangian written out, lambdified with sympy), and both are integrated over 10 s with
the same solve_ivp method and tolerances (atol = rtol/100). Each reports the error of q at
10 s against a reference (the hand script at DOP853, rtol 1e-13), the wall time of the
integration (best of --repeat runs, alternating; the energy drift computed in both) and
the energy drift max |E(t) − E(0)| / scale. The ratio is dynsolve / hand at equal method
and tolerance. Target: ratio ≤ 1.0 and drift ≤ 1e-9 at rtol 1e-12 (DOP853).

    python bench/simulate.py [--repeat 9] [--methods RK45,DOP853,Radau,LSODA] [--no-write]

writes its table to the section 'Simulation' of docs/benchmarks.md (bench/report.py).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy
from scipy.integrate import solve_ivp

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
HEADING = "## Simulation: `bench/simulate.py`"
ABOUT = """dynsolve's integrator (`dynsolve/simulate/`: the equation of motion built from the scene,
lambdified, integrated with `solve_ivp`) against a hand-written script of the same system in
the same run: its Lagrangian written out by hand, lambdified with sympy, integrated by
`solve_ivp` with the same method, tolerances (atol = rtol/100) and coordinate, its energy
drift computed the same way. Three systems over 10 s: a compound pendulum (2-kg, 1-m bar
pinned at its end) released from 60°, the seed's 40-lb disk rolling against a wound
spring under a 15 ft·lb couple (`problems/seed/rwe_seed_disk40lb.dyn`, FPS), and a double
pendulum of two uniform rods (2 kg, 1 m; an open chain of bars, two coordinates) released
from rest with the upper rod 30° below the horizontal and the lower one horizontal. Error:
|q(10 s) − q_ref| / |q_ref| (the first coordinate), the reference being the hand script at
DOP853, rtol 1e-13. Time: best of
the runs alternating dynsolve and the hand script, integration and drift only. Drift:
max |Δ(T + V)| / max(T, range of V). Target: ratio ≤ 1.0, drift ≤ 1e-9 at rtol 1e-12."""

from report import write_section  # noqa: E402

from dynsolve.simulate.integrator import integrate  # noqa: E402
from dynsolve.simulate.run import motion_of  # noqa: E402
from dynsolve.spec.parser import parse_file, parse_spec  # noqa: E402

T_END = 10.0
THETA_0 = math.radians(60)
PENDULUM = """\
given:
  m = 2 kg
  L = 1 m
  theta_0 = 60 deg
scene:
  point O: (0, 0)
  body bar: mass m, rod L, at (L/2*sin(theta_0), -L/2*cos(theta_0))
  pin bar at O
  gravity
"""


@dataclass
class Hand:
    """A hand-written system in dynsolve's coordinate q (the turn or travel from the scene
    as drawn): rhs(t, y), (T, V)(q, q') vectorised, and the start."""

    rhs: object
    energy: object
    y0: list[float]


def hand_pendulum() -> Hand:
    # Hibbeler 17.4 / 22.1: I_O θ'' = −m g (L/2) sin θ, θ from the downward vertical, here
    # θ = θ₀ + q with q the turn from the drawn position (the coordinate dynsolve uses, so
    # that both scale the tolerances alike); I_O = m L²/3; E = ½ I_O q'² − m g (L/2) cos θ
    q, w = sympy.symbols("q w")
    m, L, g = 2.0, 1.0, 9.81
    I_O = m * L**2 / 3
    theta = THETA_0 + q
    accel = sympy.lambdify([q], -m * g * (L / 2) * sympy.sin(theta) / I_O, "math")
    energy = sympy.lambdify([q, w], (I_O * w**2 / 2, -m * g * (L / 2) * sympy.cos(theta)))
    return Hand(lambda t, y: [y[1], accel(y[0])], energy, [0.0, 0.0])


def hand_disk() -> Hand:
    # the seed's disk (Ch. 18): W = 40 lb, r = 0.8 ft, k_G = 0.6 ft, k = 10 lb/ft,
    # M = 15 ft·lb ccw, rolling: s to the left (ft), θ = s/r ccw; the spring's cord leaves
    # the top of the rim, which moves 2 s, so the stretch is 2 s. T = ½ m (1 + k_G²/r²) s'²,
    # V = ½ k (2 s)² − M s/r, so m_eff s'' = M/r − 4 k s
    s, v = sympy.symbols("s v")
    m = 40 / 32.2
    r, k_G, k, M = 0.8, 0.6, 10.0, 15.0
    m_eff = m * (1 + k_G**2 / r**2)
    accel = sympy.lambdify([s], (M / r - 4 * k * s) / m_eff, "math")
    energy = sympy.lambdify([s, v], (m_eff * v**2 / 2, 2 * k * s**2 - M * s / r))
    return Hand(lambda t, y: [y[1], accel(y[0])], energy, [0.0, 0.0])


DOUBLE = """\
given:
  m = 2 kg
  L = 1 m
  theta_1 = -30 deg
  theta_2 = 0 deg
scene:
  point O: (0, 0)
  bar OA: O to A, length L, angle theta_1, mass m
  bar AB: A to B, length L, angle theta_2, mass m
  gravity
"""
DOUBLE_START = (math.radians(-30), 0.0)


def hand_double() -> Hand:
    # two uniform rods (m = 2 kg, L = 1 m) pinned at O and end to end at A, θ_i from +x
    # ccw, θ_i = θ_i0 + q_i: T = m L² [(2/3) ω₁² + (1/6) ω₂² + ½ ω₁ ω₂ cos(θ₁ − θ₂)],
    # V = m g L [(3/2) sin θ₁ + ½ sin θ₂]; Lagrange: M q'' = f with
    # M = m L² [4/3, ½ cos Δ; ½ cos Δ, 1/3], f = m L² [−½ sin Δ ω₂², ½ sin Δ ω₁²]
    #     − m g L [(3/2) cos θ₁, ½ cos θ₂]; q'' by LU (sympy), lambdified
    q1, q2, w1, w2 = sympy.symbols("q1 q2 w1 w2")
    m, L, g = 2.0, 1.0, 9.81
    t1, t2 = DOUBLE_START[0] + q1, DOUBLE_START[1] + q2
    d = t1 - t2
    M = m * L**2 * sympy.Matrix([[4 / 3, sympy.cos(d) / 2], [sympy.cos(d) / 2, 1 / 3]])
    f = m * L**2 * sympy.Matrix([-sympy.sin(d) * w2**2 / 2, sympy.sin(d) * w1**2 / 2])
    f -= m * g * L * sympy.Matrix([1.5 * sympy.cos(t1), 0.5 * sympy.cos(t2)])
    accel = sympy.lambdify([q1, q2, w1, w2], [w1, w2, *M.LUsolve(f)], "math", cse=True)
    T = m * L**2 * (2 * w1**2 / 3 + w2**2 / 6 + w1 * w2 * sympy.cos(d) / 2)
    V = m * g * L * (1.5 * sympy.sin(t1) + 0.5 * sympy.sin(t2))
    energy = sympy.lambdify([q1, q2, w1, w2], (T, V))
    return Hand(lambda t, y: accel(*y), energy, [0.0, 0.0, 0.0, 0.0])


SHAFT = """\
given:
  m = 2 kg
  L = 0.8 m
  Omega = 6 rad/s
  theta = 30 deg
  w = 0 rad/s
scene:
  body bar: mass m, rod L, at (L/2*sin(theta), -L/2*cos(theta), 0)
  axis bar: (sin(theta), -cos(theta), 0)
  rotates bar: about (0, 1, 0), through (0, 0, 0), omega Omega
  spins bar: about (0, 0, 1), through (0, 0, 0), omega w, alpha theta_ddot
  bearing B: at (0, 0, 0), pin
  gravity
"""
SHAFT_START = math.radians(30)


def hand_shaft() -> Hand:
    # the seed's bar on a rotating shaft (002, problems/seed/3d_seed_bar_shaft.dyn): the
    # b3 component of Ḣ_B = (Ḣ_B)_b + ω × H_B with I_B = m L²/3 across the bar,
    # I_B θ'' − I_B Ω² sin θ cos θ = −m g (L/2) sin θ, θ from the downward vertical,
    # θ = θ₀ + q. Ω is held constant, so the invariant is the Jacobi integral
    # ½ I_B θ'² − ½ I_B Ω² sin²θ − m g (L/2) cos θ (split as T-part and V-part)
    q, w = sympy.symbols("q w")
    m, L, g, Omega = 2.0, 0.8, 9.81, 6.0
    I_B = m * L**2 / 3
    theta = SHAFT_START + q
    accel = sympy.lambdify(
        [q], Omega**2 * sympy.sin(theta) * sympy.cos(theta) - 1.5 * g / L * sympy.sin(theta)
    )
    energy = sympy.lambdify(
        [q, w],
        (
            I_B * w**2 / 2 - I_B * Omega**2 * sympy.sin(theta) ** 2 / 2,
            -m * g * (L / 2) * sympy.cos(theta),
        ),
    )
    return Hand(lambda t, y: [y[1], accel(y[0])], energy, [0.0, 0.0])


def run_hand(hand: Hand, method: str, rtol: float) -> tuple[float, float, int]:
    """q at T_END, the energy drift and the number of right-hand side evaluations."""
    sol = solve_ivp(hand.rhs, (0.0, T_END), hand.y0, method=method, rtol=rtol, atol=rtol / 100)
    T, V = hand.energy(*sol.y)
    T, V = np.broadcast_to(T, sol.t.shape), np.broadcast_to(V, sol.t.shape)
    E = T + V
    scale = max(float(np.max(T)), float(np.ptp(V)), 1e-300)  # as dynsolve's drift
    drift = float(np.max(np.abs(E - E[0]))) / scale
    return float(sol.y[0][-1]), drift, int(sol.nfev)


def paired(ours, hand, repeat: int) -> tuple[float, object, float, object]:
    """The best wall time of each over ``repeat`` runs, alternating (so a busy moment of
    the machine falls on both), with their last results."""
    times_ours, times_hand = [], []
    result_ours = result_hand = None
    for index in range(repeat):
        if index == 3 and min(times_ours) > 1.0:  # a slow case: three pairs are enough
            break
        start = time.perf_counter()
        result_ours = ours()
        times_ours.append(time.perf_counter() - start)
        start = time.perf_counter()
        result_hand = hand()
        times_hand.append(time.perf_counter() - start)
    return min(times_ours), result_ours, min(times_hand), result_hand


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=9)
    parser.add_argument("--methods", default="RK45,DOP853,Radau,LSODA")
    parser.add_argument("--rtols", default="1e-6,1e-8,1e-10,1e-12")
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    parser.add_argument(
        "--systems", default="", help="only the systems whose names hold these words (a,b)"
    )
    args = parser.parse_args()
    builds: list[str] = []
    systems = {
        "compound pendulum, 60°": (parse_spec(PENDULUM, "pendulum.dyn"), hand_pendulum()),
        "rolling disk, wound spring (seed)": (
            parse_file(ROOT / "problems/seed/rwe_seed_disk40lb.dyn"),
            hand_disk(),
        ),
    }
    lines = [ABOUT, ""]
    show(lines, "| system | method | rtol | error dynsolve | error hand | evaluations dynsolve / "
         "hand | time dynsolve | time hand | ratio | drift dynsolve | drift hand |")  # fmt: skip
    show(lines, "|---|---|---|---|---|---|---|---|---|---|---|")
    systems["double pendulum, two rods (chain)"] = (
        parse_spec(DOUBLE, "double.dyn"),
        hand_double(),
    )
    systems["bar on a rotating shaft (seed, 3D)"] = (parse_spec(SHAFT, "shaft.dyn"), hand_shaft())
    if args.systems:
        wanted = [w.strip() for w in args.systems.split(",")]
        systems = {k: v for k, v in systems.items() if any(w in k for w in wanted)}
    for name, (spec, hand) in systems.items():
        start = time.perf_counter()
        integrator = _ours(spec)
        build = time.perf_counter() - start
        reference, _, _ = run_hand(hand, "DOP853", 1e-13)
        size = max(abs(reference), 1e-300)
        for method in args.methods.split(","):
            for rtol in (float(r) for r in args.rtols.split(",")):
                ours_time, run, hand_time, (q_hand, drift_hand, nfev) = paired(
                    lambda m=method, r=rtol, f=integrator: f(m, r),
                    lambda m=method, r=rtol, h=hand: run_hand(h, m, r),
                    args.repeat,
                )
                error_ours = abs(float(np.ravel(run.q[-1])[0]) - reference) / size
                error_hand = abs(q_hand - reference) / size
                show(
                    lines,
                    f"| {name} | {method} | {rtol:.0e} | {error_ours:.1e} | {error_hand:.1e} "
                    f"| {run.evaluations} / {nfev} "
                    f"| {ours_time * 1e3:.1f} ms | {hand_time * 1e3:.1f} ms "
                    f"| {ours_time / hand_time:.2f} | {run.drift:.1e} | {drift_hand:.1e} |",
                )
        builds.append(f"{name} {build:.2f} s")
    lines += [
        "",
        "Building the equation of motion from the scene, once: " + "; ".join(builds) + ".",
    ]
    if not args.no_write:
        command = " ".join(["python bench/simulate.py", *sys.argv[1:]])
        write_section(HEADING, "\n".join(lines), command)


def _ours(spec: object) -> object:
    """dynsolve's equation of motion of the spec, built once; a function (method, rtol)
    that integrates it over T_END as ``dynsolve simulate`` does (every step kept)."""
    from dynsolve.linkage.model import is_linkage
    from dynsolve.rigid3d.model import is_3d
    from dynsolve.simulate.chain import chain_of

    if is_3d(spec):
        from dynsolve.simulate.chain_run import integrate_chain
        from dynsolve.simulate.spin3d import spin_of

        spin = spin_of(spec)
        return lambda m, r: integrate_chain(spin, T_END, m, r, r / 100, None)
    if is_linkage(spec):
        from dynsolve.simulate.chain_run import integrate_chain

        chain = chain_of(spec)
        chain.right_hand_side()  # lambdified once, as the hand script is
        return lambda m, r: integrate_chain(chain, T_END, m, r, r / 100, None)
    from dynsolve.model.scene import build_scene
    from dynsolve.modes.equation_mode import givens_of

    givens = givens_of(spec)
    symbols = {g.name: g.symbol for g in givens}
    values = {g.symbol: g.value for g in givens if g.value is not None}
    scene = build_scene(spec, symbols, {g.name: g.dim for g in givens}, values)
    motion = motion_of(scene, symbols, values)
    return lambda m, r: integrate(motion, 0.0, 0.0, T_END, (), m, r, r / 100)


def show(lines: list[str], line: str) -> None:
    """Print a table line as it is measured, and keep it for the document."""
    print(line, flush=True)
    lines.append(line)


if __name__ == "__main__":
    main()
