"""`dynsolve solve --plot`: the motion laws and paths of kinematics specs (issue 12, part 6)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.modes.kinematics_mode import build_kinematics_problem
from dynsolve.plots import _line, _plane, motion_plot
from dynsolve.spec.parser import parse_file

PROBLEMS = Path(__file__).resolve().parent.parent / "problems"


def cli(*args: str):
    return CliRunner().invoke(app, list(args))


@pytest.mark.parametrize(
    "suffix,magic", [(".png", b"\x89PNG"), (".svg", b"<?xml"), (".pdf", b"%PDF")]
)
def test_plot_writes_the_figure_in_the_format_of_its_suffix(tmp_path, suffix, magic):
    figure = tmp_path / f"drag{suffix}"
    result = cli("solve", str(PROBLEMS / "kinematics" / "drag_fall.dyn"), "--plot", str(figure))
    assert result.exit_code == 0, result.output
    assert figure.read_bytes().startswith(magic)


def test_the_plotted_laws_are_the_motion_laws(tmp_path):
    # drag fall by hand: v = v_T tanh(g t / v_T), x = (v_T²/g) ln cosh(g t / v_T), v_T = 31.32 m/s;
    # the law is not inverted (values only), so the plot integrates it
    problem = build_kinematics_problem(parse_file(PROBLEMS / "kinematics" / "drag_fall.dyn"))
    values = dict(problem.system.knowns)
    times = np.linspace(0.0, 3.0, 31)
    curves = {label: (xs, ys) for label, _, xs, ys, _ in _line(problem, values, times)}
    v_T, g = math.sqrt(2 * 9.81 / 0.02), 9.81
    assert curves["v"][1][-1] == pytest.approx(v_T * math.tanh(g * 3 / v_T), rel=1e-8)
    assert curves["x"][1][-1] == pytest.approx(
        v_T**2 / g * math.log(math.cosh(g * 3 / v_T)), rel=1e-8
    )
    assert curves["a"][1][0] == pytest.approx(g)  # from rest: no drag yet


def test_the_projectile_path_peaks_at_the_textbook_height():
    # v_0 = 20 m/s at 30°: h = v_0² sin² 30° / (2 g) = 5.097 m (by hand)
    problem = build_kinematics_problem(parse_file(PROBLEMS / "kinematics" / "projectile.dyn"))
    times = np.linspace(0.0, 2.2, 2201)
    (_, _, _xs, ys, _), _speed = _plane(problem.motion.formulas, dict(problem.system.knowns), times)
    assert max(ys) == pytest.approx(20**2 * 0.25 / (2 * 9.81), rel=1e-5)


def test_plot_of_a_scene_is_refused_before_solving(tmp_path):
    figure = tmp_path / "drum.png"
    result = cli("solve", str(PROBLEMS / "seed" / "fa_hib_drum.dyn"), "--plot", str(figure))
    assert result.exit_code == 2
    assert "--plot draws the motion of a kinematics: section" in result.stderr
    assert "dynsolve simulate" in result.stderr and not figure.exists()


def test_plot_with_an_unknown_suffix_is_refused(tmp_path):
    result = cli("solve", str(PROBLEMS / "kinematics" / "drag_fall.dyn"), "--plot", "fig.jpg")
    assert result.exit_code == 2 and "use .png, .svg, .pdf" in result.stderr


def test_the_projectile_path_ends_at_landing_not_underground(monkeypatch):
    # regression: the path ran 10 % past t_f = 2 v_0 sin 30° / g = 2.039 s (by hand) and
    # dipped to y = -0.9 m below the level ground it lands on
    import matplotlib.axes

    drawn: list[tuple] = []
    original = matplotlib.axes.Axes.plot

    def record(self, *args, **kwargs):
        drawn.append(args)
        return original(self, *args, **kwargs)

    monkeypatch.setattr(matplotlib.axes.Axes, "plot", record)
    problem = build_kinematics_problem(parse_file(PROBLEMS / "kinematics" / "projectile.dyn"))
    assert motion_plot(problem).startswith(b"\x89PNG")
    xs, ys = drawn[0][0], drawn[0][1]
    assert min(ys) > -1e-9
    assert max(xs) == pytest.approx(20**2 * math.sin(math.radians(60)) / 9.81, rel=1e-6)
    marked = [args for args in drawn[1:] if len(args) == 3 and args[2] == "o"]
    assert [x[0] for x, _, _ in marked] == pytest.approx([35.3119], rel=1e-4)
