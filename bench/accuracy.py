"""Speed–accuracy benchmark: every bundled problem (and its scaled variants) in each mode.

For each problem under ``problems/`` and each scale 10^k (masses and lengths rescaled
through the parsed spec, :mod:`dynsolve.scaling`; k = 0 is the problem as written), the
spec is solved in-process in ``exact``, ``numeric`` and ``auto`` mode. Method: one
warm-up solve of the first problem in every mode (imports, unit cache, lark parser),
then sympy's cache is cleared before every timed solve, so no mode profits from work
another mode left in the cache; the time is ``time.process_time()`` (CPU time, so
other processes on a shared machine do not count). The error of a mode is the largest
relative difference of its answers from the exact mode's, per problem and in total;
a problem whose exact solve produced no number for an answer is left out of the error.

    python bench/accuracy.py [--ks -9,-3,3,9] [--modes exact,numeric,auto] [--repeat 3]
                             [--phases] [--no-write]

writes the table to the section "Speed–accuracy" of ``docs/benchmarks.md``. With
``--repeat N`` each solve's time is the least of N (a spec that does nearly the same work
in two modes is then not ranked by the machine's noise); with ``--phases`` the section
also says where each mode spends its time (:mod:`phases`). Totals are given over every
problem and over the problems whose givens all have values (a problem with symbolic
givens gets formulas in every mode, so numeric mode does the same work there).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import sympy  # noqa: E402
from phases import PHASES, timing  # noqa: E402
from report import write_section  # noqa: E402

from dynsolve.errors import DynsolveError  # noqa: E402
from dynsolve.pipeline import solve_spec  # noqa: E402
from dynsolve.results import Solution  # noqa: E402
from dynsolve.scaling import exact_scale, scale_spec  # noqa: E402
from dynsolve.spec.parser import parse_file  # noqa: E402
from dynsolve.system import SolveOptions  # noqa: E402

DOC = ROOT / "docs" / "benchmarks.md"
HEADING = "## Speed–accuracy: `bench/accuracy.py`"
NOTE = (
    "Numeric mode builds the same model as exact mode, with the givens as letters, so the "
    "equations it shows are dimension-checked and read as exact mode's, and it runs every "
    "check exact mode runs (with the same verdicts). It differs in the solve (linear blocks "
    "in floating point with guard digits; polynomial blocks, also of several unknowns or of "
    "one cos/sin/tan of an angle, by exact elimination and mpmath.polyroots; roots checked "
    "in numbers), in its second methods and decisions (the numbers put in first), and in the "
    "tidying of forms it only reads as numbers. See [precision.md](precision.md)."
)


@dataclass
class Row:
    """One problem at one scale: CPU seconds and largest relative error per mode."""

    name: str
    k: int
    symbolic: bool = False
    seconds: dict[str, float] = field(default_factory=dict)
    error: dict[str, float] = field(default_factory=dict)
    escalated: bool = False


def _timed(spec: object, mode: str, repeat: int = 1) -> tuple[Solution | None, float]:
    """The solution and the least CPU time of ``repeat`` solves, each from a cleared cache."""
    best = math.inf
    for _ in range(repeat):
        sympy.core.cache.clear_cache()
        started = time.process_time()
        try:
            solution = solve_spec(spec, SolveOptions(mode=mode))  # type: ignore[arg-type]
        except DynsolveError:
            solution = None
        best = min(best, time.process_time() - started)
    return solution, best


def _symbolic(spec: object) -> bool:
    """A given without a value (its answers are formulas in every mode)."""
    return any(g.quantity is None for g in spec.givens)  # type: ignore[attr-defined]


def _error(solution: Solution | None, reference: Solution | None) -> float:
    """Largest relative difference of ``solution``'s answers from ``reference``'s."""
    if reference is None:
        return math.nan
    if solution is None:
        return math.inf
    got = {row.name: row.value for row in solution.answers}
    worst = 0.0
    for row in reference.answers:
        if row.value is None:
            continue
        value = got.get(row.name)
        if value is None:
            return math.inf
        scale = abs(row.value)
        worst = max(worst, abs(value - row.value) / scale if scale else abs(value))
    return worst


def measure(
    paths: list[Path],
    ks: list[int],
    modes: list[str],
    repeat: int = 1,
    phases: dict[str, Counter[str]] | None = None,
) -> list[Row]:
    """Solve every problem at every scale in every mode; one row per problem and scale.
    With ``phases``, a second untimed pass per mode charges each mode's CPU time to the
    pipeline's phases (the wrappers cost a little, so the timed pass runs without them)."""
    import scipy.integrate  # noqa: F401  (imported on first use: not charged to one mode)

    first = parse_file(paths[0])
    for mode in modes:  # warm-up, not timed
        _timed(first, mode)
    rows = []
    for path in paths:
        spec = parse_file(path)
        for k in [0, *(exact_scale(spec, j) for j in ks)]:  # even for a half power
            row = Row(f"{path.parent.name}/{path.stem}", k, _symbolic(spec))
            scaled = scale_spec(spec, k) if k else spec
            solutions = {}
            for mode in modes:
                solutions[mode], row.seconds[mode] = _timed(scaled, mode, repeat)
                if phases is not None:
                    with timing(phases.setdefault(mode, Counter())):
                        _timed(scaled, mode)
            for mode in modes:
                row.error[mode] = _error(solutions[mode], solutions.get("exact"))
            auto = solutions.get("auto")
            row.escalated = auto is not None and any(
                c.name == "precision" and "escalated" in c.detail for c in auto.checks
            )
            rows.append(row)
            print(_line(row, modes), flush=True)
    return rows


def _worst(errors: Iterable[float]) -> float:
    return max((e for e in errors if not math.isnan(e)), default=0.0)


def _fmt_error(value: float) -> str:
    if math.isnan(value):
        return "–"
    return "0" if value == 0 else f"{value:.1e}"


def _line(row: Row, modes: list[str]) -> str:
    times = " ".join(f"{m}={row.seconds[m]:.2f}s" for m in modes)
    errors = " ".join(f"{m}={_fmt_error(row.error[m])}" for m in modes if m != "exact")
    return f"{row.name} k={row.k}: {times} | {errors}{' (auto escalated)' if row.escalated else ''}"


def table(
    rows: list[Row],
    modes: list[str],
    ks: list[int],
    repeat: int = 1,
    phases: dict[str, Counter[str]] | None = None,
) -> str:
    """The Markdown section: totals first (all problems, then those with numbers), the
    problems where a mode is slower than exact, where the time goes, then one line per
    problem (worst over scales)."""
    worst = {
        m: max((r.error[m] for r in rows if not math.isnan(r.error[m])), default=0.0) for m in modes
    }
    valued = [r for r in rows if not r.symbolic]
    timing_note = f"the least of {repeat} solves" if repeat > 1 else "one solve"
    lines = [
        HEADING,
        "",
        "Every bundled problem as written and with masses and lengths scaled by 10^k for "
        f"k in {{{', '.join(map(str, ks))}}}, in each mode; CPU time (`time.process_time`, "
        f"{timing_note} per problem, scale and mode), sympy's cache cleared before each solve "
        "after one warm-up per mode; error = largest relative difference of the answers from "
        "exact mode's. Regenerate with `python bench/accuracy.py`.",
        "",
        "| mode | problems | total CPU s (all scales) | total CPU s (as written) | vs exact | "
        "largest rel. error |",
        "|---|---|---:|---:|---:|---:|",
    ]
    for subset, label in ((rows, "all"), (valued, "with numbers")):
        totals = {m: sum(r.seconds[m] for r in subset) for m in modes}
        for m in modes:
            written = sum(r.seconds[m] for r in subset if r.k == 0)
            ratio = totals["exact"] / totals[m] if "exact" in totals and totals[m] else math.nan
            count = len({r.name for r in subset})
            lines.append(
                f"| {m} | {label} ({count}) | {totals[m]:.1f} | {written:.1f} | "
                f"{ratio:.2f}× faster | {_fmt_error(worst[m])} |"
            )
    escalated = sum(r.escalated for r in rows)
    lines += ["", f"auto escalated to exact in {escalated} of {len(rows)} solves.", ""]
    by_name: dict[str, list[Row]] = {}
    for r in rows:
        by_name.setdefault(r.name, []).append(r)
    if "exact" in modes:
        for m in modes:
            if m == "exact":
                continue
            slower = [
                f"{name} ({sum(r.seconds[m] for r in g) / sum(r.seconds['exact'] for r in g):.2f}×)"
                for name, g in by_name.items()
                if sum(r.seconds[m] for r in g) > sum(r.seconds["exact"] for r in g)
            ]
            lines.append(
                f"{m} slower than exact (total over the scales): "
                + (", ".join(slower) if slower else "none")
                + "."
            )
        lines.append("")
    if phases:
        lines += _phase_table(phases, modes)
    lines += [NOTE, ""]
    header = " | ".join(f"{m} s" for m in modes)
    errors = " | ".join(f"{m} err" for m in modes if m != "exact")
    lines += [f"| problem | {header} | {errors} |", "|---" * (1 + 2 * len(modes) - 1) + "|"]
    for name, group in by_name.items():
        times = " | ".join(f"{sum(r.seconds[m] for r in group) / len(group):.2f}" for m in modes)
        errs = " | ".join(
            _fmt_error(_worst(r.error[m] for r in group)) for m in modes if m != "exact"
        )
        lines.append(f"| {name} | {times} | {errs} |")
    lines.append("")
    lines.append("Times per problem are the mean over its scales; errors the worst over them.")
    return "\n".join(lines) + "\n"


def _phase_table(phases: dict[str, Counter[str]], modes: list[str]) -> list[str]:
    """Each mode's CPU seconds by phase of the pipeline (exclusive: they add up)."""
    names = [*PHASES, "other"]
    lines = [
        "Where the time goes (CPU s over every problem and scale, each second charged to the "
        "innermost phase running, from a separate untimed pass: `bench/phases.py`):",
        "",
        "| phase | " + " | ".join(modes) + " |",
        "|---|" + "---:|" * len(modes),
    ]
    for name in names:
        if any(phases[m][name] >= 0.005 for m in modes):
            cells = " | ".join(f"{phases[m][name]:.2f}" for m in modes)
            lines.append(f"| {name} | {cells} |")
    lines.append("| total | " + " | ".join(f"{sum(phases[m].values()):.2f}" for m in modes) + " |")
    lines.append("")
    if "exact" in phases and "numeric" in phases:
        exact, numeric = sum(phases["exact"].values()), sum(phases["numeric"].values())
        rest = numeric - phases["numeric"]["solve"]
        lines.append(
            f"Numeric mode outside its solve: {rest:.2f} s of {numeric:.2f} s. Were its solve "
            f"free, numeric mode would be {exact / rest:.2f}× faster than exact mode (this "
            "pass): the rest is the model, the forms shown, the checks and the output, which "
            "both modes build."
        )
        lines.append("")
    return lines


def write(section: str, command: str) -> None:
    """Replace (or append) the Speed–accuracy section of docs/benchmarks.md, stamped."""
    write_section(HEADING, section.removeprefix(HEADING).strip(), command, DOC)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ks", default="-9,-3,3,9", help="scales 10^k besides k = 0")
    parser.add_argument("--modes", default="exact,numeric,auto")
    parser.add_argument("--problems", default="problems/*/*.dyn", help="glob under the repo")
    parser.add_argument("--repeat", type=int, default=1, help="each time the least of N solves")
    parser.add_argument("--phases", action="store_true", help="also where each mode's time goes")
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()
    ks = [int(k) for k in args.ks.split(",") if k.strip()]
    modes = args.modes.split(",")
    paths = sorted(ROOT.glob(args.problems))
    phases: dict[str, Counter[str]] | None = {} if args.phases else None
    rows = measure(paths, ks, modes, args.repeat, phases)
    section = table(rows, modes, ks, args.repeat, phases)
    print(section)
    if not args.no_write:
        write(section, " ".join(["python bench/accuracy.py", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
