"""Impulse and momentum over an interval of constant forces (scene mode: `travel B: for Δt`)."""

from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

G = 9.81
SEED = Path(__file__).resolve().parent.parent / "problems" / "seed"


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "impulse.dyn"
    path.write_text(text)
    return path


def test_the_drum_after_three_seconds(tmp_path):
    # Hibbeler 17.11 drum and block from rest: ΣM_O over Δt with the block's momentum,
    # α = m_b g r/(m_d k_O² + m_b r²) = 20(9.81)(0.4)/(3.75 + 3.2) = 11.292 rad/s², constant;
    # ω₂ = α Δt = 33.88 rad/s (cw), v_block = r ω₂ = 13.55 m/s, T = 106 N as in the seed
    text = (SEED / "fa_hib_drum.dyn").read_text()
    text = text.replace("  gravity\n", "  gravity\n  travel drum: for t_1\n")
    text = text.replace("given:\n", "given:\n  t_1 = 3 s\n")
    text = text.split("find:")[0] + "find: omega = omega2(drum), v = speed(block), T [N]\n"
    solution = solve_file(write(tmp_path, text))
    assert solution.passed
    omega, v, T = solution.answers
    alpha = 20 * G * 0.4 / (60 * 0.25**2 + 20 * 0.4**2)
    assert omega.value == pytest.approx(alpha * 3, rel=1e-12)
    assert omega.direction == "cw"
    assert v.value == pytest.approx(0.4 * alpha * 3, rel=1e-12)
    assert T.value == pytest.approx(20 * (G - 0.4 * alpha), rel=1e-12)
    notes = " ".join(e.note for e in solution.equations)
    assert "angular impulse and momentum about O" in notes


BLOCK = """\
given:
  m = 10 kg
  v_1 = 6 m/s
  mu_k = 0.3
  b = 0.4 m
  h = 0.2 m
scene:
  body block: mass m, block b by h, at (0, h/2)
  base B on block: from (-b/2, -h/2) to (b/2, -h/2), mu_k mu_k, slides right
  velocity block: v_1, right
  gravity
  travel block: for t_s, stops
find: t_s [s], N_B [N]
"""


def test_the_time_for_friction_to_stop_a_sliding_block(tmp_path):
    # −μk m g t = 0 − m v_1  →  t = v_1/(μk g) = 6/(0.3 × 9.81) = 2.0387 s; N = m g
    solution = solve_file(write(tmp_path, BLOCK))
    t_s, N = solution.answers
    assert t_s.value == pytest.approx(6 / (0.3 * G), rel=1e-12)
    assert N.value == pytest.approx(10 * G, rel=1e-12)


WHEEL = """\
given:
  m = 50 kg
  r = 0.4 m
  k_O = 0.3 m
  P = 50 N
  t_1 = 4 s
scene:
  point C: (0, 0)
  body wheel: mass m, disk r, gyration k_O, at (0, r)
  rolls wheel at C: normal up
  force P on wheel at G: right
  gravity
  travel wheel: for t_1
find: omega = omega2(wheel), v = speed(wheel)
"""


def test_a_wheel_pulled_from_rest_by_a_force_at_its_centre(tmp_path):
    # about the contact point: P r Δt = (I_G + m r²) ω₂ → ω₂ = 50(0.4)(4)/(4.5 + 8) = 6.4 rad/s
    # (cw), v_G = r ω₂ = 2.56 m/s
    solution = solve_file(write(tmp_path, WHEEL))
    omega, v = solution.answers
    assert omega.value == pytest.approx(6.4, rel=1e-12)
    assert omega.direction == "cw"
    assert v.value == pytest.approx(2.56, rel=1e-12)


def test_momentum_is_conserved_where_no_force_acts(tmp_path):
    # a puck on smooth ice pushed sideways: along x no external impulse, v_x stays 3 m/s;
    # along y: F Δt = m v_y → v_y = 4(2)/2 = 4 m/s, speed 5 m/s
    text = """\
given:
  m = 2 kg
  F = 4 N
  t_1 = 2 s
  v_1 = 3 m/s
scene:
  body puck: particle, mass m
  force F on puck at G: up
  velocity puck: v_1, right
  travel puck: for t_1
find: v = speed(puck)
"""
    solution = solve_file(write(tmp_path, text))
    assert solution.answers[0].value == pytest.approx(5.0, rel=1e-12)
    conserved = [e.note for e in solution.equations if "momentum conserved" in e.note]
    assert len(conserved) == 1 and "along x" in conserved[0]


@pytest.mark.parametrize(
    ("seed", "message"),
    [
        ("fa_seed_rod15.dyn", "the weight's moment about O changes"),
        ("we_seed_collar.dyn", "a spring's force changes"),
    ],
)
def test_changing_forces_are_refused_with_the_reason(tmp_path, seed, message):
    text = (SEED / seed).read_text()
    text = "\n".join(line for line in text.splitlines() if not line.strip().startswith("travel"))
    text = text.replace("  gravity\n", "  gravity\n  travel X: for t_1\n")
    body = next(
        line.split()[1].rstrip(":") for line in text.splitlines() if line.strip().startswith("body")
    )
    text = text.replace("travel X", f"travel {body}").replace("given:\n", "given:\n  t_1 = 1 s\n")
    text = text.split("find:")[0] + f"find: w = omega2({body})\n"
    with pytest.raises(SpecError, match=message):
        solve_file(write(tmp_path, text))
