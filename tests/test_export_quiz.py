"""``dynsolve export moodle-xml|prairielearn``: a problem's variants as a Moodle XML quiz and
as a PrairieLearn question folder, checked against each format's published rules.

Moodle: what ``qformat_xml`` (question/format/xml/format.php) reads: a ``<quiz>`` of
``<question type=...>`` of the types it imports; ``<name><text>`` (required: "xmlimportnoname"),
``<questiontext format=...>`` with one of the formats ``trans_format`` knows, each
``<answer fraction=...>`` (percent) with ``<text>`` and, for numerical, ``<tolerance>``;
``<units><unit><multiplier>``/``<unit_name>``; ``showunits`` 0-3, ``unitgradingtype`` 0-2
(qtype_numerical's UNITINPUT..UNITNONE, UNITOPTIONAL/UNITGRADEDOUTOFMARK/..OUTOFMAX).

PrairieLearn: infoQuestion.json (required uuid, type, title, topic; type "v3" for new
questions; uuid pattern; no other properties than the schema's) and pl-number-input's
schema (docs/elements/pl-number-input.md: the attribute list, comparison relabs|sigfig|
decdig, integer digits and weight). server.py runs with the standard library only.

Expected answers by hand: the drum and block (examples/grading/drum.dyn, Hibbeler 12e
Ex. 17.11): I_O = m_d k_O^2, alpha = m_b g r / (I_O + m_b r^2), T = I_O alpha / r,
a = alpha r; the push: a = F / m.
"""

from __future__ import annotations

import csv
import json
import math
import re
import subprocess
import sys
import uuid
from html.parser import HTMLParser
from pathlib import Path
from xml.etree import ElementTree

import pytest
from typer.testing import CliRunner

from dynsolve.cli import ExitCode, app

ROOT = Path(__file__).parent.parent
DRUM = ROOT / "examples" / "grading" / "drum.dyn"
DRUM_VARIANTS = ROOT / "examples" / "grading" / "variants.csv"
runner = CliRunner()

MOODLE_TYPES = {
    "multichoice", "truefalse", "shortanswer", "numerical", "description", "matching",
    "match", "cloze", "multianswer", "essay", "calculated", "calculatedsimple",
    "calculatedmulti", "category",
}  # fmt: skip
MOODLE_TEXT_FORMATS = {"moodle_auto_format", "html", "plain_text", "wiki_like", "markdown"}
PL_INFO_PROPERTIES = {
    "comment", "uuid", "type", "title", "topic", "tags", "authors", "clientFiles",
    "clientTemplates", "template", "gradingMethod", "singleVariant", "showCorrectAnswer",
    "partialCredit", "options", "externalGradingOptions", "dependencies", "workspaceOptions",
    "sharingSets", "sharePublicly", "shareSourcePublicly", "preferences",
}  # fmt: skip
PL_UUID = re.compile(
    r"^[0-9a-fA-F]{8}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{12}$"
)
PL_NUMBER_INPUT = {
    "allow-blank", "allow-complex", "allow-fractions", "answers-name", "aria-label", "atol",
    "blank-value", "comparison", "correct-answer", "custom-format", "digits", "display",
    "initial-value", "label", "placeholder", "rtol", "show-correct-answer", "show-help-text",
    "show-placeholder", "show-score", "size", "suffix", "weight",
}  # fmt: skip

PUSH = """\
problem: Push <b>&"x"</b> ]]> {{{params.m}}}
given:
  m = 2 kg   # mass </text><script>alert(1)</script>
  F = 10 N
vary:
  m = 1..6 kg step 1
equations:
  F = m*a
find: a [m/s^2]
"""
HOSTILE_ID = "=cmd|' /C calc'!A0"


def _number(cell: str) -> float:
    return float(cell.split()[0])


def _drum(givens: dict[str, str]) -> dict[str, float]:
    """The drum's answers by hand, from a variant's givens (kg, m, m/s^2)."""
    m_d, k_o, r, m_b, g = (_number(givens[n]) for n in ("m_d", "k_O", "r", "m_b", "g"))
    inertia = m_d * k_o**2
    alpha = m_b * g * r / (inertia + m_b * r**2)
    return {"alpha": alpha, "T": inertia * alpha / r, "a": alpha * r}


def _drum_rows() -> dict[str, dict[str, str]]:
    with DRUM_VARIANTS.open(newline="") as stream:
        rows = {r["student"]: r for r in csv.DictReader(stream)}
    return {s: {"m_d": r["m_d"], "k_O": "0.25 m", "r": r["r"], "m_b": r["m_b"], "g": "9.81"}
            for s, r in rows.items()}  # fmt: skip


def _push(tmp_path: Path) -> tuple[Path, Path]:
    spec = tmp_path / "push.dyn"
    spec.write_text(PUSH)
    variants = tmp_path / "v.csv"
    variants.write_text(f"student,units,m\n{HOSTILE_ID},SI,4 kg\ns<2>&,SI,5 kg\n")
    return spec, variants


def _who(question: ElementTree.Element) -> tuple[str, ...]:
    """(student, part) of a numerical question named 'TITLE: STUDENT: PART', (part,) of a
    calculated one named 'TITLE: PART'."""
    parts = question.findtext("name/text").split(": ")
    return tuple(parts[-2:]) if question.get("type") == "numerical" else (parts[-1],)


def _check_moodle(quiz: ElementTree.Element) -> list[ElementTree.Element]:
    """Every rule of qformat_xml the file must meet; the numerical questions."""
    assert quiz.tag == "quiz"
    questions = quiz.findall("question")
    assert questions[0].get("type") == "category"
    assert questions[0].findtext("category/text").startswith("$course$/")
    numerical = []
    for question in questions[1:]:
        assert question.get("type") in MOODLE_TYPES
        assert question.get("type") == "numerical"
        assert question.findtext("name/text").strip()
        assert question.find("questiontext").get("format") in MOODLE_TEXT_FORMATS
        assert question.findtext("questiontext/text").strip()
        answers = question.findall("answer")
        assert answers and any(float(a.get("fraction")) == 100 for a in answers)
        for answer in answers:
            assert -100 <= float(answer.get("fraction")) <= 100
            assert math.isfinite(float(answer.findtext("text")))
            assert float(answer.findtext("tolerance")) >= 0
        units = question.findall("units/unit")
        if units:  # the answer's unit is the one with multiplier 1, listed first
            assert float(units[0].findtext("multiplier")) == 1.0
        for unit in units:
            assert float(unit.findtext("multiplier")) > 0
            assert unit.findtext("unit_name").strip()
        assert question.findtext("showunits") in {"0", "1", "2", "3"}
        assert question.findtext("unitgradingtype") in {"0", "1", "2"}
        assert question.findtext("unitsleft") in {"0", "1"}
        assert float(question.findtext("defaultgrade")) > 0
        numerical.append(question)
    return numerical


def test_moodle_quiz_of_the_drum_variants(tmp_path: Path) -> None:
    out = tmp_path / "quiz.xml"
    result = runner.invoke(
        app, ["export", "moodle-xml", str(DRUM), "--variants", str(DRUM_VARIANTS), "-o", str(out)]
    )
    assert result.exit_code == ExitCode.OK, result.output
    questions = _check_moodle(ElementTree.parse(out).getroot())
    rows = _drum_rows()
    assert len(questions) == 3 * len(rows)  # a question per student and part
    units = {"alpha": "rad/s^2", "T": "N", "a": "m/s^2"}
    for question in questions:
        student, part = _who(question)
        expected = _drum(rows[student])[part]
        value = float(question.findtext("answer/text"))
        assert value == pytest.approx(expected, rel=1e-9)
        # the default rule: 1 % of the key
        assert float(question.findtext("answer/tolerance")) == pytest.approx(0.01 * expected)
        assert question.findtext("units/unit/unit_name") == units[part]
        others = {u.findtext("unit_name"): float(u.findtext("multiplier"))
                  for u in question.findall("units/unit")[1:]}  # fmt: skip
        # the US customary unit too: 1 lb = 4.4482216152605 N, 1 ft = 0.3048 m
        expected_others = {
            "T": {"lb": pytest.approx(1 / 4.4482216152605)},
            "a": {"ft/s^2": pytest.approx(1 / 0.3048)},
            "alpha": {},
        }
        assert others == expected_others[part]
        text = question.findtext("questiontext/text")
        assert f"m_d = {rows[student]['m_d']}" in text
    alpha = next(q for q in questions if _who(q) == ("s001", "alpha"))
    assert "magnitude of α" in alpha.findtext("questiontext/text")  # the key is cw


def test_moodle_quiz_escapes_every_text(tmp_path: Path) -> None:
    spec, variants = _push(tmp_path)
    out = tmp_path / "quiz.xml"
    args = ["export", "moodle-xml", str(spec), "--variants", str(variants), "-o", str(out)]
    assert runner.invoke(app, [*args, "--sigfig", "3"]).exit_code == 0
    questions = _check_moodle(ElementTree.parse(out).getroot())
    names = [q.findtext("name/text") for q in questions]
    assert names[0] == f'Push <b>&"x"</b> ]]> {{{{{{params.m}}}}}}: {HOSTILE_ID}: a'
    statement = questions[0].findtext("questiontext/text")
    assert "<script>" not in statement and "&lt;/text&gt;&lt;script&gt;" in statement
    # a = 10/4 = 2.5 and 10/5 = 2; sigfig 3: half a unit (0.51) of the 3rd figure, 0.0051
    assert [float(q.findtext("answer/text")) for q in questions] == [2.5, 2.0]
    tolerances = [float(q.findtext("answer/tolerance")) for q in questions]
    assert tolerances == pytest.approx([0.0051, 0.0051])


class _Tags(HTMLParser):
    """The elements of question.html with their attributes."""

    def __init__(self) -> None:
        super().__init__()
        self.tags: list[tuple[str, dict[str, str]]] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append((tag, {k: v or "" for k, v in attrs}))


def _check_prairielearn(folder: Path) -> tuple[dict, list[dict[str, str]]]:
    """The folder against infoQuestion.json and pl-number-input's attributes."""
    assert sorted(p.name for p in folder.iterdir()) == ["info.json", "question.html", "server.py"]
    info = json.loads((folder / "info.json").read_text(encoding="utf-8"))
    assert {"uuid", "type", "title", "topic"} <= set(info) <= PL_INFO_PROPERTIES
    assert PL_UUID.match(info["uuid"]) and uuid.UUID(info["uuid"])
    assert info["type"] == "v3"
    assert isinstance(info["title"], str) and isinstance(info["topic"], str)
    assert all(isinstance(tag, str) for tag in info["tags"])
    parser = _Tags()
    html = (folder / "question.html").read_text(encoding="utf-8")
    parser.feed(html)
    assert "pl-question-panel" in [tag for tag, _ in parser.tags]
    inputs = [attrs for tag, attrs in parser.tags if tag == "pl-number-input"]
    names = [attrs["answers-name"] for attrs in inputs]
    assert len(names) == len(set(names))
    for attrs in inputs:
        assert set(attrs) <= PL_NUMBER_INPUT
        assert attrs.get("comparison", "relabs") in {"relabs", "sigfig", "decdig"}
        for key in ("rtol", "atol"):
            if key in attrs:
                assert math.isfinite(float(attrs[key]))
        for key in ("digits", "weight"):
            if key in attrs:
                int(attrs[key])
    assert "</pl-number-input>" in html  # never self-closed: HTML has no <x/> for custom tags
    return info, inputs


def _generate(folder: Path, seed: int) -> dict:
    """server.py's generate() on a fake data dict, in a Python with only the standard
    library (-I -S: no site-packages, so no dynsolve)."""
    program = (
        "import json, random, runpy, sys\n"
        f"random.seed({seed})\n"
        "ns = runpy.run_path(sys.argv[1])\n"
        "data = {'params': {}, 'correct_answers': {}, 'variant_seed': 1}\n"
        "ns['generate'](data)\n"
        "print(json.dumps(data))\n"
    )
    run = subprocess.run(
        [sys.executable, "-I", "-S", "-c", program, str(folder / "server.py")],
        capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_prairielearn_folder_of_the_drum_variants(tmp_path: Path) -> None:
    out = tmp_path / "drum_question"
    args = ["export", "prairielearn", str(DRUM), "--variants", str(DRUM_VARIANTS), "-o", str(out)]
    result = runner.invoke(app, [*args, "--topic", "Rigid-body kinetics", "--tag", "hw3"])
    assert result.exit_code == ExitCode.OK, result.output
    info, inputs = _check_prairielearn(out)
    assert info["title"] == "Drum and hanging block" and info["topic"] == "Rigid-body kinetics"
    assert info["tags"] == ["dynsolve", "hw3"]
    by_name = {attrs["answers-name"]: attrs for attrs in inputs}
    assert set(by_name) == {"alpha", "T", "a"}
    assert by_name["T"]["suffix"] == "N" and by_name["T"]["comparison"] == "relabs"
    assert float(by_name["T"]["rtol"]) == 0.01  # the default rule
    table = {tuple(sorted(r.items())) for r in _drum_rows().values()}
    seen = set()
    for seed in range(6):
        data = _generate(out, seed)
        params, answers = data["params"], data["correct_answers"]
        assert set(answers) == set(by_name)  # every input has its correct answer
        shown = {**params, "g": params["g"].split()[0]}
        assert tuple(sorted(shown.items())) in table  # a row of the variants file
        for name, expected in _drum(params).items():
            assert answers[name] == pytest.approx(expected, rel=1e-9)
        seen.add(params["m_d"] + params["m_b"] + params["r"])
    assert len(seen) > 1  # different seeds draw different variants


def test_prairielearn_rules_escaping_and_the_uuid_kept(tmp_path: Path) -> None:
    spec, variants = _push(tmp_path)
    out = tmp_path / "push_question"
    args = ["export", "prairielearn", str(spec), "--variants", str(variants), "-o", str(out)]
    assert runner.invoke(app, [*args, "--decdig", "2"]).exit_code == 0
    info, inputs = _check_prairielearn(out)
    assert info["title"] == 'Push <b>&"x"</b> ]]> {{{params.m}}}'
    assert inputs == [{"answers-name": "a", "label": "$a =$", "suffix": "m/s^2",
                       "comparison": "decdig", "digits": "2"}]  # fmt: skip
    html = (out / "question.html").read_text(encoding="utf-8")
    assert "<script>" not in html and "{{{" not in html  # no tag of the spec's text
    assert "m = {{params.m}}" in html
    assert {"2.5", "2.0"} >= {str(_generate(out, s)["correct_answers"]["a"]) for s in range(4)}
    assert HOSTILE_ID not in (out / "server.py").read_text()  # no student ids in the table
    refused = runner.invoke(app, args)
    assert refused.exit_code == ExitCode.BAD_INPUT and "--force" in refused.output
    assert runner.invoke(app, [*args, "--force"]).exit_code == 0
    assert json.loads((out / "info.json").read_text())["uuid"] == info["uuid"]


def test_prairielearn_never_writes_outside_its_folder(tmp_path: Path) -> None:
    spec, variants = _push(tmp_path)
    out = tmp_path / "q"
    out.mkdir()
    victim = tmp_path / "victim.py"
    victim.write_text("keep\n")
    (out / "server.py").symlink_to(victim)
    args = ["export", "prairielearn", str(spec), "--variants", str(variants), "-o", str(out)]
    result = runner.invoke(app, [*args, "--force"])
    assert result.exit_code == ExitCode.BAD_INPUT and "outside" in result.output
    assert victim.read_text() == "keep\n"
    assert not (out / "info.json").exists()  # refused before anything was written


def test_a_variant_without_a_key_stops_the_export(tmp_path: Path) -> None:
    spec, _ = _push(tmp_path)
    variants = tmp_path / "bad.csv"
    variants.write_text("student,units,m\ns1,SI,4 kg\ns2,SI,0 kg\n")  # a = 10/0
    out = tmp_path / "quiz.xml"
    args = ["export", "moodle-xml", str(spec), "--variants", str(variants), "-o", str(out)]
    result = runner.invoke(app, args)
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "student s2: no expected answer" in result.output
    assert not out.exists()


def test_without_variants_the_problem_as_written(tmp_path: Path) -> None:
    out = tmp_path / "quiz.xml"
    assert runner.invoke(app, ["export", "moodle-xml", str(DRUM), "-o", str(out)]).exit_code == 0
    questions = _check_moodle(ElementTree.parse(out).getroot())
    base = _drum({"m_d": "60", "k_O": "0.25", "r": "0.4", "m_b": "20", "g": "9.81"})
    # Hibbeler: alpha = 78.48 / 6.95 = 11.29 rad/s^2
    assert [_who(q) for q in questions] == [("base", "alpha"), ("base", "T"), ("base", "a")]
    assert float(questions[0].findtext("answer/text")) == pytest.approx(base["alpha"], rel=1e-9)
    assert base["alpha"] == pytest.approx(78.48 / 6.95)


def test_export_help_names_every_format() -> None:
    result = runner.invoke(app, ["export", "--help"])
    assert result.exit_code == 0
    for name in ("canvas", "scores", "moodle-xml", "prairielearn"):
        assert name in result.output


# qtype_calculated's placeholder: a letter, then anything but > } space < { " '
MOODLE_WILDCARD = re.compile(r"\{([A-Za-z][^>} <{\"']*)\}")


def test_moodle_calculated_questions_draw_the_variants(tmp_path: Path) -> None:
    out = tmp_path / "calc.xml"
    args = ["export", "moodle-xml", str(DRUM), "--variants", str(DRUM_VARIANTS), "-o", str(out)]
    result = runner.invoke(app, [*args, "--calculated"])
    assert result.exit_code == ExitCode.OK, result.output
    quiz = ElementTree.parse(out).getroot()
    questions = quiz.findall("question")[1:]
    assert [q.get("type") for q in questions] == ["calculated"] * 3  # one per part
    rows = list(_drum_rows().values())
    for question in questions:
        # what import_calculated reads without a default (format.php indexes them directly)
        for path in ("name/text", "questiontext/text", "answer/tolerance", "answer/tolerancetype",
                     "answer/correctanswerformat", "answer/correctanswerlength",
                     "dataset_definitions/dataset_definition"):  # fmt: skip
            assert question.find(path) is not None, path
        assert question.find("questiontext").get("format") in MOODLE_TEXT_FORMATS
        assert question.findtext("answer/tolerancetype") == "1"  # relative
        assert float(question.findtext("answer/tolerance")) == 0.01  # the default 1 %
        datasets = {}
        for definition in question.findall("dataset_definitions/dataset_definition"):
            assert definition.findtext("status/text") == "private"
            assert definition.findtext("type") == "calculated"
            items = definition.findall("dataset_items/dataset_item")
            assert int(definition.findtext("itemcount")) == len(items) <= 100
            assert [int(i.findtext("number")) for i in items] == list(range(1, len(items) + 1))
            datasets[definition.findtext("name/text")] = [float(i.findtext("value")) for i in items]
        wildcards = set(MOODLE_WILDCARD.findall(question.findtext("questiontext/text")))
        wildcards |= set(MOODLE_WILDCARD.findall(question.findtext("answer/text")))
        assert wildcards == set(datasets) == {"m_d", "r", "m_b", f"key_{_who(question)[-1]}"}
        part = _who(question)[-1]
        for k in range(len(datasets["m_d"])):  # item k of every dataset is one variant
            givens = {"m_d": str(datasets["m_d"][k]), "k_O": "0.25", "r": str(datasets["r"][k]),
                      "m_b": str(datasets["m_b"][k]), "g": "9.81"}  # fmt: skip
            assert datasets[f"key_{part}"][k] == pytest.approx(_drum(givens)[part], rel=1e-9)
            assert any(_number(r["m_d"]) == datasets["m_d"][k] and
                       _number(r["r"]) == datasets["r"][k] for r in rows)  # fmt: skip


def test_moodle_calculated_refuses_a_sigfig_rule(tmp_path: Path) -> None:
    out = tmp_path / "calc.xml"
    args = ["export", "moodle-xml", str(DRUM), "--variants", str(DRUM_VARIANTS), "-o", str(out)]
    result = runner.invoke(app, [*args, "--calculated", "--sigfig", "3"])
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "sigfig rule has no Moodle calculated tolerance" in result.output
    assert not out.exists()


def test_atol_sets_the_tolerance_of_its_dimension(tmp_path: Path) -> None:
    out = tmp_path / "quiz.xml"
    args = ["export", "moodle-xml", str(DRUM), "-o", str(out), "--rtol", "0"]
    assert runner.invoke(app, [*args, "--atol", "5 cm/s^2"]).exit_code == 0
    questions = _check_moodle(ElementTree.parse(out).getroot())
    tolerances = {_who(q)[1]: float(q.findtext("answer/tolerance")) for q in questions}
    # 5 cm/s^2 = 0.05 m/s^2 for a; alpha and T keep rtol 0 and no atol
    assert tolerances == {"alpha": 0.0, "T": 0.0, "a": pytest.approx(0.05)}
    refused = runner.invoke(app, [*args, "--atol", "1 kg", "--force"])
    assert refused.exit_code == ExitCode.BAD_INPUT
    assert "matches the dimension of no part" in refused.output


def test_an_angle_is_asked_in_its_display_unit(tmp_path: Path) -> None:
    spec = tmp_path / "angle.dyn"
    spec.write_text(
        "problem: Angle\ngiven:\n  x = 3 m\n  y = 4 m\nequations:\n  theta = atan(y/x)\n"
        "  d = sqrt(x^2 + y^2)\nfind: theta [deg], d\n"
    )
    out = tmp_path / "angle.xml"
    assert runner.invoke(app, ["export", "moodle-xml", str(spec), "-o", str(out)]).exit_code == 0
    theta, d = _check_moodle(ElementTree.parse(out).getroot())
    # atan(4/3) = 53.130 deg; the 3-4-5 triangle's hypotenuse is 5 m
    assert float(theta.findtext("answer/text")) == pytest.approx(53.13010235, rel=1e-9)
    assert [u.findtext("unit_name") for u in theta.findall("units/unit")] == ["deg"]
    assert float(d.findtext("answer/text")) == pytest.approx(5.0)
    assert [u.findtext("unit_name") for u in d.findall("units/unit")] == ["m", "ft"]


def test_a_zero_key_without_tolerance_is_a_warning(tmp_path: Path) -> None:
    spec = tmp_path / "balance.dyn"
    spec.write_text("given:\n  F1 = 10 N\n  F2 = 10 N\nequations:\n  R = F1 - F2\nfind: R\n")
    out = tmp_path / "q.xml"
    result = runner.invoke(app, ["export", "moodle-xml", str(spec), "-o", str(out)])
    assert result.exit_code == 0  # R = 10 - 10 = 0 N: 1 % of 0 is no tolerance
    assert "warning: the key of R is 0 for base with no tolerance" in result.output
    assert "--atol '0.01 N'" in result.output
    result = runner.invoke(app, ["export", "moodle-xml", str(spec), "-o", str(out), "--force",
                                 "--atol", "0.01 N"])  # fmt: skip
    assert result.exit_code == 0 and "warning" not in result.output
