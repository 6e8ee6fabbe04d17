"""Grading benchmark, end to end: a class of N students, each with their own variant.

Draws N students' variants of ``examples/grading/drum.dyn`` (Hibbeler 17.11 with a
``vary:`` section) as ``dynsolve variants`` does, writes their answers from the hand
formulas (a tenth of them with g left out, a tenth with alpha ×10, the rest right to 3
figures), then:

1. times ``dynsolve variants`` and ``dynsolve grade … --variants`` as fresh processes
   (wall time and peak resident size);
2. in-process, splits ``dynsolve grade``'s work into the one-time build (the keys: the
   closed form built, checked and evaluated for every variant; the mistakes: each
   classic mistake's closed form for every variant) and the grading of the rows (reading,
   judging and diagnosing every cell, and writing the report).

Target (issue 9): the rows graded in under 2 s after the one-time build.

    python bench/grade_class.py [--students 10000] [--no-write]
"""

from __future__ import annotations

import argparse
import csv
import random
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from report import write_section  # noqa: E402

import dynsolve.grade.command as command  # noqa: E402
import dynsolve.grade.diagnose as diagnose  # noqa: E402

PROBLEM = ROOT / "examples" / "grading" / "drum.dyn"
HEADING = "## Grading a class end to end: `bench/grade_class.py`"
K_O, G = 0.25, 9.81  # the drum's radius of gyration and g (drum.dyn)


def write_answers(variants: Path, answers: Path, seed: int = 3) -> None:
    """Each student's answers from the hand derivation of Hibbeler 17.11 on their variant:
    I_O = m_d k_O², alpha = m_b g r / (I_O + m_b r²) (cw), T = I_O alpha / r, a = alpha r."""
    rng = random.Random(seed)
    with variants.open(encoding="utf-8") as source, answers.open("w", newline="") as target:
        writer = csv.writer(target)
        writer.writerow(["student", "alpha", "T", "a"])
        for row in csv.DictReader(source):
            m_d, m_b, r = (float(row[k].split()[0]) for k in ("m_d", "m_b", "r"))
            g = 1.0 if rng.random() < 0.1 else G  # g left out
            I_O = m_d * K_O**2
            alpha = m_b * g * r / (I_O + m_b * r**2)
            T, a = I_O * alpha / r, alpha * r
            alpha *= 10 if rng.random() < 0.1 else 1  # a power-of-ten slip
            writer.writerow(
                [row["student"], f"{alpha:.3g} rad/s^2 cw", f"{T:.3g} N", f"{a:.3g} m/s^2 down"]
            )


def timed_process(arguments: list[str]) -> tuple[float, float]:
    """Wall seconds and the peak resident size (MB) of a fresh ``dynsolve`` process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "dynsolve", *arguments], check=True, capture_output=True)
    wall = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return wall, max(peak, before) / 1024


def phases(variants: Path, answers: Path, report: Path) -> dict[str, float]:
    """``dynsolve grade``'s work in-process, split into the one-time build and the rest."""
    seconds: dict[str, float] = {}

    def timing(name: str, work):  # type: ignore[no-untyped-def]
        def timed(*args, **kwargs):  # type: ignore[no-untyped-def]
            start = time.perf_counter()
            result = work(*args, **kwargs)
            seconds[name] = seconds.get(name, 0.0) + time.perf_counter() - start
            return result

        return timed

    command._keys = timing("keys", command._keys)
    diagnose.variant_mistakes = timing("mistakes", diagnose.variant_mistakes)
    request = command.GradeRequest(PROBLEM, answers, report=report, variants=variants)
    start = time.perf_counter()
    command.grade(request)
    seconds["total"] = time.perf_counter() - start
    seconds["rows"] = seconds["total"] - seconds["keys"] - seconds.get("mistakes", 0.0)
    return seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=10_000)
    parser.add_argument("--no-write", action="store_true", help="print, do not update the doc")
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp())
    roster, variants = folder / "roster.csv", folder / "variants.csv"
    answers, report = folder / "answers.csv", folder / "report.csv"
    roster.write_text(
        "student\n" + "".join(f"s{i:05d}\n" for i in range(args.students)), encoding="utf-8"
    )
    draw_wall, draw_peak = timed_process(
        ["variants", str(PROBLEM), "--roster", str(roster), "--seed", "7", "-o", str(variants)]
    )
    write_answers(variants, answers)
    grade_wall, grade_peak = timed_process(
        ["grade", str(PROBLEM), str(answers), "--variants", str(variants), "-o", str(report)]
    )
    split = phases(variants, answers, folder / "report2.csv")
    build = split["keys"] + split.get("mistakes", 0.0)
    body = "\n".join(
        [
            f"{args.students:,} students, each with their own variant of "
            "`examples/grading/drum.dyn` (3 parts; a tenth answer with g left out, a tenth "
            "with alpha ×10).",
            "",
            "| step | figure | target |",
            "|---|---|---|",
            f"| `dynsolve variants` (draw, check, write), fresh process | {draw_wall:.2f} s wall, "
            f"{draw_peak:.0f} MB peak | |",
            f"| `dynsolve grade --variants`, fresh process | {grade_wall:.2f} s wall, "
            f"{grade_peak:.0f} MB peak | |",
            f"| in-process: one-time build, keys (closed form built, checked, evaluated) | "
            f"{split['keys']:.2f} s | |",
            f"| in-process: one-time build, the classic mistakes for every variant | "
            f"{split.get('mistakes', 0.0):.2f} s | |",
            f"| in-process: grading the rows after the build (read, judge, diagnose, report) | "
            f"**{split['rows']:.2f} s** | < 2 s |",
            f"| in-process total | {split['total']:.2f} s (build {build:.2f} s) | |",
        ]
    )
    print(body)
    if not args.no_write:
        write_section(HEADING, body, " ".join(["python bench/grade_class.py", *sys.argv[1:]]))


if __name__ == "__main__":
    main()
