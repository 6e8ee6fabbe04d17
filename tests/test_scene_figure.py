"""The problem's figure on a sheet (issue 12, part 5: "hatched floors and inclines, pins and
rollers, forces attached at their points"): a planar scene drawn where its bodies are.

Expected geometry by hand from the specs: the crate (Hibbeler 12e Ex. 17.7) 1 m by 1 m
with G at the origin sits on its base C from (−0.5, −0.5) to (0.5, −0.5), pushed right at
D (−0.5, 0.3); the disk of the incline example (R = 0.2 m, slope tan β = 0.6) touches the
incline at C with the normal (−0.6, 1)/√1.36; a pendulum's pin is at O.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from dynsolve.pipeline import solve_file, solve_text
from dynsolve.render.latex import render_latex

PROBLEMS = Path(__file__).parent.parent / "problems"


def test_the_crate_stands_on_its_hatched_floor_pushed_at_its_point():
    sketch = solve_file(PROBLEMS / "seed" / "tr_hib_crate.dyn").sketch
    assert sketch is not None
    ((name, shape, x, y, sizes, angle, parts),) = sketch.bodies
    assert (name, shape, x, y, sizes, angle) == ("crate", "block", 0.0, 0.0, (1.0, 1.0), 0.0)
    assert parts == ()  # one shape, no parts
    ((_, fx, fy, nx, ny, half),) = sketch.surfaces
    assert (fx, fy, nx, ny) == (0.0, -0.5, 0.0, 1.0) and half == pytest.approx(0.9)
    ((force, px, py, dx, dy),) = sketch.forces
    assert (force, px, py, dx, dy) == ("P", -0.5, pytest.approx(0.3), 1.0, 0.0)
    assert sketch.gravity


def test_the_incline_is_drawn_along_the_contact():
    sketch = solve_file(PROBLEMS / "seed" / "gpm_seed_incline_threshold.dyn").sketch
    assert sketch is not None
    ((_, _x, _y, nx, ny, _half),) = sketch.surfaces
    size = math.sqrt(1 + 0.6**2)
    assert (nx, ny) == (pytest.approx(-0.6 / size), pytest.approx(1 / size))


def test_a_pin_is_drawn_on_its_support_and_the_sheet_shows_the_scene():
    solution = solve_file(PROBLEMS / "seed" / "fa_seed_pendulum.dyn")
    assert solution.sketch is not None and [p[0] for p in solution.sketch.pins] == ["O"]
    tex = render_latex(solution)
    scene = tex[tex.index("\\subsection*{The scene}") : tex.index("Free-body diagrams")]
    assert "pattern=north east lines" in scene and "circle[radius=1.2]" in scene
    assert "patterns" in tex.split("\\begin{document}")[0]
    handout = render_latex(solution, "handout")
    assert "\\subsection*{The scene}" in handout  # the figure is part of the problem
    assert "\\subsection*{The scene}" not in render_latex(solution, "key")


def test_a_composite_pendulum_is_drawn_as_its_rod_and_sphere():
    """Regression: the seed's rod-and-sphere pendulum (rod L = 0.6 m from the pin O at 45°
    below the horizontal, to the left; sphere r = 0.1 m with its centre d = 0.7 m from O)
    was drawn as one big circle around O. By hand: the rod's centre is at
    (−0.3 cos 45°, −0.3 sin 45°) = (−0.2121, −0.2121) m and it lies along the line to O
    (45°), the sphere's centre at (−0.7 cos 45°, −0.7 sin 45°) = (−0.4950, −0.4950) m."""
    solution = solve_file(PROBLEMS / "seed" / "fa_seed_pendulum.dyn")
    assert solution.sketch is not None
    ((name, shape, _x, _y, _sizes, _angle, parts),) = solution.sketch.bodies
    assert (name, shape) == ("pendulum", "composite")
    (rod, sphere) = parts
    c = math.cos(math.radians(45))
    assert rod[0] == "rod" and rod[1:3] == (pytest.approx(-0.3 * c), pytest.approx(-0.3 * c))
    assert rod[3] == (pytest.approx(0.6),) and rod[4] == pytest.approx(45.0)
    assert sphere[0] == "sphere" and sphere[3] == (pytest.approx(0.1),)
    assert sphere[1:3] == (pytest.approx(-0.7 * c), pytest.approx(-0.7 * c))
    tex = render_latex(solution)
    scene = tex[tex.index("\\subsection*{The scene}") : tex.index("Free-body diagrams")]
    assert "line width=2.4pt" in scene  # the rod as a bar
    # the free-body diagram draws the parts too, placed from G (r_G = 0.54 m from O)
    (body,) = solution.free_body
    assert [p[0] for p in body.parts] == ["rod", "sphere"]
    g = 0.54 / math.sqrt(2)  # G at (−0.3818, −0.3818)
    assert body.parts[1][1] == pytest.approx(-0.7 * c + g)
    fbd = tex[tex.index("Free-body diagrams") : tex.index("\\subsection*{Equations}")]
    assert "line width=2.4pt" in fbd


def test_a_scene_without_numbers_has_no_figure():
    spec = """\
given:
  m: mass
  r: length
  M: moment
scene:
  body disk: mass m, disk r, at (0, 0)
  point O: (0, 0)
  pin disk at O
  couple M on disk: ccw
find: alpha = alpha(disk)
"""
    solution = solve_text(spec)
    assert solution.sketch is None
    assert "The scene" not in render_latex(solution)


def test_a_collars_rod_is_drawn_as_a_guide():
    # newcomer report: a 'contact … guide' (two-sided) was not drawn at all. The seed
    # collar slides on a horizontal smooth rod: one guide at the collar, normal (0, 1)
    solution = solve_file(PROBLEMS / "seed" / "we_seed_collar.dyn")
    assert solution.sketch is not None
    ((_, _x, _y, nx, ny, _half),) = solution.sketch.guides
    assert (nx, ny) == (pytest.approx(0.0), pytest.approx(1.0))
    scene = render_latex(solution)
    scene = scene[scene.index("\\subsection*{The scene}") : scene.index("Free-body diagrams")]
    assert scene.count("\\draw[thin]") >= 2  # the guide's two lines
