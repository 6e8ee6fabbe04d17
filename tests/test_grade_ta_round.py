"""A teaching assistant's first class graded from the docs alone (newcomer round, 2026-11-28):
direction words on a key stated as an angle, a unit to the power 0, tolerances written
``+-``, the report's expected direction, help texts, export and variants paths.

Keys by hand.
- FPS incline (problems/scenes/block_moving_up_incline_fps.dyn): a 20-lb block moving UP a
  30° incline whose surface rises to the right (contact normal (-sin θ, cos θ)), μk = 0.25.
  Friction opposes the motion and gravity's slope component points down the slope, so both
  point down and to the left, 30° below the horizontal:
  a = g (sin 30° + μk cos 30°) = 32.2 (0.5 + 0.2165064) = 23.0715 ft/s²,
  F = μk W cos 30° = 0.25 · 20 · 0.8660254 = 4.330127 lb.
  With θ = 20°: a = 32.2 (0.3420201 + 0.25 · 0.9396926) = 18.5776 ft/s², F = 4.698463 lb,
  20° below the horizontal, to the left.
- Drum (Hibbeler 12e Example 17.11; problems/seed/fa_hib_drum.dyn, scene mode):
  α = 78.48/6.95 = 11.292 rad/s² cw, T = 3.75 (11.292)/0.4 = 105.86 N, a = 4.5168 m/s² down.
"""

from __future__ import annotations

import csv
import io
import json
import re
from pathlib import Path

import pytest
from typer.main import get_command
from typer.testing import CliRunner

from dynsolve.cli import app
from dynsolve.grade.semantics import Key, Rule, agreeing_words, judge
from dynsolve.units import Dim

ROOT = Path(__file__).parent.parent
INCLINE = ROOT / "problems" / "scenes" / "block_moving_up_incline_fps.dyn"
DRUM = ROOT / "problems" / "seed" / "fa_hib_drum.dyn"
DOWN_LEFT = "30.0° below the horizontal, to the left"
runner = CliRunner()


def _grade(tmp_path: Path, problem: Path, answers: str, *extra: str) -> dict:
    path = tmp_path / "answers.csv"
    path.write_text(answers, encoding="utf-8")
    out = tmp_path / "r.json"
    result = runner.invoke(app, ["grade", str(problem), str(path), "--json", str(out), *extra])
    assert result.exit_code == 0, result.output
    return {s["student"]: s["parts"] for s in json.loads(out.read_text())["students"]}


INCLINE_ANSWERS = """student,a [ft/s^2],F [lb]
s1,23.07 ft/s^2 down,4.33 lb left
s2,23.07 ft/s^2 left,4.33 lb down
s3,23.07 ft/s^2 up,4.33 lb right
s4,23.07 ft/s^2 right,4.33 lb up
s5,−23.07 ft/s^2,-4.33
s6,+23.07 ft/s^2,+4.33 lb
s7,23.07,4.33 lb
s8,23.07 ft/s^2 cw,4.23 lb left
"""


def test_words_agree_with_a_key_stated_as_an_angle(tmp_path: Path) -> None:
    # Both the key's words (down, left) agree; the opposite ones (up, right) are reversed.
    parts = _grade(tmp_path, INCLINE, INCLINE_ANSWERS)
    verdicts = {s: (p["a"]["verdict"], p["F"]["verdict"]) for s, p in parts.items()}
    assert verdicts["s1"] == verdicts["s2"] == ("correct", "correct")
    assert verdicts["s3"] == verdicts["s4"] == ("sign", "sign")
    # down-left is negative along both axes by the convention: a minus sign agrees
    assert verdicts["s5"] == ("correct", "correct")
    assert verdicts["s6"] == ("sign", "sign")
    assert verdicts["s7"] == ("correct", "correct")  # a bare number is the magnitude
    # cw is no direction of a force; 4.23 lb is 2.3 % off 4.330 lb (the TA's g027 cell)
    assert verdicts["s8"] == ("sign", "wrong")
    feedback = parts["s3"]["F"]["feedback"]
    assert DOWN_LEFT in feedback and "give down or left" in feedback


def test_the_report_states_the_expected_direction(tmp_path: Path) -> None:
    parts = _grade(tmp_path, INCLINE, INCLINE_ANSWERS, "-o", str(tmp_path / "r.csv"))
    a = parts["s5"]["a"]
    assert a["expected"] == pytest.approx(23.0715, rel=1e-5)  # the magnitude, by hand
    assert a["expected_direction"] == DOWN_LEFT
    rows = list(csv.DictReader(io.StringIO((tmp_path / "r.csv").read_text())))
    assert rows[0]["F expected direction"] == DOWN_LEFT
    assert float(rows[0]["F expected"]) == pytest.approx(4.330127, rel=1e-5)


def test_a_variant_at_20_degrees_takes_its_own_words(tmp_path: Path) -> None:
    variants = tmp_path / "v.csv"
    variants.write_text("student,units,W,theta,mu_k\ns1,US,20 lb,20 deg,0.25\n")
    answers = "student,a [ft/s^2],F [lb]\ns1,18.58 down,4.70 right\n"
    parts = _grade(tmp_path, INCLINE, answers, "--variants", str(variants))
    assert parts["s1"]["a"]["verdict"] == "correct"
    assert parts["s1"]["F"]["verdict"] == "sign"
    assert parts["s1"]["F"]["expected"] == pytest.approx(4.698463, rel=1e-5)
    assert parts["s1"]["F"]["expected_direction"] == "20.0° below the horizontal, to the left"


def test_a_sign_on_an_up_left_key_is_ambiguous() -> None:
    # a normal force 60° above the horizontal, to the left: up is positive, left negative
    key = Key("N", 77.0, Dim.of("force"), "N", direction="60.0° above the horizontal, to the left")
    assert agreeing_words(key.direction) == ("up", "left")
    verdicts = [
        judge(t, key, Rule()).verdict for t in ("77 N up", "77 N left", "77 N", "77 N down")
    ]
    assert verdicts == ["correct", "correct", "correct", "sign"]
    for text in ("-77 N", "+77 N"):
        result = judge(text, key, Rule())
        assert result.verdict == "unreadable" and "cannot say which way" in result.detail
    assert judge("77 N", key, Rule(signed=True)).verdict == "correct"  # no sign to give it


def test_a_bare_number_under_signed_is_positive_on_a_down_left_key() -> None:
    key = Key("F", 19.26, Dim.of("force"), "N", direction=DOWN_LEFT)  # 4.330 lb = 19.26 N
    assert judge("19.26 N", key, Rule(signed=True)).verdict == "sign"
    assert judge("-19.26 N", key, Rule(signed=True)).verdict == "correct"
    assert judge("19.26 N", key, Rule()).verdict == "correct"


def test_straight_line_sign_feedback_names_the_expected_words(tmp_path: Path) -> None:
    answers = "student,alpha,T,a\ns1,11.3 rad/s^2 ccw,106 N,4.52 m/s^2 up\n"
    parts = _grade(tmp_path, DRUM, answers)
    assert parts["s1"]["a"]["verdict"] == "sign"
    assert "a is down" in parts["s1"]["a"]["feedback"]
    assert "give down" in parts["s1"]["a"]["feedback"]
    assert "give cw" in parts["s1"]["alpha"]["feedback"]


ZERO_POWERS = """student,alpha [rad/s^2],T [N],a [m/s^2]
p1,11.3 foo^0,106 kg0,4.52 ft0
p2,11.3 rad^0,106 N^0,0.461 g0
p3,11.3 xyz0,106 N,4.52 m/s^2
"""


def test_a_unit_to_the_power_0_is_unreadable_not_dropped(tmp_path: Path) -> None:
    # Each number is the key in the header's unit: dropping the unit would grade it correct.
    parts = _grade(tmp_path, DRUM, ZERO_POWERS)
    for student, names in (("p1", ("alpha", "T", "a")), ("p2", ("alpha", "T", "a"))):
        for name in names:
            assert parts[student][name]["verdict"] == "unreadable", (student, name)
    assert "unknown unit 'foo'" in parts["p1"]["alpha"]["feedback"]
    assert "unknown unit 'xyz'" in parts["p3"]["alpha"]["feedback"]
    assert "power 0" in parts["p1"]["T"]["feedback"]
    assert "g_0" in parts["p2"]["a"]["feedback"]  # the hint for standard gravity
    assert parts["p3"]["T"]["verdict"] == "correct"


@pytest.mark.parametrize("written", ["5.08 +- 0.01 m/s^2", "5.08 ± 0.01 m/s^2", "5.08 +/- 0.01"])
def test_a_tolerance_written_in_ascii_gets_the_tolerance_reason(
    tmp_path: Path, written: str
) -> None:
    parts = _grade(tmp_path, DRUM, f"student,alpha,T,a\ns1,,,{written}\n")
    assert parts["s1"]["a"]["verdict"] == "unreadable"
    assert parts["s1"]["a"]["feedback"].endswith("has a tolerance: give one value")


def test_a_bare_number_in_a_numbered_column_says_how_to_give_a_unit(tmp_path: Path) -> None:
    answers = "ID number;Response 1;Response 2;Response 3\nu1;11,3;106 N;4,52 m/s^2\n"
    path = tmp_path / "moodle.csv"
    path.write_text(answers)
    out = tmp_path / "r.json"
    result = runner.invoke(app, ["grade", str(DRUM), str(path), "--json", str(out)])
    assert result.exit_code == 0, result.output
    document = json.loads(out.read_text())
    alpha = document["students"][0]["parts"]["alpha"]
    assert alpha["verdict"] == "unreadable"
    assert "head the column 'alpha [rad/s^2]'" in alpha["feedback"]
    assert any("head every answer column by its find" in w for w in document["warnings"])


def _commands(command, path):  # type: ignore[no-untyped-def]
    yield path, command
    for name, sub in getattr(command, "commands", {}).items():
        yield from _commands(sub, [*path, name])


def test_help_texts_keep_their_brackets() -> None:
    # rich markup swallows '[rad/s^2]' unless escaped: every bracketed text of a help
    # (a command's or an option's) must reach the rendered --help.
    for path, command in _commands(get_command(app), []):
        texts = [command.help or "", *(getattr(p, "help", "") or "" for p in command.params)]
        result = runner.invoke(app, [*path, "--help"], env={"COLUMNS": "400"})
        assert result.exit_code == 0, path
        shown = re.sub(r"[\s│]+", " ", result.output)
        for text in texts:
            for bracketed in re.findall(r"\[[^\]\n]*\]", text.replace("\\[", "[")):
                assert re.sub(r"\s+", " ", bracketed) in shown, (path, bracketed)
    grade_help = runner.invoke(app, ["grade", "--help"], env={"COLUMNS": "400"}).output
    assert "('alpha [rad/s^2]')" in grade_help


def test_prairielearn_export_creates_missing_parent_folders(tmp_path: Path) -> None:
    folder = tmp_path / "pl" / "questions" / "drum"
    result = runner.invoke(app, ["export", "prairielearn", str(DRUM), "-o", str(folder)])
    assert result.exit_code == 0, result.output
    assert (folder / "info.json").is_file() and (folder / "server.py").is_file()
    blocker = tmp_path / "file"
    blocker.write_text("x")
    refused = runner.invoke(app, ["export", "prairielearn", str(DRUM), "-o", str(blocker / "q")])
    assert refused.exit_code == 2 and "is a file, not a folder" in refused.output


def test_variants_of_an_fps_problem_are_labelled_us(tmp_path: Path) -> None:
    spec = tmp_path / "incline.dyn"
    text = INCLINE.read_text().replace("scene:", "vary:\n  W = 15..25 lb step 1\nscene:", 1)
    spec.write_text(text)
    roster = tmp_path / "roster.csv"
    roster.write_text("student\ng1\ng2\n")
    out = tmp_path / "v.csv"
    args = ["variants", str(spec), "--roster", str(roster), "--seed", "3", "-o", str(out)]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert [r["units"] for r in rows] == ["US", "US"]
    assert all(r["W"].endswith(" lb") for r in rows)
