"""Work and energy of a particle between two states (scene mode, `travel`)."""

import math
from pathlib import Path

import pytest

from dynsolve.errors import SpecError
from dynsolve.pipeline import solve_file

DROP = """\
given:
  m = 3 kg
  h = 5 m
  v_1 = {v_1}
scene:
  body ball: particle, mass m, at (0, h)
  velocity ball: v_1, right
  gravity
  travel ball: to (0, 0)
find: v = speed(ball)
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "energy.dyn"
    path.write_text(text)
    return path


@pytest.mark.parametrize("v_1", ["0 m/s", "4 m/s"])
def test_a_drop_gains_two_g_h(tmp_path, v_1):
    # (1/2) m v² = (1/2) m v_1² + m g h  ->  v = sqrt(v_1² + 2 g h)
    speed = float(v_1.split()[0])
    answer = solve_file(write(tmp_path, DROP.format(v_1=v_1))).answers[0]
    assert answer.value == pytest.approx(math.sqrt(speed**2 + 2 * 9.81 * 5), rel=1e-12)


def test_the_collar_seed_from_its_scene():
    seed = Path(__file__).resolve().parent.parent / "problems" / "seed" / "we_seed_collar.dyn"
    solution = solve_file(seed)
    assert solution.mode == "scene" and solution.passed
    note = next(e.note for e in solution.equations if e.note.startswith("T1 + ΣU"))
    assert "no work: N_G" in note  # the guide's normal force does no work


@pytest.mark.parametrize(
    ("scene", "message"),
    [
        ("body ball: mass m, disk h, at (0, h)", "supported for particles"),
        ("contact ball at G: normal up, mu_s 0.3", "friction at"),
    ],
)
def test_unsupported_states_say_so(tmp_path, scene, message):
    text = DROP.format(v_1="0 m/s")
    if scene.startswith("body"):
        text = text.replace("body ball: particle, mass m, at (0, h)", scene)
    else:
        text = text.replace("  gravity\n", f"  gravity\n  {scene}\n")
    with pytest.raises(SpecError) as caught:
        solve_file(write(tmp_path, text))
    assert message in caught.value.message
