"""The HTML page (``dynsolve solve --format html``): structure, escaping, figures as SVG
drawn from the sheet's TikZ, MathML equations, and how headless Chromium renders it."""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

import pytest
from browser_tools import dump_dom, screenshot
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.pipeline import solve_file
from dynsolve.render.html import render_html
from dynsolve.render.latex import render_latex
from dynsolve.render.tikz_svg import label_runs, svg_pictures
from dynsolve.results import AnswerRow, Solution
from dynsolve.system import SolveOptions

ROOT = Path(__file__).resolve().parents[1]
DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
# The drum (Hibbeler 12e Example 17.11) draws its scene and, for each of its two bodies
# (drum, block), a free-body diagram = a kinetic diagram: 1 + 2 * 2 = 5 figures.
DRUM_FIGURES = 5
DRUM_EQUATIONS = 6  # ΣFx, ΣFy, ΣM_O (drum); ΣFx, ΣFy (block); the cord's constraint


class _Page(HTMLParser):
    """The tags a page opens and the text a reader sees (not <style> or <title>); its prose:
    the text outside mathematics, figures and the spec's file name."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.attrs: list[tuple[str, str | None]] = []
        self.text: list[str] = []
        self.prose: list[str] = []
        self._open: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        self.attrs += attrs
        if tag not in ("meta", "br", "mspace"):
            self._open.append(tag)

    def handle_endtag(self, tag: str) -> None:
        if tag in self._open:
            while self._open.pop() != tag:
                pass

    def handle_data(self, data: str) -> None:
        if {"style", "title"} & set(self._open):
            return
        self.text.append(data)
        if not {"math", "svg", "code"} & set(self._open):  # <code>: the spec's file name
            self.prose.append(data)


def _parse(page: str) -> _Page:
    parser = _Page()
    parser.feed(page)
    parser.close()
    return parser


@pytest.fixture(scope="module")
def drum_page() -> str:
    return render_html(solve_file(DRUM, SolveOptions()))


def test_the_drum_page_has_each_figure_as_svg_and_each_equation_as_mathml(drum_page: str) -> None:
    page = _parse(drum_page)
    assert page.tags[0] == "html" and drum_page.startswith("<!DOCTYPE html>")
    assert page.tags.count("svg") == DRUM_FIGURES
    assert page.tags.count("math") > DRUM_EQUATIONS
    blocks = re.findall(r'<math display="block">', drum_page)
    assert len(blocks) >= DRUM_EQUATIONS + 3  # each equation, then α, a and T solved
    assert "mfrac" in page.tags and "msub" in page.tags
    labels = [value for name, value in page.attrs if name == "aria-label"]
    assert labels == ["The scene", "Free-body diagram of drum", "Kinetic diagram of drum",
                      "Free-body diagram of block", "Kinetic diagram of block"]  # fmt: skip
    # the textbook's answers (Hibbeler 17.11: T = 106 N, α = 11.3 rad/s², a = 4.52 m/s²)
    answers = drum_page.split(">Answers<", 1)[1]
    for number in ("106", "11.3", "4.52"):
        assert f"<mn>{number}</mn>" in answers


def test_the_page_shows_no_ascii_maths(drum_page: str) -> None:
    prose = " ".join(_parse(drum_page).prose)
    for raw in ("**", "sqrt(", "Abs(", "mu_s", "\\frac", "\\mathrm", "$"):
        assert raw not in prose, raw
    assert not re.search(r"\w\*\w|[A-Za-z]_[A-Za-z0-9]", prose), prose


def test_the_page_loads_nothing_from_elsewhere(drum_page: str) -> None:
    page = _parse(drum_page)
    assert not {"script", "link", "img", "iframe", "object"} & set(page.tags)
    links = [value or "" for name, value in page.attrs if name in ("src", "href")]
    assert not [link for link in links if re.match(r"\s*(https?:)?//", link)]


def test_user_text_is_escaped() -> None:
    answer = AnswerRow("T", 1.0, "N", "1 N", "1", "1\\,\\mathrm{N}", "")
    evil = '<script>alert("x")</script> & <img src=x onerror=alert(1)>'
    solution = Solution("<b>.dyn", evil, evil, "SI", "equations", (), (), (), (answer,), (),
                        (), "solved")  # fmt: skip
    page = render_html(solution)
    parsed = _parse(page)
    assert "script" not in parsed.tags and "img" not in parsed.tags and "b" not in parsed.tags
    assert evil in "".join(parsed.text)  # shown as text, title and source alike
    assert "&lt;script&gt;" in page


def test_a_spec_title_cannot_inject_markup(tmp_path: Path) -> None:
    spec = tmp_path / "evil.dyn"
    spec.write_text(
        DRUM.read_text(encoding="utf-8").replace(
            "problem: Drum and hanging block", "problem: <script>alert(1)</script> drum"
        ),
        encoding="utf-8",
    )
    out = tmp_path / "page.html"
    result = CliRunner().invoke(app, ["solve", str(spec), "-o", str(out)])
    assert result.exit_code == 0, result.output
    page = out.read_text(encoding="utf-8")
    assert "<script" not in page and "&lt;script&gt;alert(1)&lt;/script&gt; drum" in page


def test_format_html_writes_the_page_to_stdout() -> None:
    result = CliRunner().invoke(app, ["solve", str(DRUM), "--format", "html"])
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("<!DOCTYPE html>") and result.stdout.count("<svg") == 5


def test_the_handout_page_leaves_out_lines_file_and_checks(tmp_path: Path) -> None:
    out = tmp_path / "handout.htm"  # .htm picks the format too
    result = CliRunner().invoke(app, ["solve", str(DRUM), "-o", str(out), "--handout"])
    assert result.exit_code == 0, result.output
    page = out.read_text(encoding="utf-8")
    assert "(line " not in page and "fa_hib_drum" not in page and ">Checks<" not in page
    assert "Answer key" not in page and page.count("<svg") == DRUM_FIGURES
    key = CliRunner().invoke(app, ["solve", str(DRUM), "--format", "html", "--key"]).stdout
    assert ">Checks<" in key and "Answer key" in key and "<svg" not in key


@pytest.mark.parametrize(
    "name", ["gpm_seed_pole_slip", "we_seed_collar", "ci_seed_cube_lip", "moi_hib_plate_hole"]
)
def test_every_figure_of_the_sheet_is_on_the_page(name: str) -> None:
    solution = solve_file(ROOT / "problems" / "seed" / f"{name}.dyn", SolveOptions())
    page = render_html(solution)
    assert page.count("<svg") == render_latex(solution).count("\\begin{tikzpicture}") > 0
    assert "not drawn" not in page


# ---- the SVG back end of the figures


def test_a_force_arrow_is_drawn_where_the_tikz_puts_it() -> None:
    # W pointing down from G, 10 mm: the SVG's y runs down, so its tip is at (0, 10)
    (svg,) = svg_pictures(
        "\\begin{tikzpicture}[x=1mm,y=1mm]\n"
        "\\draw[force,unknown,->] (0,0) -- (0,-10) node[anchor=90] {$W_{b}$};\n"
        "\\end{tikzpicture}"
    )
    path, head, text = svg.find("path"), svg.find("polygon"), svg.find("text")
    assert path is not None and head is not None and text is not None
    assert path.get("d") == "M0,0 L0,10" and path.get("stroke-dasharray")  # unknown: dashed
    assert path.get("stroke") == head.get("fill") != "#000"  # and red
    assert head.get("points", "").startswith("0,10 ")  # the head at the tip
    assert float(text.get("y", "0")) > 10  # the label beyond the tip (anchor north)
    assert [t.text for t in text] == ["W", "b"] and text[1].get("font-size") == "70%"


def test_an_arc_turns_the_way_the_tikz_says() -> None:
    # a ccw arc on the page (y up) sweeps the negative way once y runs down: flag 0
    (ccw,) = svg_pictures(
        "\\begin{tikzpicture}\n\\draw[spin] (5,0) arc[start angle=0,end angle=90,radius=5];\n"
        "\\end{tikzpicture}"
    )
    arc = ccw.find("path")
    assert arc is not None and arc.get("d") == "M5,0 A5,5 0 0,0 0,-5"


def test_an_unknown_tikz_command_is_refused_not_dropped() -> None:
    with pytest.raises(ValueError, match="not drawn as SVG"):
        svg_pictures("\\begin{tikzpicture}\n\\shade (0,0) circle[radius=1];\n\\end{tikzpicture}")
    with pytest.raises(ValueError, match="not drawn as SVG"):
        svg_pictures(
            "\\begin{tikzpicture}\n\\draw[shading=ball] (0,0) -- (1,1);\n\\end{tikzpicture}"
        )


def test_labels_become_text_with_subscripts() -> None:
    assert label_runs("$m \\, (a_{G})_{x}$") == [
        ("m", "", True),
        ("\u2009(", "", False),
        ("a", "", True),
        ("G", "sub", True),
        (")", "", False),
        ("x", "sub", True),
    ]
    assert label_runs("\\textit{<b>\\&}") == [("<b>&", "", True)]


# ---- in the browser


@pytest.mark.browser
def test_chromium_renders_the_drum_page(chromium: str, tmp_path: Path, drum_page: str) -> None:
    import numpy as np
    from PIL import Image

    page = tmp_path / "page.html"
    page.write_text(drum_page, encoding="utf-8")
    png = screenshot(chromium, page, tmp_path / "page.png")
    image = Image.open(png).convert("RGB")
    assert image.size == (1000, 3000)
    rgb = np.asarray(image).reshape(-1, 3).astype(int)
    r, g, b = rgb[:, 0], rgb[:, 1], rgb[:, 2]
    assert (rgb.sum(axis=1) < 600).mean() > 0.01  # text and figures, not a blank page
    # the unknown forces (red) and the kinetic diagrams (blue) are drawn
    assert ((r > 180) & (g < 80) & (b < 80)).any()
    assert ((b > 150) & (r < 60) & (g < 120)).any()


@pytest.mark.browser
def test_chromium_builds_mathml_and_svg(chromium: str, tmp_path: Path, drum_page: str) -> None:
    page = tmp_path / "page.html"
    page.write_text(drum_page, encoding="utf-8")
    dom = _parse(dump_dom(chromium, page))
    assert dom.tags.count("svg") == DRUM_FIGURES
    assert dom.tags.count("math") > DRUM_EQUATIONS and "mfrac" in dom.tags
    assert "Drum and hanging block" in "".join(dom.text)


def test_jupyter_shows_the_same_page() -> None:
    import dynsolve

    shown = dynsolve.solve(DRUM)._repr_html_()
    assert shown.startswith("<style>") and '<article class="dynsolve">' in shown
    assert shown.count("<svg") == DRUM_FIGURES and "<math" in shown and "<html" not in shown


def test_a_greek_letter_spelt_out_in_a_note_is_the_letter() -> None:
    # regression: "mu_s" in an assumption's detail was set as m·u_s (LaTeX and HTML alike)
    from dynsolve.render.latex import caption_latex
    from dynsolve.results import Assumption

    assert caption_latex("(no mu_s: static)") == "(no $\\mu_{s}$: static)"
    solution = Solution("c.dyn", "Crate", "", "SI", "scene", (), (), (), (), (), (), "solved",
                        assumptions=(Assumption("sliding", True, "no mu_s: static"),))  # fmt: skip
    page = render_html(solution)
    assert "<msub><mi>μ</mi><mrow><mi>s</mi></mrow></msub>" in page and "<mi>u</mi>" not in page


def test_a_scene_with_nothing_to_draw_has_no_empty_figure() -> None:
    # the ellipse's track is given by its equation: the sheet's scene picture is empty
    from dynsolve.results import SceneSketch

    empty = SceneSketch((), (), (), (), (), (), (), (), (), False)
    solution = Solution("e.dyn", "Track", "", "SI", "scene", (), (), (), (), (), (), "solved",
                        sketch=empty)  # fmt: skip
    page = render_html(solution)
    assert "The scene" not in page and "<svg" not in page


def test_the_svg_back_end_reads_the_tikz_it_may_be_given() -> None:
    (svg,) = svg_pictures(
        "\\begin{tikzpicture}\n"
        "\\filldraw[fill=gray!30,densely dashed] (0,0) rectangle (4,2);\n"
        "\\draw[<-,blue!70] (0,0) -- (5,0);\n"
        "\\draw[-{Stealth[length=2mm]}] (0,0) -- (0,5);\n"
        "\\coordinate (A) at (1,1);\n"
        "\\end{tikzpicture}"
    )
    rect, back, head, up, tip = list(svg)[:5]
    assert rect.get("fill") == "#808080" and rect.get("stroke") == "#000"
    assert rect.get("stroke-dasharray")
    assert back.get("stroke") == head.get("fill") == "#0044cc"
    assert head.get("points", "").startswith("0,0 ")  # <-: the head at the start
    assert up.get("d") == "M0,0 L0,-5" and tip.get("points", "").startswith("0,-5 ")


def test_a_figure_the_svg_back_end_cannot_draw_is_said_so(monkeypatch: pytest.MonkeyPatch) -> None:
    from dynsolve.render import html

    monkeypatch.setattr(
        html,
        "free_body_picture",
        lambda body, system: "\\begin{tikzpicture}\n\\shade (0,0);\n\\end{tikzpicture}",
    )
    page = render_html(solve_file(DRUM, SolveOptions()))
    assert "Free-body diagram of drum: not drawn (TikZ command not drawn as SVG" in page
