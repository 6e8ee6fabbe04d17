"""One-line laws benchmark: a generated set of rectilinear laws × scales × finds (issue 25, 11).

Every common form of one-line kinematics: a(t), a(v), a(x), Newton's law with the mass on
either side (``m*a = -k*x``, ``a = -k*x/m``), x(t) and v(t), each with finds of values at
a time or a position, events (``t_at``, ``x_at``) and extremes (``max``, ``min``). Each law
is generated at every scale 10^k (k = −9, −6, … 9): lengths and masses times 10^k, so a
time is the same at every scale and a length, speed or force scales by its dimension.
Each spec is solved in-process in a worker (:func:`dynsolve.budget.run_each`, 60 s of
wall time per solve so a cliff cannot stall the run), sympy's cache cleared before each
solve; the figure is the CPU time (``process_time``) of parse + build + solve + checks.

Every answer is compared with an independent reference: a closed form derived by hand
(the comment by each law), or scipy's quadrature where there is none (the Duffing
spring's time to x = 0), scaled by its dimension. The baseline, measured in the same run,
is what a hand-written numeric script would do for the same law and scale: scipy's
``solve_ivp`` (DOP853, rtol 1e-10) of x' = v, v' = a from t₀ to the latest time asked.

    python bench/oneline_laws.py [--ks -9,-6,-3,0,3,6,9] [--modes exact,numeric] [--no-write]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from dynsolve.startup import import_solver  # noqa: E402

import_solver()  # as the CLI's worker does, before anything else of dynsolve

import numpy as np  # noqa: E402
from report import write_section  # noqa: E402
from scipy.integrate import quad, solve_ivp  # noqa: E402

from dynsolve.budget import Budget, OverBudget, run_each  # noqa: E402

HEADING = "## One-line laws: `bench/oneline_laws.py`"
TARGET = 2.0  # CPU seconds per law, at any scale (issue 25, item 11)
TOLERANCE = 1e-6  # relative, against the reference

Given = tuple[str, float, str, int]  # name, value at scale 1, unit, power of the scale
Find = tuple[str, str, float, int]  # name, find text, reference at scale 1, power of the scale
Rate = Callable[[float, float, float], float]  # a(t, x, v) at scale 1


@dataclass(frozen=True)
class Law:
    """One relation with its givens, finds and their references (at scale 1)."""

    name: str
    relation: str
    givens: tuple[Given, ...]
    finds: tuple[Find, ...]
    rate: Rate  # a(t, x, v) at scale 1, for the baseline (lengths scale with it)
    start: tuple[float, float]  # (x₀, v₀) at scale 1
    until: float  # the latest time asked, s


E = math.exp(1.0)
W = 2.0  # ω of the springs: k/m = 4 1/s²
# a = -C/x² from rest at x₀ = 2 m, C = 4 m³/s²: t to x₁ = 1 m = √(x₀³/2C)(√(ξ(1−ξ)) + acos √ξ)
INFALL = math.sqrt(8 / 8) * (math.sqrt(0.25) + math.acos(math.sqrt(0.5)))
# m a = −k x − c x³ (m = 2, k = 8, c = 0.5) from rest at x₀ = 0.1: v² = (x₀² − x²)(k/m +
# c (x₀² + x²)/2m); with x = x₀ sin θ, t to x = 0 = ∫₀^{π/2} dθ/√(k/m + c x₀²(1 + sin² θ)/2m)
DUFFING_T = quad(
    lambda th: 1 / math.sqrt(4 + 0.125 * 0.01 * (1 + math.sin(th) ** 2)), 0, math.pi / 2
)[0]
DUFFING_V = math.sqrt(4 * 0.01 + 0.125 * 1e-4)  # √(k x₀²/m + c x₀⁴/2m), at x = 0
SPRING_FINDS: tuple[Find, ...] = (
    # x = 0.1 cos 2t: x = 0 at t = π/4; v² = ω²(x₀² − x²), moving in (v < 0)
    ("t_z", "t_at(x, 0)", math.pi / 4, 0),
    ("v_1", "v(x_1)", -W * math.sqrt(0.01 - 0.0025), 1),
    ("x_lo", "min(x)", -0.1, 1),
    ("v_hi", "max(v)", W * 0.1, 1),
    ("x_2", "x(t_2)", 0.1 * math.cos(2 * 0.3), 1),
)
SPRING_START = (0.1, 0.0)
SPRING_GIVENS: tuple[Given, ...] = (
    ("x_0", 0.1, "m", 1),
    ("v_0", 0.0, "m/s", 1),
    ("x_1", 0.05, "m", 1),
    ("t_2", 0.3, "s", 0),
)
LAWS = (
    # a = c − b t, v₀ = 1: v = 1 + 2t − t²/4, x = t + t² − t³/12; v = 0 at t = 4 + √20
    Law(
        "a(t)",
        "a = c - b*t",
        (("c", 2.0, "m/s^2", 1), ("b", 0.5, "m/s^3", 1), ("v_0", 1.0, "m/s", 1),
         ("t_1", 2.0, "s", 0)),
        (("v_1", "v(t_1)", 4.0, 1), ("x_1", "x(t_1)", 2 + 4 - 8 / 12, 1),
         ("t_s", "t_at(v, 0)", 4 + math.sqrt(20), 0),
         ("x_hi", "max(x)", (4 + math.sqrt(20)) + (4 + math.sqrt(20)) ** 2
          - (4 + math.sqrt(20)) ** 3 / 12, 1)),
        lambda t, x, v: 2 - 0.5 * t, (0.0, 1.0), 4 + math.sqrt(20),
    ),
    # m a = F − c t, a = 5 − t from rest: v = 5t − t²/2, x = 5t²/2 − t³/6; v = 0 at t = 10
    Law(
        "m*a = F(t)",
        "m*a = F - c*t",
        (("m", 2.0, "kg", 1), ("F", 10.0, "N", 2), ("c", 2.0, "N/s", 2), ("v_0", 0.0, "m/s", 1),
         ("t_1", 2.0, "s", 0)),
        (("v_1", "v(t_1)", 8.0, 1), ("x_1", "x(t_1)", 10 - 8 / 6, 1),
         ("t_s", "t_at(v, 0)", 10.0, 0)),
        lambda t, x, v: 5 - t, (0.0, 0.0), 10.0,
    ),
    # a = (F/m) sin ωt from rest, F/m = 5, ω = 2: v = 5(1 − cos 2t)/2, x = 5(t/2 − sin 2t/4)
    Law(
        "a = F(t)/m",
        "a = F/m*sin(w*t)",
        (("m", 2.0, "kg", 1), ("F", 10.0, "N", 2), ("w", 2.0, "1/s", 0), ("v_0", 0.0, "m/s", 1),
         ("t_1", 1.0, "s", 0)),
        (("v_1", "v(t_1)", 2.5 * (1 - math.cos(2)), 1),
         ("x_1", "x(t_1)", 5 * (0.5 - math.sin(2) / 4), 1)),
        lambda t, x, v: 5 * math.sin(2 * t), (0.0, 0.0), 1.0,
    ),
    # a = −k v, k = 0.5, v₀ = 3: v = 3e^(−t/2), x = 6(1 − e^(−t/2)); v = 1 at t = 2 ln 3, x = 4
    Law(
        "a(v)",
        "a = -k*v",
        (("k", 0.5, "1/s", 0), ("v_0", 3.0, "m/s", 1), ("t_1", 2.0, "s", 0),
         ("v_1", 1.0, "m/s", 1)),
        (("v_2", "v(t_1)", 3 / E, 1), ("x_2", "x(t_1)", 6 * (1 - 1 / E), 1),
         ("t_3", "t_at(v, v_1)", 2 * math.log(3), 0), ("x_3", "x_at(v, v_1)", 4.0, 1)),
        lambda t, x, v: -0.5 * v, (0.0, 3.0), 2 * math.log(3),
    ),
    # m a = −c v with c/m = 0.5: as a = −k v
    Law(
        "m*a = F(v)",
        "m*a = -c*v",
        (("m", 2.0, "kg", 1), ("c", 1.0, "kg/s", 1), ("v_0", 3.0, "m/s", 1),
         ("t_1", 2.0, "s", 0), ("v_1", 1.0, "m/s", 1)),
        (("v_2", "v(t_1)", 3 / E, 1), ("x_2", "x(t_1)", 6 * (1 - 1 / E), 1),
         ("t_3", "t_at(v, v_1)", 2 * math.log(3), 0)),
        lambda t, x, v: -0.5 * v, (0.0, 3.0), 2 * math.log(3),
    ),
    # a = −c v/m with c/m = 0.5: as a = −k v
    Law(
        "a = F(v)/m",
        "a = -c*v/m",
        (("m", 2.0, "kg", 1), ("c", 1.0, "kg/s", 1), ("v_0", 3.0, "m/s", 1),
         ("t_1", 2.0, "s", 0), ("v_1", 1.0, "m/s", 1)),
        (("v_2", "v(t_1)", 3 / E, 1), ("x_2", "x(t_1)", 6 * (1 - 1 / E), 1),
         ("x_3", "x_at(v, v_1)", 4.0, 1)),
        lambda t, x, v: -0.5 * v, (0.0, 3.0), 2 * math.log(3),
    ),
    # a = −c v², c = 0.2 1/m, v₀ = 10: v = 10/(1 + 2t), x = 5 ln(1 + 2t); v = 5 at t = 0.5
    Law(
        "a(v) quadratic",
        "a = -c*v^2",
        (("c", 0.2, "1/m", -1), ("v_0", 10.0, "m/s", 1), ("t_1", 2.0, "s", 0),
         ("v_1", 5.0, "m/s", 1)),
        (("v_2", "v(t_1)", 2.0, 1), ("x_2", "x(t_1)", 5 * math.log(5), 1),
         ("t_3", "t_at(v, v_1)", 0.5, 0)),
        lambda t, x, v: -0.2 * v * v, (0.0, 10.0), 2.0,
    ),
    Law("a(x)", "a = -k*x", (("k", 4.0, "1/s^2", 0), *SPRING_GIVENS), SPRING_FINDS,
        lambda t, x, v: -4 * x, SPRING_START, math.pi / 2),
    Law("m*a = F(x)", "m*a = -k*x",
        (("m", 2.0, "kg", 1), ("k", 8.0, "N/m", 1), *SPRING_GIVENS), SPRING_FINDS,
        lambda t, x, v: -4 * x, SPRING_START, math.pi / 2),
    Law("a = F(x)/m", "a = -k*x/m",
        (("m", 2.0, "kg", 1), ("k", 8.0, "N/m", 1), *SPRING_GIVENS), SPRING_FINDS,
        lambda t, x, v: -4 * x, SPRING_START, math.pi / 2),
    # a = −C/x² from rest at x₀ = 2: v² = 2C(1/x − 1/x₀) = 4 at x = 1, moving in
    Law(
        "a(x) inverse square",
        "a = -C/x^2",
        (("C", 4.0, "m^3/s^2", 3), ("x_0", 2.0, "m", 1), ("v_0", 0.0, "m/s", 1),
         ("x_1", 1.0, "m", 1)),
        (("v_1", "v(x_1)", -2.0, 1), ("t_1", "t_at(x, x_1)", INFALL, 0)),
        lambda t, x, v: -4 / x**2, (2.0, 0.0), INFALL,
    ),
    Law(
        "m*a = F(x) Duffing",
        "m*a = -k*x - c*x^3",
        (("m", 2.0, "kg", 1), ("k", 8.0, "N/m", 1), ("c", 0.5, "N/m^3", -1),
         ("x_0", 0.1, "m", 1), ("v_0", 0.0, "m/s", 1)),
        (("t_z", "t_at(x, 0)", DUFFING_T, 0), ("x_lo", "min(x)", -0.1, 1),
         ("v_hi", "max(v)", DUFFING_V, 1)),
        lambda t, x, v: -4 * x - 0.25 * x**3, (0.1, 0.0), DUFFING_T,
    ),
    # x = b t³ − c t², b = 1, c = 6: v = 3t² − 12t, a = 6t − 12; v = 0 at t = 4, x = −32
    Law(
        "x(t)",
        "x = b*t^3 - c*t^2",
        (("b", 1.0, "m/s^3", 1), ("c", 6.0, "m/s^2", 1), ("t_1", 1.0, "s", 0)),
        (("v_1", "v(t_1)", -9.0, 1), ("a_1", "a(t_1)", -6.0, 1),
         ("t_s", "t_at(v, 0)", 4.0, 0), ("x_lo", "min(x)", -32.0, 1)),
        lambda t, x, v: 6 * t - 12, (0.0, 0.0), 4.0,
    ),
    # v = v_m (1 − e^(−t/τ)), v_m = 20, τ = 2: x = 20(t − 2(1 − e^(−t/2))), a = 10 e^(−t/2)
    Law(
        "v(t)",
        "v = v_m*(1 - exp(-t/tau))",
        (("v_m", 20.0, "m/s", 1), ("tau", 2.0, "s", 0), ("t_1", 2.0, "s", 0),
         ("v_1", 10.0, "m/s", 1)),
        (("x_1", "x(t_1)", 40 / E, 1), ("a_1", "a(t_1)", 10 / E, 1),
         ("t_2", "t_at(v, v_1)", 2 * math.log(2), 0)),
        lambda t, x, v: 10 * math.exp(-t / 2), (0.0, 0.0), 2.0,
    ),
)  # fmt: skip


def spec_text(law: Law, k: int) -> str:
    """The law's spec at scale 10^k: each given times 10^(k × its power)."""
    lines = [f"problem: {law.name} at scale 1e{k}", "given:"]
    lines += [f"  {n} = {v * 10.0 ** (k * p):.12g} {unit}" for n, v, unit, p in law.givens]
    lines += ["kinematics:", f"  {law.relation}"]
    lines.append("find: " + ", ".join(f"{name} = {text}" for name, text, _, _ in law.finds))
    return "\n".join(lines) + "\n"


def solve_timed(text: str, mode: str) -> tuple[float, dict[str, float | None], list[str]]:
    """(CPU s, the answers' values by name, the failed checks) of one in-process solve."""
    import sympy

    from dynsolve.pipeline import solve_text
    from dynsolve.system import SolveOptions

    sympy.core.cache.clear_cache()
    start = time.process_time()
    solution = solve_text(text, "law.dyn", SolveOptions(mode=mode))  # type: ignore[arg-type]
    seconds = time.process_time() - start
    answers = {a.name: a.value for a in solution.answers}
    return seconds, answers, [c.name for c in solution.checks if not c.passed]


def baseline_seconds(law: Law, k: int, repeat: int = 5) -> float:
    """scipy's solve_ivp of the law at scale 10^k to its latest time: mean CPU s."""
    scale = 10.0**k
    x0, v0 = law.start

    def slopes(t: float, state: np.ndarray) -> list[float]:
        return [state[1], scale * law.rate(t, state[0] / scale, state[1] / scale)]

    start = time.process_time()
    for _ in range(repeat):
        solve_ivp(slopes, (0.0, law.until), [x0 * scale, v0 * scale], method="DOP853", rtol=1e-10)
    return (time.process_time() - start) / repeat


def wrong_answers(law: Law, k: int, answers: dict[str, float | None]) -> list[str]:
    """The finds whose value is missing or off the reference by more than TOLERANCE."""
    wrong = []
    for name, _, reference, power in law.finds:
        expected = reference * 10.0 ** (k * power)
        got = answers.get(name)
        floor = 1e-12 * 10.0 ** (k * power)
        if got is None or abs(got - expected) > TOLERANCE * max(abs(expected), floor):
            wrong.append(f"{name} = {got!r} (reference {expected:.9g})")
    return wrong


def shown(seconds: float) -> str:
    """A CPU time as the table shows it; a solve stopped by the budget as such."""
    return "over the 60 s budget" if math.isinf(seconds) else f"{seconds:.2f} s"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ks", default="-9,-6,-3,0,3,6,9", help="scales 10^k, comma-separated")
    parser.add_argument("--modes", default="exact,numeric", help="modes, comma-separated")
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()
    ks = [int(k) for k in args.ks.split(",")]
    modes = args.modes.split(",")
    cases = [(law, k, mode) for law in LAWS for k in ks for mode in modes]
    jobs = [(spec_text(LAWS[0], 0), modes[0])] + [(spec_text(law, k), m) for law, k, m in cases]
    outcomes = run_each(solve_timed, jobs, Budget(seconds=60))
    next(outcomes)  # warm-up: parser, unit cache, lambdify
    rows, failures, worst = [], [], (0.0, "")
    for (law, k, mode), outcome in zip(cases, outcomes, strict=True):
        label = f"{law.name} (`{law.relation}`), 1e{k}, {mode}"
        if isinstance(outcome, BaseException):
            failures.append(f"{label}: {str(outcome).splitlines()[-1][:160]}")
            if isinstance(outcome, OverBudget):
                worst = max(worst, (math.inf, label))
            print("FAILED", failures[-1], flush=True)
            continue
        seconds, answers, failed_checks = outcome
        wrong = wrong_answers(law, k, answers)
        if wrong or failed_checks:
            failures.append(
                f"{label}: " + "; ".join(wrong + [f"check {c} failed" for c in failed_checks])
            )
        ratio = seconds / baseline_seconds(law, k)
        rows.append((law, k, mode, seconds, ratio))
        worst = max(worst, (seconds, label))
        print(f"{label}: {seconds:.2f} s CPU, {ratio:.0f}× scipy, {len(wrong)} wrong", flush=True)
    total = len(cases)
    over = sum(1 for *_, s, _ in rows if s > TARGET) + sum("time budget" in f for f in failures)
    lines = [
        f"{len(LAWS)} laws (every common form) × {len(ks)} scales (10^k, k = {args.ks}) × "
        f"{len(modes)} modes ({', '.join(modes)}): {total} solves, "
        f"{sum(len(law.finds) for law in LAWS) * len(ks) * len(modes)} answers, each compared "
        f"with a reference derived by hand (or scipy's quadrature) to {TOLERANCE:g} relative. "
        "CPU seconds of one in-process solve (parse, build, solve, checks), sympy's cache "
        "cleared before each; the ratio is against scipy's `solve_ivp` of the same law and "
        f"scale in the same run. Target: every law ≤ {TARGET:g} s CPU at every scale.",
        "",
        f"Worst case: **{shown(worst[0])}** ({worst[1]}); over {TARGET:g} s: {over} of {total}; "
        f"failures (an error, a wrong or missing answer, a failed check): {len(failures)}.",
        "",
        "| law | mode | CPU s, median | CPU s, worst (scale) | × scipy, median |",
        "|---|---|---|---|---|",
    ]
    for law in LAWS:
        for mode in modes:
            mine = [(s, k, r) for lw, k, m, s, r in rows if lw is law and m == mode]
            if not mine:
                lines.append(f"| {law.name}: `{law.relation}` | {mode} | – | – | – |")
                continue
            seconds = sorted(s for s, _, _ in mine)
            slowest = max(mine)
            ratios = sorted(r for _, _, r in mine)
            lines.append(
                f"| {law.name}: `{law.relation}` | {mode} | {seconds[len(seconds) // 2]:.2f} | "
                f"{slowest[0]:.2f} (1e{slowest[1]}) | {ratios[len(ratios) // 2]:.0f} |"
            )
    if failures:
        lines += ["", "Failures:", "", *(f"- {f}" for f in failures)]
    body = "\n".join(lines)
    print(body)
    if not args.no_write:
        write_section(HEADING, body, " ".join(["python bench/oneline_laws.py", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
