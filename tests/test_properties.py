"""Property tests: answers do not depend on the unit system the problem is stated in."""

from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.pipeline import solve_file

KG_PER_SLUG = 14.593902937206364  # 1 slug = 1 lbf*s^2/ft = 4.4482216152605 N / 0.3048 m/s^2
M_PER_FT = 0.3048

DRUM = """\
problem: Drum and hanging block (Hibbeler 17.11 form)
units: {system}
given:
  m_d = {m_d}
  k_O = {k_O}
  r = {r}
  m_b = {m_b}
  g = {g}
equations:
  I_O = m_d*k_O^2
  T*r = I_O*alpha
  m_b*g - T = m_b*a
  a = alpha*r
find: alpha [rad/s^2], T [N], a [m/s^2]
"""

magnitudes = st.floats(min_value=0.05, max_value=500, allow_nan=False, allow_infinity=False)


def solve(tmp: Path, name: str, text: str) -> dict[str, float]:
    path = tmp / f"{name}.dyn"
    path.write_text(text)
    solution = solve_file(path)
    assert solution.passed
    return {a.name: a.value for a in solution.answers}


def close(a: dict[str, float], b: dict[str, float], rel: float) -> bool:
    return all(abs(a[k] - b[k]) <= rel * max(abs(a[k]), abs(b[k]), 1e-300) for k in a)


@settings(max_examples=15, deadline=None)
@given(m_d=magnitudes, k_O=magnitudes, r=magnitudes, m_b=magnitudes)
def test_same_givens_in_si_or_fps_problem_give_the_same_answers(tmp_path_factory, m_d, k_O, r, m_b):
    # Only the base system used for solving changes; the givens are the same text.
    values = dict(
        m_d=f"{m_d!r} kg", k_O=f"{k_O!r} m", r=f"{r!r} m", m_b=f"{m_b!r} kg", g="9.81 m/s^2"
    )
    tmp = tmp_path_factory.mktemp("units")
    si = solve(tmp, "si", DRUM.format(system="SI", **values))
    fps = solve(tmp, "fps", DRUM.format(system="FPS", **values))
    assert close(si, fps, 1e-12)


@settings(max_examples=15, deadline=None)
@given(m_d=magnitudes, k_O=magnitudes, r=magnitudes, m_b=magnitudes)
def test_problem_restated_in_us_customary_units_gives_the_same_answers(
    tmp_path_factory, m_d, k_O, r, m_b
):
    tmp = tmp_path_factory.mktemp("restated")
    si_values = dict(m_d=f"{m_d!r} kg", k_O=f"{k_O!r} m", r=f"{r!r} m", m_b=f"{m_b!r} kg")
    fps_values = dict(
        m_d=f"{m_d / KG_PER_SLUG!r} slug",
        k_O=f"{k_O / M_PER_FT!r} ft",
        r=f"{r / M_PER_FT!r} ft",
        m_b=f"{m_b / KG_PER_SLUG!r} slug",
    )
    # g = 32.2 ft/s^2 is 9.81456 m/s^2 exactly (32.2 * 0.3048)
    si = solve(tmp, "si", DRUM.format(system="SI", g="9.81456 m/s^2", **si_values))
    fps = solve(tmp, "fps", DRUM.format(system="FPS", g="32.2 ft/s^2", **fps_values))
    assert close(si, fps, 1e-9)
