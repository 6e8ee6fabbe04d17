"""Write answers.csv: 30 synthetic students answering the drum problem, with typical mistakes.

Problem: problems/seed/fa_hib_drum.dyn (Hibbeler 12e Example 17.11). Every number below is
derived by hand, not by dynsolve:
  I_O = m_d k_O^2 = 60(0.25)^2 = 3.75 kg m^2
  alpha = m_b g r / (I_O + m_b r^2) = 20(9.81)(0.4)/(3.75 + 3.2) = 78.48/6.95 = 11.292 rad/s^2 cw
  T = I_O alpha / r = 3.75(11.292)/0.4 = 105.86 N  (= 105.86/4.4482 = 23.80 lb)
  a = alpha r = 4.517 m/s^2 down  (= 4.517/0.3048 = 14.82 ft/s^2)
Mistakes, on the same model:
  g left out (g = 1):  alpha = 20(0.4)/6.95 = 1.151, T = 3.75(1.151)/0.4 = 10.79 N, a = 0.460
  g = 32.2 in SI:      alpha = 20(32.2)(0.4)/6.95 = 37.06, T = 347.5 N, a = 14.83 m/s^2
  diameter for r (0.8 m): alpha = 20(9.81)(0.8)/(3.75 + 12.8) = 9.484, a = 0.8(9.484) = 7.587
  degrees for radians: alpha = 11.292(180/pi) = 647.0
  a power of ten: a = 45.2, T = 1059 N;  alpha's number given for T: 11.3 N

Run: python examples/grading/make_answers.py  (rewrites answers.csv next to it)
"""

from __future__ import annotations

import csv
from pathlib import Path

RIGHT = ("11.3 rad/s^2 cw", "106 N", "4.52 m/s^2 down")
ROWS = [
    RIGHT,
    RIGHT,
    ("11.29 rad/s^2 cw", "105.9 N", "4.517 m/s^2 down"),
    ("-11.3 rad/s^2", "23.8 lb", "-4.52 m/s^2"),  # signs instead of words; T in lb
    ("11.3 rad/s^2 cw", "0.106 kN", "14.8 ft/s^2 down"),  # other units of the same dimension
    ("11.3 rad/s^2", "106 N", "4.52 m/s^2 up"),  # directions reversed
    ("1.15 rad/s^2 cw", "10.8 N", "0.460 m/s^2 down"),  # g left out
    ("37.1 rad/s^2 cw", "347 N", "14.8 m/s^2 down"),  # g = 32.2 in an SI problem
    ("9.48 rad/s^2 cw", "44.5 N", "7.59 m/s^2 down"),  # the diameter used for r
    ("647 rad/s^2 cw", "106 N", "4.52 m/s^2 down"),  # degrees given for radians
    ("11.3 rad/s^2 cw", "1059 N", "45.2 m/s^2 down"),  # powers of ten
    ("11.3 rad/s^2 cw", "11.3 N", "4.52 m/s^2 down"),  # alpha's number for T
    ("4.5 rad/s^2 cw", "106 N", "4.5 m/s^2 down"),  # a's number for alpha; 2 figures for a
    ("11.3 rad/s^2 cw", "10.8 kg", "4.52 m/s^2 down"),  # a mass for a force: wrong dimension
    ("11.3 rad/s^2 cw", "106 N", "4.52 m down"),  # wrong dimension
    ("eleven", "106 N", "4.52 m/s^2 down"),  # unreadable
    ("11.3 rad/s^2 cw", "", "4.52 m/s^2 down"),  # missing
    ("11.3", "106", "4.52"),  # bare numbers, no unit in the header
    ("11.3 rad/s^2 cw", "106 N", "4.52 m/s^2 down"),
    ("11.3 rad/s^2 cw", "106 N", "4.52 m/s^2 down"),
    ("11.3 rad/s^2 cw", "106 N", "4.52 m/s^2 down"),
    ("11.3 rad/s^2 cw", "196 N", "4.52 m/s^2 down"),  # T = m_b g: the block taken as static
    ("11.3 rad/s^2 cw", "106 N", "9.81 m/s^2 down"),  # free fall
    ("1.15 rad/s^2 cw", "10.8 N", "0.46 m/s^2 down"),  # g left out again
    ("9.48 rad/s^2 cw", "44.5 N", "7.59 m/s^2 down"),  # the diameter again
    ("11.3 rad/s^2 ccw", "106 N", "4.52 m/s^2 down"),  # alpha's sense reversed
    ("11.3 rad/s^2 cw", "106 N", "4.52 m/s^2 down"),
    ("11.3 rad/s^2 cw", "105 N", "4.52 m/s^2 down"),  # T within 1 %: 0.8 %
    ("11.3 rad/s^2 cw", "104 N", "4.52 m/s^2 down"),  # T off by 1.8 %
    ("11.3 rad/s^2 cw", "106 N", "4.52 m/s^2 down"),
]


def main() -> None:
    """Write answers.csv next to this script."""
    path = Path(__file__).with_name("answers.csv")
    with path.open("w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(["student", "alpha", "T", "a"])
        for index, row in enumerate(ROWS, start=1):
            writer.writerow([f"s{index:03d}", *row])


if __name__ == "__main__":
    main()
