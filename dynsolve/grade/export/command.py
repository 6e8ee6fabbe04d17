"""``dynsolve export``'s work, without printing: read the inputs, build the export, write it.

>>> import pathlib, tempfile
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> _ = (folder / "gb.csv").write_text("student,score,points,max_points\\ns1,50.00,1.5,3\\n")
>>> export_gradebook(GradebookRequest(folder / "gb.csv", folder / "c.csv", "canvas", "HW 1"))
1
>>> (folder / "c.csv").read_text().splitlines()[-1]
',,s1,,,1.5'
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

from dynsolve.grade.export.canvas import canvas_csv, check_assignment, read_roster
from dynsolve.grade.export.gradebook import read_gradebook
from dynsolve.grade.export.scores import scores_csv
from dynsolve.grade.export.table import VariantTable, variant_table
from dynsolve.grade.export.target import (
    ExportError,
    check_file,
    check_folder,
    write_file,
    write_folder,
)
from dynsolve.grade.semantics import Rule
from dynsolve.system import SolveOptions


@dataclass(frozen=True)
class GradebookRequest:
    """A gradebook export: dynsolve's gradebook CSV into Canvas's or a scores CSV."""

    gradebook: Path
    output: Path
    format: str  # "canvas" or "scores"
    assignment: str = ""  # canvas: the assignment column's header
    points: float | None = None  # rescale totals to this many points
    roster: Path | None = None  # canvas: Canvas's own gradebook export
    id_column: str = "SIS User ID"  # canvas without a roster: where the id goes
    force: bool = False


@dataclass(frozen=True)
class QuizRequest:
    """A quiz export of a problem's variants (or of the problem as written)."""

    problem: Path
    output: Path
    format: str  # "moodle" or "prairielearn"
    variants: Path | None = None
    overrides: Rule = field(default_factory=Rule)
    atol: str = ""  # "0.01 m/s": the absolute tolerance of the parts of its dimension
    category: str = ""  # moodle: question bank category under the course's top
    calculated: bool = False  # moodle: calculated questions instead of numerical ones
    topic: str = "Dynamics"  # prairielearn: info.json topic
    tags: tuple[str, ...] = ()
    force: bool = False
    options: SolveOptions = field(default_factory=SolveOptions)


def export_gradebook(request: GradebookRequest) -> int:
    """Write the gradebook in the requested format; the number of students written."""
    inputs = [p for p in (request.gradebook, request.roster) if p is not None]
    _refuse_inputs(request.output, inputs)
    if request.format == "canvas":
        check_assignment(request.assignment)
    check_file(request.output, request.force)
    totals = read_gradebook(request.gradebook)
    if request.format == "canvas":
        roster = read_roster(request.roster) if request.roster is not None else None
        text = canvas_csv(totals, request.assignment, request.points, roster, request.id_column)
    elif request.format == "scores":
        text = scores_csv(totals, request.points)
    else:
        raise ExportError(f"unknown gradebook format {request.format!r}", hint="canvas or scores")
    write_file(request.output, text, request.force)
    return len(totals)


def export_quiz(request: QuizRequest) -> VariantTable:
    """Write the quiz (a Moodle XML file or a PrairieLearn folder); the table it holds."""
    from dynsolve.grade.variants import read_variants
    from dynsolve.spec.parser import parse_file

    inputs = [p for p in (request.problem, request.variants) if p is not None]
    _refuse_inputs(request.output, inputs)
    if request.format == "prairielearn":
        check_folder(request.output, request.force)
    elif request.format == "moodle":
        check_file(request.output, request.force)
    else:
        raise ExportError(f"unknown quiz format {request.format!r}", hint="moodle or prairielearn")
    spec = parse_file(request.problem)
    variants = read_variants(request.variants) if request.variants is not None else None
    table = variant_table(spec, variants, request.options, request.overrides, request.atol)
    if request.format == "moodle":
        from dynsolve.grade.export.calculated import calculated_questions
        from dynsolve.grade.export.moodle import moodle_xml

        questions = calculated_questions(table) if request.calculated else None
        quiz = moodle_xml(table, request.category, questions)
        write_file(request.output, quiz, request.force)
    else:
        from dynsolve.grade.export.prairielearn import existing_uuid, question_files

        uuid = existing_uuid(request.output)
        files = question_files(table, request.topic, request.tags, uuid)
        _refuse_inputs(request.output, inputs, names=list(files))
        write_folder(request.output, files, request.force)
    return table


def _refuse_inputs(output: Path, inputs: list[Path], names: list[str] | None = None) -> None:
    """An output (or, for a folder, a file written in it) must not be an input file."""
    targets = [output] if names is None else [output / n for n in names]
    real_inputs = {os.path.realpath(p) for p in inputs}
    for target in targets:
        if os.path.realpath(target) in real_inputs or target.suffix.lower() == ".dyn":
            raise ExportError(
                f"refusing to write {target}: it is an input", hint="choose another -o"
            )
