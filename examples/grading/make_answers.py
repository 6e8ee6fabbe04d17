"""Write answers.csv: the 30 students of variants.csv answering their own drum, with mistakes.

Problem: drum.dyn (Hibbeler 12e Example 17.11 with a vary: section); each student's m_d, m_b
and r come from variants.csv. Every number is computed here from the hand derivation, not
by dynsolve (k_O = 0.25 m, g = 9.81 m/s^2):
  I_O = m_d k_O^2
  alpha = m_b g r / (I_O + m_b r^2)  (cw)     base: 78.48/6.95 = 11.292 rad/s^2
  T = I_O alpha / r                           base: 105.86 N
  a = alpha r  (down)                         base: 4.517 m/s^2
Mistakes are the same formulas with one change: g = 1 (g left out), g = 32.2 (the US
value in SI), r doubled (the diameter for the radius); or alpha x 180/pi (degrees),
a power of ten, another part's number, a reversed direction, a wrong unit.

Run: python examples/grading/make_answers.py  (rewrites answers.csv next to it)
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

K_O, G = 0.25, 9.81
ROWS = [  # per student (in variants.csv order): what each part's cell holds
    ("right", "right", "right"),
    ("right", "right", "right"),
    ("right4", "right4", "right4"),  # 4 figures
    ("signed", "lb", "signed"),  # signs instead of words; T in lb
    ("right", "kN", "ft"),  # other units of the same dimension
    ("reversed", "right", "reversed"),  # directions reversed
    ("g1", "g1", "g1"),  # g left out
    ("g32", "g32", "g32"),  # g = 32.2 in an SI problem
    ("diameter", "diameter", "diameter"),  # the diameter used for r
    ("degrees", "right", "right"),  # degrees given for radians
    ("right", "x10", "x10"),  # powers of ten
    ("right", "alpha", "right"),  # alpha's number for T
    ("a", "right", "2fig"),  # a's number for alpha; a to 2 figures
    ("right", "kg", "right"),  # a mass for a force: wrong dimension
    ("right", "right", "metres"),  # wrong dimension
    ("eleven", "right", "right"),  # unreadable
    ("right", "empty", "right"),  # missing
    ("bare", "bare", "bare"),  # bare numbers, no unit in the header
    ("right", "right", "right"),
    ("right", "right", "right"),
    ("right", "right", "right"),
    ("right", "static", "right"),  # T = m_b g: the block taken as static
    ("right", "right", "freefall"),  # a = g
    ("g1", "g1", "g1"),  # g left out again
    ("diameter", "diameter", "diameter"),  # the diameter again
    ("reversed", "right", "right"),  # alpha's sense reversed
    ("right", "right", "right"),
    ("right", "plus08", "right"),  # T 0.8 % high: within 1 %
    ("right", "minus18", "right"),  # T 1.8 % low
    ("right", "right", "right"),
]


def solve(m_d: float, m_b: float, r: float, g: float = G) -> dict[str, float]:
    """alpha (rad/s^2, cw), T (N), a (m/s^2, down) by the hand formulas above."""
    inertia = m_d * K_O**2
    alpha = m_b * g * r / (inertia + m_b * r**2)
    return {"alpha": alpha, "T": inertia * alpha / r, "a": alpha * r}


def cell(part: str, how: str, givens: tuple[float, float, float]) -> str:
    """The text one student writes for ``part``."""
    right = solve(*givens)
    unit = {"alpha": "rad/s^2", "T": "N", "a": "m/s^2"}[part]
    word = {"alpha": "cw", "T": "", "a": "down"}[part]
    value = right[part]
    m_d, m_b, r = givens
    other = {
        "g1": solve(m_d, m_b, r, 1.0),
        "g32": solve(m_d, m_b, r, 32.2),
        "diameter": solve(m_d, m_b, 2 * r),
    }
    text = {
        "right": f"{value:.3g} {unit} {word}",
        "right4": f"{value:.4g} {unit} {word}",
        "signed": f"{-value:.3g} {unit}" if word else f"{value:.3g} {unit}",
        "reversed": f"{value:.3g} {unit} {'ccw' if word == 'cw' else 'up'}",
        "degrees": f"{value * 180 / math.pi:.3g} {unit} {word}",
        "x10": f"{10 * value:.3g} {unit} {word}",
        "alpha": f"{right['alpha']:.3g} {unit} {word}",
        "a": f"{right['a']:.3g} {unit} {word}",
        "2fig": f"{value:.2g} {unit} {word}",
        "lb": f"{value / 4.4482216:.3g} lb",
        "kN": f"{value / 1000:.3g} kN",
        "ft": f"{value / 0.3048:.3g} ft/s^2 {word}",
        "kg": f"{value / G:.3g} kg",
        "metres": f"{value:.3g} m {word}",
        "eleven": "eleven",
        "empty": "",
        "bare": f"{value:.3g}",
        "static": f"{m_b * G:.3g} N",
        "freefall": f"{G:.3g} m/s^2 down",
        "plus08": f"{value * 1.008:.4g} {unit}",
        "minus18": f"{value * 0.982:.4g} {unit}",
    }
    if how in other:
        return f"{other[how][part]:.3g} {unit} {word}".strip()
    return text[how].strip()


def _number(text: str) -> float:
    return float(text.split()[0])


def main() -> None:
    """Write answers.csv next to this script."""
    folder = Path(__file__).parent
    with (folder / "variants.csv").open(encoding="utf-8") as handle:
        variants = list(csv.DictReader(handle))
    path = folder / "answers.csv"
    with path.open("w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(["student", "alpha", "T", "a"])
        for row, hows in zip(variants, ROWS, strict=True):
            givens = (_number(row["m_d"]), _number(row["m_b"]), _number(row["r"]))
            parts = ("alpha", "T", "a")
            writer.writerow(
                [row["student"], *(cell(p, h, givens) for p, h in zip(parts, hows, strict=True))]
            )


if __name__ == "__main__":
    main()
