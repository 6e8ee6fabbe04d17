"""Scene mode in the renderers: free-body diagrams and assumptions in LaTeX, Markdown, text.

The LaTeX diagrams are TikZ pictures, one command per line; the geometry tests read each
arrow back from its ``\\draw`` line to check it points the way its force does.
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import tempfile
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from latex_tools import compile_pdf

from dynsolve.render import latex
from dynsolve.render.latex import caption_latex, render_latex, safe_math
from dynsolve.render.markdown import render_markdown
from dynsolve.render.terminal import render_text
from dynsolve.results import (
    AnswerRow,
    Assumption,
    Check,
    EquationRow,
    ForceRow,
    Formula,
    FreeBody,
    GivenRow,
    KeyComparison,
    Solution,
    Step,
)

SIN = math.sin(math.radians(36.87))
COS = math.cos(math.radians(36.87))


def force(
    name: str,
    kind: str,
    point: str,
    at: tuple[float, float],
    direction: str,
    towards: tuple[float, float],
    known: bool = True,
    value: str = "",
) -> ForceRow:
    return ForceRow(name, kind, point, *at, direction, *towards, known, value)


DRUM = FreeBody(
    body="drum",
    shape="disk",
    size=(0.4,),
    motion="rotation about O",
    forces=(
        force("T", "tension", "(r, 0)", (0.4, 0.0), "down", (0.0, -1.0), False, "106 N"),
        force("W_drum", "weight", "G", (0.0, 0.0), "down", (0.0, -1.0), True, "589 N"),
        force("O_x", "reaction", "O", (0.0, 0.0), "right", (1.0, 0.0), False),
        force("O_y", "reaction", "O", (0.0, 0.0), "up", (0.0, 1.0), False, "695 N"),
    ),
    kinetic=("I_O α",),
    moment_point="O, the pin: its reactions have no moment",
)
CRATE = FreeBody(
    body="crate",
    shape="block",
    size=(1.0, 0.5),
    motion="translation",
    forces=(
        force("W_c", "weight", "G", (0.0, 0.0), "down", (0.0, -1.0), True, "981 N"),
        force("N_C", "reaction", "C", (0.0, -0.25), "up", (0.0, 1.0), False),
        force("F_C", "friction", "C", (0.0, -0.25), "left", (-1.0, 0.0), False),
        force("P", "applied", "(-0.5, 0.1)", (-0.5, 0.1), "angle -36.9°", (COS, -SIN), True),
    ),
    kinetic=("m a_Gx",),
    moment_point="G, since the crate translates",
)
LINK = FreeBody(
    body="link",
    shape="rod",
    size=(2.0,),
    motion="rotation about A",
    forces=(
        force("M", "couple", "G", (0.0, 0.0), "ccw", (0.0, 0.0), True, "50 N·m"),
        force("W_link", "weight", "G", (0.0, 0.0), "down", (0.0, -1.0), True, "196 N"),
        force("A_n", "reaction", "A", (-1.0, 0.0), "right", (1.0, 0.0), False),
        force("A_t", "reaction", "A", (-1.0, 0.0), "up", (0.0, 1.0), False),
    ),
    kinetic=("m a_Gx", "m a_Gy", "I_G α"),
    moment_point="A, the pin",
)
BALL = FreeBody(
    body="ball",
    shape="particle",
    size=(),
    motion="translation",
    forces=(
        force("W_b", "weight", "G", (0.0, 0.0), "down", (0.0, -1.0), True, "196 N"),
        force("T_2", "tension", "G", (0.0, 0.0), "up", (0.0, 1.0), False, "157 N"),
    ),
    kinetic=("m a",),
    moment_point="",
)
ASSUMPTIONS = (
    Assumption("no slip at C", True, "|F_C| = 98.1 N ≤ μ_s N_C = 196 N"),
    Assumption("no tipping", True, "x_C = 0.1 m, within the base (half-width 0.5 m)"),
    Assumption("cord T taut", False, "T = -3.2 N < 0"),
)

# Where each arrowhead must be (mm from G on the page) and which way it must point.
# Bodies are drawn 35 mm across; arrows are 10 mm long (an arrow from G is shortened to
# stay inside a block); a force pointing back toward G from a point off G ends there.
EXPECTED_TIPS = {
    "drum": [((17.5, -10.0), (0, -1)), ((0, -10), (0, -1)), ((10, 0), (1, 0)), ((0, 10), (0, 1))],
    "crate": [
        ((0, -7), (0, -1)),  # weight from G, 80 % of the 8.75 mm to the base
        ((0, -8.75), (0, 1)),  # the base's normal force pushes up into the base
        ((-10, -10.25), (-1, 0)),  # friction along the floor, 1.5 mm below the base line
        ((-17.5, 3.5), (COS, -SIN)),  # the push ends at its point on the left face
    ],
    "link": [((0, -10), (0, -1)), ((-17.5, 0), (1, 0)), ((-17.5, 10), (0, 1))],
    "ball": [((0, -10), (0, -1)), ((0, 10), (0, 1))],
}


def scene_solution(bodies: tuple[FreeBody, ...] = (DRUM, CRATE, LINK, BALL)) -> Solution:
    """A hand-built scene-mode solution: givens, answers and checks, plus the scene."""
    return Solution(
        file="scene.dyn",
        title="Drum, crate, link and ball",
        source="made up for the renderer tests",
        system="SI",
        mode="scene",
        givens=(GivenRow("m_d", "60 kg", "60 kg", "drum mass", False, "m_{d}", "60"),),
        equations=(EquationRow(12, "T r = I_O α", "T r = I_{O} α", "ΣM_O", "moment", True, False),),
        steps=(Step(1, (12,), ("T",), "linear", (Formula("T", "", "", "106 N", "106"),), (), ""),),
        answers=(AnswerRow("T", 105.9, "N", "106 N", "14715/139", "106\\,\\mathrm{N}", ""),),
        checks=(Check("units", True, "all equations"),),
        key=(KeyComparison("T", "106 N", "106 N", True, "within 0.5%"),),
        status="solved",
        free_body=bodies,
        assumptions=ASSUMPTIONS,
    )  # fmt: skip


def equation_solution() -> Solution:
    """The same solution in equation mode: no scene."""
    return replace(scene_solution(), mode="equations", free_body=(), assumptions=())


# ---- reading the pictures back

NUMBER = r"-?\d+(?:\.\d+)?"
PAIR = re.compile(rf"\(({NUMBER}),({NUMBER})\)")
Point = tuple[float, float]


def pictures(tex: str) -> dict[str, list[str]]:
    """Each body's free-body diagram (its first TikZ picture), as its lines, by body name."""
    found = re.findall(
        r"\\subsubsection\*\{(\S+) \([^)]*\)\}\n\\begin\{center\}\n(.*?)\\end\{tikzpicture\}",
        tex,
        re.S,
    )
    return {name: body.splitlines() for name, body in found}


def force_groups(lines: list[str]) -> list[tuple[bool, list[str]]]:
    """The command drawing each force, in order, and whether it is red (unknown)."""
    return [
        ("unknown" in line.split("]")[0], [line])
        for line in lines
        if line.startswith(("\\draw[force", "\\draw[thick"))
    ]


def arrowhead(commands: list[str]) -> tuple[Point, Point]:
    """The arrow's tip and unit direction: the end of its straight path, or of its arc."""
    (line,) = commands
    arc = re.search(rf"arc\[start angle=({NUMBER}),end angle=({NUMBER}),radius=({NUMBER})\]", line)
    (x0, y0), *rest = PAIR.findall(line)
    if arc:
        start, end, radius = (float(v) for v in arc.groups())
        a, b = math.radians(start), math.radians(end)
        centre = (float(x0) - radius * math.cos(a), float(y0) - radius * math.sin(a))
        tip = (centre[0] + radius * math.cos(b), centre[1] + radius * math.sin(b))
        sense = 1.0 if end > start else -1.0
        return tip, (-sense * math.sin(b), sense * math.cos(b))
    x1, y1 = rest[0]
    tail, tip = (float(x0), float(y0)), (float(x1), float(y1))
    length = math.dist(tail, tip)
    return tip, ((tip[0] - tail[0]) / length, (tip[1] - tail[1]) / length)


def label(commands: list[str]) -> str:
    labels = re.findall(r"(?:node\[[^\]]*\]|\\node\[[^\]]*\] at \([^)]*\)) \{(.*?)\};", commands[0])
    assert len(labels) == 1, commands
    return labels[0]


# ---- LaTeX: content


def test_latex_sections_in_order() -> None:
    tex = render_latex(scene_solution())
    headings = re.findall(r"\\(?:sub)*section\*\{([^}]*)\}", tex)
    assert headings == [
        "Drum, crate, link and ball", "Given", "Free-body diagrams", "drum (disk)",
        "crate (block)", "link (rod)", "ball (particle)", "Assumptions", "Equations",
        "Solution", "Answers", "Checks",
    ]  # fmt: skip
    assert "\\usepackage{tikz}" in tex.split("\\begin{document}")[0]
    assert tex.isascii()


def test_latex_text_under_each_picture() -> None:
    tex = render_latex(scene_solution())
    assert "\\textbf{Motion:} rotation about O." in tex
    assert "\\textbf{Moments about:} O, the pin: its reactions have no moment." in tex
    assert "\\textbf{Kinetic diagram:} $I_{O} \\, \\alpha$." in tex
    assert "\\textbf{Kinetic diagram:} $m \\, a_{Gx}$, $m \\, a_{Gy}$, $I_{G} \\, \\alpha$." in tex
    assert "\\textbf{Moments about:} G, since the crate translates." in tex
    ball = tex[tex.index("ball (particle)") :]
    assert "Moments about" not in ball[: ball.index("\\end{minipage}")]  # none given
    assert tex.count("Unknown forces are dashed and red") == 4


def test_latex_assumptions() -> None:
    tex = render_latex(scene_solution())
    assert (
        "\\item[$\\checkmark$] \\textbf{no slip at C} (holds): \\textbar{}$F_{C}$\\textbar{} = "
        "98.1 N $\\leq$ $\\mu_{s}$ $N_{C}$ = 196 N"
    ) in tex
    assert "\\item[$\\checkmark$] \\textbf{no tipping} (holds): $x_{C}$ = 0.1 m" in tex
    assert (
        "\\item[$\\times$] \\textbf{cord T taut} (\\textbf{fails}): T = $-$3.2 N \\textless{} 0"
        in tex
    )


@pytest.mark.parametrize("body", [DRUM, CRATE, LINK, BALL], ids=lambda b: b.body)
def test_latex_labels_and_colours(body: FreeBody) -> None:
    groups = force_groups(pictures(render_latex(scene_solution()))[body.body])
    assert len(groups) == len(body.forces)
    for (red, commands), f in zip(groups, body.forces, strict=True):
        assert red is not f.known, f.name
        name = f"${safe_math(latex.latex_name(f.name)).strip()}$"
        expected = f"{name} ({f.direction})" if f.kind == "couple" else name
        assert label(commands) == expected


@pytest.mark.parametrize("body", [DRUM, CRATE, LINK, BALL], ids=lambda b: b.body)
def test_latex_arrows_point_the_right_way(body: FreeBody) -> None:
    groups = force_groups(pictures(render_latex(scene_solution()))[body.body])
    tips = [
        arrowhead(c) for (_, c), f in zip(groups, body.forces, strict=True) if f.kind != "couple"
    ]
    for (tip, unit), (expected_tip, expected_unit) in zip(
        tips, EXPECTED_TIPS[body.body], strict=True
    ):
        assert math.dist(tip, expected_tip) < 0.02
        assert math.dist(unit, expected_unit) < 0.02


def test_latex_unknown_forces_are_dashed() -> None:
    groups = force_groups(pictures(render_latex(scene_solution()))["drum"])
    assert [red for red, _ in groups] == [True, False, True, True]  # T, O_x, O_y unknown
    assert "unknown/.style={dashed,red}" in render_latex(scene_solution())


def test_latex_couple_is_a_ccw_arc_around_g() -> None:
    (_, commands), *_ = force_groups(pictures(render_latex(scene_solution()))["link"])
    tip, unit = arrowhead(commands)
    assert math.dist(tip, (-4.24, -4.24)) < 0.02  # the arc ends at 225 degrees, radius 6 mm
    assert math.dist(unit, (math.sqrt(0.5), -math.sqrt(0.5))) < 0.02  # heading counterclockwise
    assert "radius=6]" in commands[0]
    clockwise = replace(LINK, forces=(replace(LINK.forces[0], direction="cw"),))
    (_, commands), *_ = force_groups(pictures(render_latex(scene_solution((clockwise,))))["link"])
    tip, unit = arrowhead(commands)
    assert math.dist(tip, (4.24, -4.24)) < 0.02
    assert math.dist(unit, (-math.sqrt(0.5), -math.sqrt(0.5))) < 0.02
    assert label(commands) == "$M$ (cw)"


def test_latex_outlines() -> None:
    drawn = pictures(render_latex(scene_solution()))
    assert "\\draw[very thick] (0,0) circle[radius=17.5];" in drawn["drum"]  # 35 mm across
    assert "\\draw[thin] (0,0) circle[radius=2.62];" in drawn["drum"]  # and its hub
    assert "\\draw[line width=2.4pt,line cap=round] (-17.5,0) -- (17.5,0);" in drawn["link"]
    assert "\\draw[very thick] (-17.5,-8.75) rectangle (17.5,8.75);" in drawn["crate"]  # 1 by 0.5
    assert "\\fill (0,0) circle[radius=1.25];" in drawn["ball"]
    centre = "\\fill (0,0) circle[radius=0.6] node[anchor=north east,inner sep=1pt] {$G$};"
    assert all(centre in lines for lines in drawn.values())


def test_latex_unknown_shape_is_a_small_box_or_a_pinned_drum() -> None:
    odd = FreeBody("lump", "blob", (0.3,), "translation", (), (), "")
    (lines,) = pictures(render_latex(scene_solution((odd,)))).values()
    assert "\\draw[very thick,rounded corners=2mm] (-4,-4) rectangle (4,4);" in lines
    # a body without a shape turning on a pin, pulled at its rim: a circle through the rim
    drum = replace(DRUM, shape="body", size=())
    (lines,) = pictures(render_latex(scene_solution((drum,)))).values()
    assert "\\draw[very thick] (0,0) circle[radius=17.5];" in lines


def test_latex_kinetic_diagram_beside_the_free_body() -> None:
    tex = render_latex(scene_solution((LINK,)))
    kinetic = tex[tex.index("\\quad$=$\\quad") :]
    kinetic = kinetic[: kinetic.index("\\end{tikzpicture}")]
    assert "\\draw[kinetic] (0,0) -- (10,0) node[anchor=180] {$m \\, a_{Gx}$};" in kinetic
    assert "\\draw[kinetic] (0,0) -- (0,10) node[anchor=270] {$m \\, a_{Gy}$};" in kinetic
    assert "arc[start angle=-45,end angle=225,radius=6]" in kinetic  # I_G alpha, ccw
    # a particle's m a has no direction to draw: no kinetic diagram, the terms in words
    tex = render_latex(scene_solution((BALL,)))
    assert "\\quad$=$\\quad" not in tex and "Kinetic diagram:} $m \\, a$" in tex


def test_equation_mode_output_is_unchanged() -> None:
    """Without a scene the document is exactly the sections it always had."""
    solution = equation_solution()
    sections = [
        latex._title(solution),
        latex._givens_section(solution.givens, solution.system),
        latex._equations_section(solution.equations),
        latex._solution_section(solution.steps),
        latex._answers_section(solution.answers, solution.key),
        latex._checks_section(solution.checks),
    ]
    expected = "\n\n".join([latex.PREAMBLE, "\\begin{document}", *sections, "\\end{document}"])
    assert render_latex(solution) == expected + "\n"
    markdown = render_markdown(solution)
    assert "Free-body" not in markdown and "Assumptions" not in markdown
    assert markdown.index("## Given") < markdown.index("## Equations")
    text = render_text(solution)
    assert "Free-body" not in text and "Assumptions" not in text


# ---- Markdown


def test_markdown_tables() -> None:
    document = render_markdown(scene_solution())
    order = ["## Given", "## Free-body diagrams", "### drum (disk)", "### crate (block)",
             "### link (rod)", "### ball (particle)", "## Assumptions", "## Equations"]  # fmt: skip
    assert [document.index(h) for h in order] == sorted(document.index(h) for h in order)
    header = "| Force | Kind | Point | Direction | Known | Value |"
    assert document.count(header) == 4
    for row in [
        "| $T$ | tension | (r, 0) | down | **no** | 106 N |",
        "| $W_{drum}$ | weight | G | down | yes | 589 N |",
        "| $O_{x}$ | reaction | O | right | **no** |  |",
        "| $P$ | applied | (-0.5, 0.1) | angle -36.9° | yes |  |",
        "| $M$ | couple | G | ccw | yes | 50 N·m |",
        "| $T_{2}$ | tension | G | up | **no** | 157 N |",
    ]:
        assert row in document
    assert "- Motion: rotation about O" in document
    assert "- Moments about: O, the pin: its reactions have no moment" in document
    assert "- Kinetic diagram: $m \\, a_{Gx}$, $m \\, a_{Gy}$, $I_{G} \\, α$" in document


def test_markdown_assumptions() -> None:
    document = render_markdown(scene_solution())
    table = document[document.index("## Assumptions") : document.index("## Equations")]
    assert "|  | Assumption | Detail |" in table
    assert "| ✓ | no slip at C | \\|F\\_C\\| = 98.1 N ≤ μ\\_s N\\_C = 196 N |" in table
    assert "| ✗ | cord T taut | T = -3.2 N \\< 0 |" in table


def test_markdown_escapes_awkward_names() -> None:
    odd = force("N|A*", "reaction", "[A]", (0.1, 0.0), "up", (0.0, 1.0), False, "1 | 2")
    body = FreeBody("b_1 | x", "disk", (0.1,), "rotation", (odd,), ("m·a | b",), "`O`")
    document = render_markdown(scene_solution((body,)))
    assert "### b\\_1 \\| x (disk)" in document
    assert "| N\\|A\\* | reaction | \\[A\\] | up | **no** | 1 \\| 2 |" in document
    assert "- Kinetic diagram: m·a \\| b" in document
    assert "- Moments about: \\`O\\`" in document


# ---- terminal


def test_terminal_sections() -> None:
    text = render_text(scene_solution())
    lines = [line.rstrip() for line in text.splitlines()]
    order = ["Given", "Free-body diagrams", "drum (disk)", "crate (block)", "link (rod)",
             "ball (particle)", "Equations (units checked)", "Answers", "Assumptions",
             "Checks"]  # fmt: skip
    assert [lines.index(h) for h in order] == sorted(lines.index(h) for h in order)
    start = lines.index("drum (disk)")
    assert lines[start + 1].split() == ["force", "kind", "at", "direction", "known", "value"]
    assert lines[start + 2].split() == ["T", "tension", "(r,", "0)", "down", "no", "106", "N"]
    assert lines[start + 4].split() == ["O_x", "reaction", "O", "right", "no"]
    assert (
        "motion: rotation about O · moments about O, the pin: its reactions have no moment" in lines
    )
    assert "kinetic diagram: m a_Gx, m a_Gy, I_G α" in lines
    assert "motion: translation" in lines  # the ball: no moment point
    rows = lines[lines.index("Assumptions") + 2 : lines.index("Assumptions") + 5]
    assert [r.split()[0] for r in rows] == ["✓", "✓", "✗"]
    assert "cord T taut" in rows[2] and "T = -3.2 N < 0" in rows[2]


def test_terminal_shows_markup_literally() -> None:
    odd = force("[bold]x[/bold]", "applied", "[A]", (0.0, 0.0), "up", (0.0, 1.0))
    body = FreeBody("[red]b", "disk", (0.1,), "rotation", (odd,), (), "")
    text = render_text(scene_solution((body,)))
    assert "[bold]x[/bold]" in text and "[red]b (disk)" in text


# ---- any force list: ASCII LaTeX that pdflatex accepts

NAMES = st.one_of(
    st.from_regex(r"[A-Za-z][A-Za-z0-9]{0,3}(_[A-Za-z0-9]{0,3}){0,3}", fullmatch=True),
    st.sampled_from(["lambda_", "a__b", "x_", "theta_dot", "omega2", "Sigma_x", "W_bar", "F_{A}",
                     "50%", "$x$", "\\relax", "{", "}", "#1", "μ_s", "T'", "", " ", "é", "N_A^2"]),
    st.text(max_size=12),
)  # fmt: skip
FLOATS = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False),
    st.floats(min_value=-10, max_value=10, allow_nan=False),
    st.sampled_from([0.0, -0.0, 1e-300, 5e-324, 1e300]),
)
ANGLES = st.floats(min_value=-720, max_value=720, allow_nan=False)
KINDS = st.sampled_from(["weight", "reaction", "friction", "tension", "applied", "couple"])


@st.composite
def forces(draw: st.DrawFn) -> ForceRow:
    kind = draw(st.one_of(KINDS, st.text(max_size=8)))
    angle = math.radians(draw(ANGLES))
    dx, dy = (0.0, 0.0) if kind == "couple" else (math.cos(angle), math.sin(angle))
    if draw(st.booleans()) and kind != "couple":
        dx, dy = draw(st.sampled_from([(0.0, 0.0), (1e300, 1e300), (3.0, -4.0), (-0.0, 1e-320)]))
    direction = draw(
        st.one_of(st.sampled_from(["cw", "ccw", "down", "angle 36.9°"]), st.text(max_size=8))
    )
    return ForceRow(
        draw(NAMES), kind, draw(st.text(max_size=8)), draw(FLOATS), draw(FLOATS), direction,
        dx, dy, draw(st.booleans()), draw(st.text(max_size=8)),
    )  # fmt: skip


@st.composite
def bodies(draw: st.DrawFn) -> FreeBody:
    shapes = ["disk", "ring", "cylinder", "sphere", "shell", "hollow", "rod", "block", "plate",
              "particle", "composite"]  # fmt: skip
    return FreeBody(
        body=draw(NAMES),
        shape=draw(st.one_of(st.sampled_from(shapes), st.text(max_size=8))),
        size=tuple(draw(st.lists(FLOATS, max_size=3))),
        motion=draw(st.text(max_size=12)),
        forces=tuple(draw(st.lists(forces(), max_size=6))),
        kinetic=tuple(draw(st.lists(st.one_of(NAMES, st.text(max_size=10)), max_size=3))),
        moment_point=draw(st.text(max_size=12)),
    )


SCENES = st.tuples(
    st.lists(bodies(), min_size=1, max_size=3),
    st.lists(st.builds(Assumption, NAMES, st.booleans(), st.text(max_size=20)), max_size=3),
)

# Every control word the renderer and escape_latex may write in the scene sections.
TABLES = (
    latex._TEXT_SPECIAL,
    latex._TEXT_UNICODE,
    latex._GREEK,
    latex._SYMBOLS,
    latex._SUPERSCRIPTS,
    latex._ACCENTS,
)
COMMANDS = {
    command
    for table in TABLES
    for value in table.values()
    for command in re.findall(r"\\([A-Za-z]+)", value)
} | {
    "subsection",
    "subsubsection",
    "textbf",
    "small",
    "par",
    "noindent",
    "begin",
    "end",
    "medskip",
    "linewidth",
    "draw",
    "fill",
    "node",
    "quad",
    "item",
    "text",
    "mathrm",
    "dot",
    "ddot",
    "hat",
    "bar",
    "i",
    "j",
}
ENVIRONMENTS = {"minipage", "center", "tikzpicture", "itemize"}
OPTIONS = r"\[[^\]]*\]"
POINT = rf"\({NUMBER},{NUMBER}\)"
LABEL = r"\{.*\}"
PICTURE_LINE = re.compile(
    rf"\\begin\{{tikzpicture\}}\[x=1mm,y=1mm,.*\]|\\end\{{tikzpicture\}}|\\quad\$=\$\\quad"
    rf"|\\draw{OPTIONS} {POINT} circle\[radius={NUMBER}\](?: node{OPTIONS} {LABEL})?;"
    rf"|\\fill {POINT} circle\[radius={NUMBER}\](?: node{OPTIONS} {LABEL})?;"
    rf"|\\draw{OPTIONS} {POINT} rectangle {POINT};|\\draw{OPTIONS} {POINT} -- {POINT}"
    rf"(?: node{OPTIONS} {LABEL})?;"
    rf"|\\draw{OPTIONS} {POINT} arc\[start angle={NUMBER},end angle={NUMBER},radius={NUMBER}\];"
    rf" \\node{OPTIONS} at {POINT} {LABEL};"
)


def scene_part(tex: str) -> str:
    return tex[
        tex.index("\\subsection*{Free-body diagrams}") : tex.index("\\subsection*{Equations}")
    ]


def assert_safe_tex(part: str) -> None:
    """Balanced groups and math, no stray specials, no unknown commands, sane coordinates."""
    assert part.isascii()
    assert all(c.isprintable() for line in part.splitlines() for c in line)
    plain = part.replace("{1mm}%\n", "{1mm}\n")  # the picture's one comment
    plain = re.sub(r"\\[\\{}$%#&_ ,'`^~\"=.]", "", plain)  # escapes, \\, \, and accents
    depth = 0
    for char in plain:
        depth += {"{": 1, "}": -1}.get(char, 0)
        assert depth >= 0, part
    assert depth == 0
    spans = plain.split("$")
    assert len(spans) % 2 == 1, "unbalanced $"
    for i, span in enumerate(spans):
        assert not set(span) & ({"&", "#", "%"} if i % 2 else {"&", "#", "%", "_", "^"}), span
    assert set(re.findall(r"\\([A-Za-z]+)", part)) <= COMMANDS
    assert set(re.findall(r"\\(?:begin|end)\{([^}]*)\}", part)) <= ENVIRONMENTS
    in_picture = False
    for line in part.splitlines():
        in_picture = in_picture or line.startswith("\\begin{tikzpicture}")
        if in_picture:
            assert PICTURE_LINE.fullmatch(line), line
            geometry = re.sub(r"\{.*?\}|anchor=\d+|angle=-?\d+", "", line)  # lengths only
            assert all(abs(float(n)) < 150 for n in re.findall(NUMBER, geometry)), line
        in_picture = in_picture and line != "\\end{tikzpicture}"


@settings(max_examples=150, deadline=None)
@given(SCENES)
def test_any_scene_gives_safe_ascii_latex(scene: tuple[list[FreeBody], list[Assumption]]) -> None:
    free_body, assumptions = scene
    tex = render_latex(
        replace(scene_solution(), free_body=tuple(free_body), assumptions=tuple(assumptions))
    )
    assert tex.isascii()
    assert_safe_tex(scene_part(tex))
    drawn = pictures(tex)
    for body in free_body:
        name = caption_latex(body.body) or "?"  # theta_dot as $\theta_{dot}$
        assert name in tex
    pictures_drawn = len(re.findall(r"\\begin\{tikzpicture\}", tex))
    assert len(free_body) <= pictures_drawn <= 2 * len(free_body)  # and kinetic diagrams
    assert len(drawn) <= len(free_body)


@given(SCENES)
def test_any_scene_renders_in_markdown_and_text(
    scene: tuple[list[FreeBody], list[Assumption]],
) -> None:
    free_body, assumptions = scene
    solution = replace(scene_solution(), free_body=tuple(free_body), assumptions=tuple(assumptions))
    document = render_markdown(solution)
    table_rows = [line for line in document.splitlines() if line.startswith("| ")]
    for row in table_rows:
        assert len(re.findall(r"(?<!\\)\|", row)) in (4, 5, 7, 8)  # 3, 4 or 6 cells
    assert render_text(solution).count("Free-body diagrams") == 1


# ---- pdflatex


@pytest.mark.latex
def test_scene_compiles(tmp_path: Path, pdflatex: str) -> None:
    pdf = compile_pdf(render_latex(scene_solution()), tmp_path, pdflatex)
    tool = shutil.which("pdftotext")
    if tool:
        text = subprocess.run([tool, str(pdf), "-"], capture_output=True, text=True, check=True)
        words = " ".join(text.stdout.split())
        for phrase in ("Free-body diagrams", "drum (disk)", "ball (particle)", "Assumptions",
                       "no slip at C", "Motion: rotation about A"):  # fmt: skip
            assert phrase in words


@pytest.mark.latex
def test_awkward_scene_compiles(tmp_path: Path, pdflatex: str) -> None:
    awkward = FreeBody(
        body="Σ & 100% {x}_#1",
        shape="composite",
        size=(math.inf, -1.0),
        motion="general plane motion \\ ~ ^",
        forces=(
            force("\\relax", "applied", "$", (math.nan, 1e300), "?", (0.0, 0.0)),
            force("μ_s", "couple", "G", (5e-324, 0.0), "clockwise", (0.0, 0.0), False),
            force("theta_dot", "reaction", "(0, 0)", (0.0, -1e-9), "up", (1e300, 1e300), False),
            force("", "friction", "", (-3.0, 2.0), "", (-0.6, -0.8), True),
        ),
        kinetic=("m a_Gx", "I_G α²", "{", "50% of $"),
        moment_point="A & B_1 (the pin) — 100%",
    )
    tiny = replace(DRUM, size=(1e-300,), forces=(replace(DRUM.forces[0], x=1e-300),))
    solution = replace(scene_solution(), free_body=(awkward, tiny, CRATE))
    compile_pdf(render_latex(solution), tmp_path, pdflatex)


@pytest.mark.latex
@settings(
    max_examples=3, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(SCENES)
def test_random_scenes_compile(
    pdflatex: str, scene: tuple[list[FreeBody], list[Assumption]]
) -> None:
    free_body, assumptions = scene
    solution = replace(scene_solution(), free_body=tuple(free_body), assumptions=tuple(assumptions))
    with tempfile.TemporaryDirectory() as directory:
        compile_pdf(render_latex(solution), Path(directory), pdflatex)


def test_latex_pin_off_g_is_a_hole_with_its_distance_dimensioned() -> None:
    # the link turns about A, 1 m left of G (a 2 m rod drawn 35 mm long): a hole at A,
    # and a dimension line 5 mm below A–G labelled 1 m
    lines = pictures(render_latex(scene_solution((LINK,))))["link"]
    assert "\\draw[pin] (-17.5,0) circle[radius=1.1] node[anchor=0,inner sep=2pt] {$A$};" in lines
    (dimension,) = [line for line in lines if line.startswith("\\draw[dimension]")]
    assert dimension.startswith("\\draw[dimension] (0,-5) -- (-17.5,-5) ")
    assert "{$\\qty{1}{m}$};" in dimension
    # in an FPS sheet the same distance is in feet: 1 m = 3.28 ft
    fps = render_latex(replace(scene_solution((LINK,)), system="FPS"))
    assert "{$\\qty{3.28}{ft}$};" in fps
    # a drum pinned at its centre: the G mark stands for the pin, nothing to dimension
    drum = pictures(render_latex(scene_solution((DRUM,))))["drum"]
    assert not any(line.startswith(("\\draw[pin]", "\\draw[dimension]")) for line in drum)


def test_latex_kinetic_couple_label_clears_the_kinetic_arrows() -> None:
    # a pendulum's m ω² r_G heads up-right to its pin: I_G α is labelled upper left instead
    pinned = replace(
        LINK,
        forces=(*LINK.forces[1:2], force("O_n", "reaction", "O", (0.3, 0.3), "up", (0, 1), False)),
        motion="rotation about O",
        kinetic=("m ω² r_G", "I_G α"),
    )
    tex = render_latex(scene_solution((pinned,)))
    kinetic = tex[tex.index("\\quad$=$\\quad") :]
    assert "\\node[anchor=315] at (-4.95,4.95) {$I_{G} \\, \\alpha$};" in kinetic
    assert "node[anchor=225] {$m \\, \\omega^{2} \\, r_{G}$};" in kinetic


def test_latex_omega_arc_turns_the_way_the_body_does() -> None:
    # an arc over the upper left, beyond the outline (a 35 mm disk: 17.5 + 4 mm from G)
    lines = pictures(render_latex(scene_solution((replace(DRUM, omega="cw"),))))["drum"]
    (spin,) = [line for line in lines if line.startswith("\\draw[spin]")]
    assert "arc[start angle=160,end angle=100,radius=21.5]" in spin and "{$\\omega$}" in spin
    lines = pictures(render_latex(scene_solution((replace(DRUM, omega="ccw"),))))["drum"]
    (spin,) = [line for line in lines if line.startswith("\\draw[spin]")]
    assert "arc[start angle=100,end angle=160,radius=21.5]" in spin
    # a body that does not turn at the instant (the default) has none
    lines = pictures(render_latex(scene_solution((DRUM,))))["drum"]
    assert not any(line.startswith("\\draw[spin]") for line in lines)


def test_scene_free_body_carries_the_given_sense_of_omega() -> None:
    # seed pendulum: "omega pendulum: omega ccw" with ω = 3 rad/s given; the crate translates
    from dynsolve.pipeline import solve_file

    seeds = Path(__file__).resolve().parent.parent / "problems" / "seed"
    (pendulum,) = solve_file(seeds / "fa_seed_pendulum.dyn").free_body
    assert pendulum.omega == "ccw"
    (crate,) = solve_file(seeds / "tr_hib_crate.dyn").free_body
    assert crate.omega == ""


ROD_30 = """\
given:
  m = 10 kg
  L = 2 m
  theta = 30 deg
scene:
  point O: (0, 0)
  body rod: rod L, mass m, at (L/2*cos(theta), -L/2*sin(theta))
  pin rod at O
  gravity
"""  # a 10-kg, 2-m rod pinned at its end O, released from rest 30° below the horizontal


def test_a_tilted_rod_is_drawn_along_its_pin_and_without_a_centripetal_term_at_rest():
    # newcomer report: a 2-m rod pinned at O, released from rest 30° below the horizontal, was
    # drawn horizontal with O off the rod, and its kinetic diagram showed m ω² r_G with ω = 0.
    # By hand O is at −(cos 30°, −sin 30°) × 1 m from G: the bar runs along (0.866, −0.5)
    from dynsolve.pipeline import solve_text

    solution = solve_text(ROD_30 + "find: alpha = alpha(rod)\n")
    (rod,) = solution.free_body
    assert "m ω² r_G" not in rod.kinetic and "m α r_G" in rod.kinetic
    lines = pictures(render_latex(solution))["rod"]
    (bar,) = [line for line in lines if "line width=2.4pt" in line]
    (x0, y0), (x1, y1) = ((float(a), float(b)) for a, b in PAIR.findall(bar))
    assert (x1 - x0, y1 - y0) == (pytest.approx(35 * math.cos(math.pi / 6), abs=0.02),
                                  pytest.approx(-35 * 0.5, abs=0.02))  # fmt: skip


def test_a_pins_x_and_y_components_are_found_where_its_reactions_are_n_and_t():
    # newcomer report: 'O_x' was "not a quantity of this scene" for a pendulum rod.
    # By hand (rod 10 kg, 2 m, released 30° below the horizontal): O_n = m g sin 30° = 49.05 N
    # toward O, O_t = m g cos 30°/4 = 21.239 N; projected: O_x = 31.86 N left, O_y = 42.92 N up
    from dynsolve.pipeline import solve_text

    O_x, O_y = solve_text(ROD_30 + "find: O_x [N], O_y [N]\n").answers
    c, s = math.cos(math.pi / 6), 0.5
    O_n, O_t = 10 * 9.81 * s, 10 * 9.81 * c / 4
    # e_n = (−cos 30°, sin 30°) toward O; e_t ⊥ (cw α), O_t along −e_t here
    assert (O_x.value, O_x.direction) == (pytest.approx(O_n * c - O_t * s, rel=1e-12), "left")
    assert (O_y.value, O_y.direction) == (pytest.approx(O_n * s + O_t * c, rel=1e-12), "up")
