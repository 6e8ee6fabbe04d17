"""Contact lost in time: `dynsolve simulate --until 'lost(PATH)'` against the closed forms.

For a block on a smooth dome (R = 1 m, 2 m, 5 m) started at the top at v₀ from 0.01 to
0.95 √(g R), the simulated leaving angle against cos θ = 2/3 + v₀²/(3 g R); for a ball on
the inside of a loop (R = 1.5 m) entering at v_b with 2 g R < v_b² < 5 g R, against
cos θ = (2 g R − v_b²)/(3 g R) (θ from the bottom); and the normal force of one dome run
against N = m g (3 cos θ − 2) − m v₀²/R along the way (hand derivations in
tests/test_simulate_contact.py). Prints the largest relative error of cos θ (the dome)
and of θ (the loop, where cos θ passes near 0) and writes the figure (default
docs/simulate-contact.png).

    python bench/contact_lost.py [--figure docs/simulate-contact.png] [--points 15]
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from dynsolve.simulate.run import simulate_spec  # noqa: E402
from dynsolve.spec.parser import parse_spec  # noqa: E402

G = 9.81
DOME = (
    "units: SI\ngiven:\n  m = 1 kg\n  R = {R!r} m\n  v_0 = {v!r} m/s\nscene:\n"
    "  path dome: x^2 + y^2 = R^2\n  body block: particle, mass m, at (0, R)\n"
    "  velocity block: v_0, right\n  gravity\n"
)
LOOP = (
    "units: SI\ngiven:\n  m = 1 kg\n  R = {R!r} m\n  v_b = {v!r} m/s\nscene:\n"
    "  path loop: x^2 + y^2 = R^2\n  body ball: particle, mass m, at (0, -R)\n"
    "  velocity ball: v_b, right\n  gravity\n"
)


def leaving_angle(template: str, R: float, v: float, path: str) -> float:
    """The turned angle (rad) where the simulated contact is lost."""
    history = simulate_spec(parse_spec(template.format(R=R, v=v), "b.dyn"), f"lost({path})", 200.0)
    ((_, _, q, _),) = [e for e in history.events if e[0] == f"lost({path})"]
    return abs(q)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--figure", type=Path, default=ROOT / "docs" / "simulate-contact.png")
    parser.add_argument("--points", type=int, default=15)
    args = parser.parse_args()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = args.points
    figure, (left, middle, right) = plt.subplots(1, 3, figsize=(14, 4.2))
    worst = 0.0
    for R, colour, mark in ((1.0, "C0", "o"), (2.0, "C1", "s"), (5.0, "C2", "^")):
        fractions = [0.01 + 0.94 * k / (n - 1) for k in range(n)]
        simulated, closed = [], []
        for f in fractions:
            v = f * math.sqrt(G * R)
            simulated.append(math.cos(leaving_angle(DOME, R, v, "dome")))
            closed.append(2 / 3 + v * v / (3 * G * R))
            worst = max(worst, abs(simulated[-1] - closed[-1]) / closed[-1])
        left.plot(fractions, closed, "-", color=colour, label=f"closed form, R = {R:g} m")
        left.plot(fractions, simulated, mark, color=colour, mfc="none", label="simulated")
    left.set_xlabel("v₀ / √(g R)  (the three radii fall on one curve)")
    left.set_ylabel("cos θ where N = 0 (θ from the top)")
    left.set_title("block on a smooth dome")
    left.legend(fontsize=7)
    R = 1.5
    speeds = [math.sqrt(G * R * (2.02 + 2.96 * k / (n - 1))) for k in range(n)]
    simulated = [math.cos(leaving_angle(LOOP, R, v, "loop")) for v in speeds]
    closed = [(2 * G * R - v * v) / (3 * G * R) for v in speeds]
    pairs = zip(simulated, closed, strict=True)
    worst_loop = max(abs(math.acos(s) - math.acos(c)) for s, c in pairs)
    middle.plot([v * v / (G * R) for v in speeds], closed, "-", label="closed form")
    middle.plot([v * v / (G * R) for v in speeds], simulated, "o", mfc="none", label="simulated")
    middle.set_xlabel("v_b² / (g R)")
    middle.set_ylabel("cos θ where N = 0 (θ from the bottom)")
    middle.set_title("ball inside a loop, R = 1.5 m")
    middle.legend(fontsize=7)
    text = DOME.format(R=2.0, v=1.0)
    history = simulate_spec(parse_spec(text, "dome.dyn"), "lost(dome)", 1.0, samples=41)
    column = history.columns().index("N_dome [N]")
    rows = history.rows()
    top = math.acos(2 / 3 + 1.0 / (3 * G * 2.0))
    dense = [top * k / 200 for k in range(201)]
    right.plot([math.degrees(a) for a in dense], [G * (3 * math.cos(a) - 2) - 0.5 for a in dense])
    right.plot([math.degrees(abs(r[1])) for r in rows], [r[column] for r in rows], "o", mfc="none")
    right.axhline(0.0, color="0.6", linewidth=0.8)
    right.set_xlabel("θ from the top [deg]")
    right.set_ylabel("N [N]")
    right.set_title("N on the dome (1 kg, R = 2 m, v₀ = 1 m/s)")
    right.legend(["m g (3 cos θ − 2) − m v₀²/R", "simulated"], fontsize=7)
    figure.tight_layout()
    figure.savefig(args.figure, dpi=110)
    print(f"dome: largest relative error of cos θ {worst:.2e} over {3 * n} runs")
    print(f"loop: largest error of θ {worst_loop:.2e} rad over {n} runs")
    print(f"wrote {args.figure}")


if __name__ == "__main__":
    main()
