"""The command line: parse options, call the core, render, print, and set the exit code.

The only module that prints. sympy and pint are imported inside the commands, so
``dynsolve --help`` stays fast.
"""

from __future__ import annotations

import enum
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, NoReturn, TypeVar

import typer
from rich.console import Console

from dynsolve.budget import DEFAULT_MEGABYTES, DEFAULT_SECONDS, Budget

if TYPE_CHECKING:
    from dynsolve.errors import ErrorReport
    from dynsolve.grade.command import GradeRequest
    from dynsolve.grade.export.command import GradebookRequest, QuizRequest
    from dynsolve.grade.semantics import Rule
    from dynsolve.parametric.command import SweepOutput, SweepRequest
    from dynsolve.results import Check, Solution
    from dynsolve.system import SolveOptions


class ExitCode(enum.IntEnum):
    """Process exit codes."""

    OK = 0  # solved; every check and answer passed
    FAILED = 1  # an answer or a check failed
    BAD_INPUT = 2  # the input or the command line is wrong


class OutputFormat(enum.StrEnum):
    """Formats of ``dynsolve solve``."""

    text = "text"
    json = "json"
    markdown = "markdown"
    latex = "latex"
    pdf = "pdf"
    html = "html"


SUFFIX_FORMATS = {
    ".json": OutputFormat.json,
    ".md": OutputFormat.markdown,
    ".markdown": OutputFormat.markdown,
    ".tex": OutputFormat.latex,
    ".pdf": OutputFormat.pdf,
    ".html": OutputFormat.html,
    ".htm": OutputFormat.html,
}


class CheckFormat(enum.StrEnum):
    """Formats of ``dynsolve check``'s report."""

    text = "text"
    json = "json"
    junit = "junit"


class Mode(enum.StrEnum):
    """Solve modes: exact (rationals, radicals, formulas), numeric (floating point) or auto
    (numeric, escalated to exact when float64 would lose more than 3 digits)."""

    exact = "exact"
    numeric = "numeric"
    auto = "auto"


@dataclass(frozen=True)
class _Target:
    """Where ``solve`` output goes: its format, and the terminal's width and colours."""

    format: str
    to_terminal: bool
    width: int
    terminal: bool
    colours: str | None
    layout: str = "full"  # LaTeX and Markdown: full, handout or key
    source: bool | None = None  # the spec's source line on the sheet (None: not on a handout)
    plot: str = ""  # the --plot file's suffix (.png, .svg, .pdf), "" for none
    figure: str = ""  # a LaTeX sheet's motion plot: the file name it includes, "" for none


@dataclass(frozen=True)
class _Done:
    """A solved spec's rendered output, exit code and, with --plot, the figure's bytes."""

    text: str
    exit_code: int
    plot: bytes | None = None
    figure: bytes | None = None  # the sheet's motion plot (PDF), written beside it


@dataclass(frozen=True)
class _Refused:
    """A spec that could not be solved: bad input, unreadable, or over the budget."""

    errors: tuple[ErrorReport, ...]


_Outcome = TypeVar("_Outcome")
BLOCK_SECONDS = 5.0  # symbolic solve of one nonlinear block, before the numeric fallback
TimeBudget = Annotated[
    float,
    typer.Option(
        "--time-budget",
        min=0.1,
        max=3600,
        help="CPU seconds the whole run may take: parsing, solving, checks and output.",
    ),
]
MemoryBudget = Annotated[
    int,
    typer.Option(
        "--memory-budget",
        min=64,
        max=1 << 20,
        help="Megabytes of memory the run may use (not enforced on Windows).",
    ),
]

app = typer.Typer(
    help="Solve and check engineering-dynamics problems written as plain-text .dyn specs.",
    no_args_is_help=True,
    add_completion=True,
    context_settings={"help_option_names": ["-h", "--help"]},
)
stdout = Console(highlight=False)
stderr = Console(stderr=True, highlight=False)
CHECK_PROGRESS_THRESHOLD = 8  # show a progress bar from this many files on
STDIN_NAME = "<stdin>"
INTERRUPTED = 130  # the shell's code for a run stopped by Ctrl-C (128 + SIGINT)


def _version(value: bool) -> None:
    if value:
        from dynsolve import __version__

        stdout.print(f"dynsolve {__version__}")
        raise typer.Exit()


@app.callback()
def main_callback(
    version: Annotated[
        bool,
        typer.Option(
            "--version", callback=_version, is_eager=True, help="Show the version.", metavar=""
        ),
    ] = False,
) -> None:
    """Solve and check engineering-dynamics problems written as plain-text .dyn specs.

    Write the problem in the spec language (docs/spec-language.md), then
    `dynsolve solve FILE` prints a unit-checked derivation, and
    `dynsolve check PATH...` compares every spec with its answer key.
    """


@app.command()
def solve(
    file: Annotated[
        str,
        typer.Argument(
            help="The .dyn spec to solve ('-' reads it from stdin).",
            show_default=False,
            metavar="FILE",
        ),
    ],
    format: Annotated[
        OutputFormat | None,
        typer.Option(
            "--format",
            "-f",
            help="Output format \\[default: text, or from the -o file's suffix: "
            ".json, .md, .tex, .pdf (compiled with pdflatex), .html (one self-contained page)].",
            show_default=False,
        ),
    ] = None,
    output: Annotated[
        Path | None,
        typer.Option(
            "--output", "-o", help="Write to this file instead of the terminal.", metavar="FILE"
        ),
    ] = None,
    mode: Annotated[
        Mode,
        typer.Option(
            help="exact: rationals and formulas; numeric: floating point; auto: numeric, "
            "escalated to exact when float64 would lose more than 3 digits."
        ),
    ] = Mode.exact,
    handout: Annotated[
        bool,
        typer.Option(
            "--handout",
            metavar="",
            help="LaTeX/Markdown/PDF/HTML: the sheet a teacher hands out (no answer key, checks "
            "or file name).",
        ),
    ] = False,
    key: Annotated[
        bool,
        typer.Option(
            "--key",
            help="LaTeX/Markdown/PDF/HTML: only the answers, the key and checks.",
            metavar="",
        ),
    ] = False,
    cite: Annotated[
        bool,
        typer.Option(
            "--source",
            metavar="",
            help="With --handout: print the spec's source: line under the title (the full "
            "sheet and the key always do; it may give the answer away).",
        ),
    ] = False,
    time_budget: TimeBudget = DEFAULT_SECONDS,
    memory_budget: MemoryBudget = DEFAULT_MEGABYTES,
    variant: Annotated[
        str | None,
        typer.Option(
            help="Solve this student's variant (with --variants).",
            show_default=False,
            metavar="STUDENT",
        ),
    ] = None,
    variants: Annotated[
        Path | None,
        typer.Option(
            help="The variants file written by 'dynsolve variants'.",
            show_default=False,
            metavar="FILE",
        ),
    ] = None,
    plot: Annotated[
        Path | None,
        typer.Option(
            help="Also draw the motion of a kinematics: section (x, v, a against t, or the "
            "path) to FILE: .png, .svg or .pdf.",
            show_default=False,
            metavar="FILE",
        ),
    ] = None,
) -> None:
    """Solve one spec and show its unit-checked derivation.

    Shows the givens, each equation with its unit check, the solve order, the
    answers to 3 significant figures and the checks. Exit code 0 when every check
    and answer passes, 1 when one fails, 2 for bad input or past the time or
    memory budget (the whole run: parsing, solving, checks and output).
    """
    chosen = format or _format_of(output)
    if handout and key:
        _fail("--handout and --key are two different sheets", "choose one of them")
    layout = "handout" if handout else "key" if key else "full"
    if output is not None and file != "-":
        _refuse_overwriting_input(Path(file), output)
    elif output is not None:
        _refuse_unwritable(output)
    if plot is not None:
        _check_plot_path(plot, file)
    source = _read_stdin(chosen) if file == "-" else ("file", file)
    cells = _variant_cells(variant, variants)
    budget = Budget(time_budget, memory_budget)
    width, terminal, colours = stdout.width, stdout.is_terminal, stdout.color_system
    # to a terminal in text, rich renders for the terminal's width and colours (in the worker)
    rendered = "latex" if chosen == OutputFormat.pdf else chosen.value
    suffix = plot.suffix.lower() if plot is not None else ""
    figure = _sheet_figure(output, chosen, layout)
    target = _Target(
        rendered, output is None, width, terminal, colours, layout, cite or None, suffix, figure
    )
    job = (source, mode.value, budget, target, cells)
    outcome = _in_worker(solve_and_render, job, budget)
    if isinstance(outcome, _Refused):
        _report(outcome.errors, chosen)
        raise typer.Exit(ExitCode.BAD_INPUT)
    if output is None:
        stdout.file.write(outcome.text)
        stdout.file.flush()
    elif chosen == OutputFormat.pdf:
        _write_pdf(output, outcome.text, {figure: outcome.figure} if outcome.figure else None)
    else:
        if outcome.figure is not None:  # the sheet's motion plot, beside it
            _write_output(output.parent / figure, outcome.figure)
        _write_output(output, outcome.text)
    if plot is not None and outcome.plot is not None:
        _write_output(plot, outcome.plot)
    raise typer.Exit(outcome.exit_code)


def _sheet_figure(output: Path | None, chosen: OutputFormat, layout: str) -> str:
    """The file name of the motion plot a LaTeX or PDF sheet includes (beside a .tex as
    STEM-motion.pdf), for a kinematics spec; "" where there is no sheet file to go with.

    >>> _sheet_figure(Path("out/sheet.tex"), OutputFormat.latex, "full")
    'sheet-motion.pdf'
    >>> _sheet_figure(None, OutputFormat.latex, "full")
    ''
    >>> _sheet_figure(Path("a.tex"), OutputFormat.latex, "key")
    ''
    """
    if output is None or layout == "key":
        return ""
    if chosen == OutputFormat.latex:
        return f"{output.stem}-motion.pdf"
    return "motion.pdf" if chosen == OutputFormat.pdf else ""


def _check_plot_path(plot: Path, file: str) -> None:
    from dynsolve.plots import FORMATS

    if plot.suffix.lower() not in FORMATS:
        _fail(f"cannot write {plot}: use {', '.join(FORMATS)}", "choose another name")
    if file != "-":
        _refuse_overwriting_input(Path(file), plot)


@app.command()
def check(
    paths: Annotated[
        list[Path],
        typer.Argument(
            help="Spec files or folders (searched for *.dyn).",
            show_default=False,
            metavar="PATH...",
        ),
    ],
    mode: Annotated[Mode, typer.Option(help="Solve mode for every spec.")] = Mode.exact,
    time_budget: TimeBudget = DEFAULT_SECONDS,
    memory_budget: MemoryBudget = DEFAULT_MEGABYTES,
    report_format: Annotated[
        CheckFormat,
        typer.Option("--format", help="text (a table), json or junit (XML for CI) on stdout."),
    ] = CheckFormat.text,
    verbose: Annotated[
        bool, typer.Option("--verbose", "-v", help="List the passing files too.")
    ] = False,
) -> None:
    """Solve every .dyn spec under PATHS and compare it with its answer key.

    Prints a table of the failures, each with its reason, and ends with 'N passed,
    M failed' (then ', K malformed' when specs could not be solved: bad syntax or
    units, unreadable, not a regular file, over the budget). Each spec gets the
    whole time and memory budget. Exit code 0 only when all pass; 1 when an answer
    or check fails; 2 when a spec is malformed.
    """
    from dynsolve.budget import run_each
    from dynsolve.render.check_report import FileOutcome, check_json, check_junit
    from dynsolve.render.terminal import failures_table

    files = _collect(paths)
    budget = Budget(time_budget, memory_budget)
    failures: list[tuple[str, object]] = []
    reports: list[FileOutcome] = []
    passed = failed = malformed = 0
    jobs = [(file, mode.value, budget) for file in files]
    outcomes = run_each(solve_and_check, jobs, budget)
    for file, result in zip(files, _progress(outcomes, len(files)), strict=True):
        outcome = _refused_if_stopped(result)
        if isinstance(outcome, _Refused):
            failures.extend((str(file), error.text) for error in outcome.errors)
            reports.append(
                FileOutcome(
                    str(file), "malformed", tuple(("input", e.text) for e in outcome.errors)
                )
            )
            malformed += 1
        elif outcome:
            failures.extend((str(file), check) for check in outcome)
            reports.append(
                FileOutcome(str(file), "failed", tuple((c.name, c.detail) for c in outcome))
            )
            failed += 1
        else:
            reports.append(FileOutcome(str(file), "passed", ()))
            passed += 1
    worst = ExitCode.BAD_INPUT if malformed else ExitCode.FAILED if failed else ExitCode.OK
    if report_format != CheckFormat.text:
        render = check_json if report_format == CheckFormat.json else check_junit
        stdout.out(render(reports), highlight=False)
        raise typer.Exit(worst)
    if verbose:
        for report in reports:
            if report.status == "passed":
                stdout.out(f"passed  {report.file}", highlight=False)
    if failures:
        stdout.print(failures_table(failures))  # type: ignore[arg-type]
    summary = f"{passed} passed, {failed} failed" + (
        f", {malformed} malformed" if malformed else ""
    )
    stdout.print(summary)
    raise typer.Exit(worst)


@app.command()
def grade(
    problem: Annotated[Path, typer.Argument(help="The .dyn problem.", show_default=False)],
    answers: Annotated[
        Path,
        typer.Argument(help="CSV: a student column, one column per find.", show_default=False),
    ],
    output: Annotated[
        Path | None, typer.Option("--output", "-o", help="Per-student report (CSV).")
    ] = None,
    json_report: Annotated[
        Path | None, typer.Option("--json", help="The whole report as JSON.")
    ] = None,
    gradebook: Annotated[
        Path | None,
        typer.Option("--gradebook", help="Gradebook CSV: student,score,points,max_points."),
    ] = None,
    histogram: Annotated[
        Path | None, typer.Option("--histogram", help="Score histogram (.png or .svg).")
    ] = None,
    variants: Annotated[
        Path | None, typer.Option("--variants", help="Each student's givens (dynsolve variants).")
    ] = None,
    rtol: Annotated[
        str | None, typer.Option("--rtol", help="Relative tolerance: '1%' or 0.01.")
    ] = None,
    atol: Annotated[
        str | None, typer.Option("--atol", help="Absolute tolerance with a unit: '0.01 m/s'.")
    ] = None,
    sigfig: Annotated[
        int | None,
        typer.Option("--sigfig", min=1, max=15, help="Grade to N significant figures."),
    ] = None,
    decdig: Annotated[
        int | None, typer.Option("--decdig", min=0, max=15, help="Grade to N decimal digits.")
    ] = None,
    partial: Annotated[
        str | None,
        typer.Option(
            "--partial",
            help="Credit for a right value with a wrong sign or too few figures: '50%'.",
        ),
    ] = None,
    resume: Annotated[
        bool, typer.Option("--resume", help="Continue a killed run from its journal.")
    ] = False,
    fresh: Annotated[
        bool, typer.Option("--fresh", help="Start over, discarding a killed run's journal.")
    ] = False,
    diagnose: Annotated[
        bool, typer.Option("--diagnose/--no-diagnose", help="Name the classic mistakes.")
    ] = True,
) -> None:
    """Grade a class's answers to PROBLEM: scores, verdicts and feedback per student.

    Each cell is a number with a unit ('11.3 rad/s^2', '4.52 m/s^2 down', '23.8 lb') or a
    bare number in the column header's unit ('alpha \\[rad/s^2]'). Rules come from the
    spec's grading: section and these options (docs/grading.md). Prints the class
    summary; exit code 0 when every student was graded, 1 when some could not be (no
    variant, no key), 2 on bad input, 130 when interrupted (rerun with --resume).
    """
    from dynsolve.errors import DynsolveError
    from dynsolve.grade.command import GradeRequest
    from dynsolve.grade.command import grade as grade_answers
    from dynsolve.grade.semantics import Rule
    from dynsolve.render.grade_summary import summary_renderables

    outputs = [p for p in (output, json_report, gradebook, histogram) if p is not None]
    for path in outputs:
        if path.suffix.lower() in (".dyn",) or any(
            path.exists() and i.exists() and path.resolve() == i.resolve()
            for i in (problem, answers, variants)
            if i is not None
        ):
            _fail(f"refusing to write {path}: it is an input file", "choose another path")
        _refuse_unwritable(path)
    if histogram is not None and histogram.suffix.lower() not in (".png", ".svg"):
        _fail(f"--histogram {histogram}: write .png or .svg", "e.g. --histogram scores.png")
    overrides = Rule(
        rtol=_fraction_option("--rtol", rtol) if rtol else Rule().rtol,
        sigfig=sigfig or 0,
        decdig=decdig or 0,
        partial=_fraction_option("--partial", partial) if partial else 0.0,
    )
    request = GradeRequest(
        problem, answers, output, json_report, gradebook, histogram, variants, overrides,
        atol or "", resume, diagnose, fresh,
    )  # fmt: skip
    if resume and fresh:
        _fail("--resume and --fresh exclude each other", "keep the rows (--resume) or not")
    try:
        run = _with_progress(lambda progress: grade_answers(request, progress))
    except DynsolveError as error:
        _fail_with(error)
    except KeyboardInterrupt:
        _interrupted(request)
    for warning in run.warnings:
        stderr.out(f"warning: {warning}", highlight=False)
    for renderable in summary_renderables(run.results, run.title):
        stdout.print(renderable)
    stdout.out(f"keys: {run.path}", highlight=False)
    for path in run.written:
        stderr.out(f"wrote {path}", highlight=False)
    if run.ungraded:
        shown = ", ".join(run.ungraded[:10]) + (" ..." if len(run.ungraded) > 10 else "")
        stderr.out(f"not graded (no variant or no key): {shown}", highlight=False)
        raise typer.Exit(ExitCode.FAILED)
    raise typer.Exit(ExitCode.OK)


def _interrupted(request: GradeRequest) -> NoReturn:
    """Ctrl-C: say what was kept and how to finish, exit 130."""
    from dynsolve.grade.command import check_outputs
    from dynsolve.grade.journal import journal_path

    anchor = check_outputs(request)
    journal = journal_path(anchor) if anchor is not None else None
    if journal is not None and journal.exists():
        stderr.out(
            f"interrupted: the rows graded so far are kept in {journal}; rerun the same "
            "command with --resume to grade the rest",
            highlight=False,
        )
    else:
        stderr.out("interrupted: nothing was kept; rerun the same command", highlight=False)
    raise typer.Exit(INTERRUPTED)


def _fraction_option(option: str, text: str) -> float:
    """'1%' or '0.01' as a fraction; anything else stops with a hint."""
    import re

    match = re.fullmatch(r"\s*(\d+(?:\.\d*)?|\.\d+)\s*(%?)\s*", text)
    if match is None:
        _fail(f"{option} {text}: not a number or percentage", f"e.g. {option} 1%")
    assert match is not None
    value = float(match[1]) / (100 if match[2] else 1)
    if value > 1:
        _fail(f"{option} {text}: more than 100 %", f"e.g. {option} 1%")
    return value


def _with_progress(work: Callable[[Callable[[int, int], None]], _Outcome]) -> _Outcome:
    """Run ``work`` with a progress callback: a rich bar on a terminal's stderr."""
    if not stderr.is_terminal:
        return work(lambda done, total: None)
    from rich.progress import Progress

    with Progress(console=stderr, transient=True) as bar:
        task = bar.add_task("grading", total=None)

        def advance(done: int, total: int) -> None:
            if done % 50 == 0 or done == total:
                bar.update(task, completed=done, total=total)

        return work(advance)


class Method(enum.StrEnum):
    """solve_ivp methods offered by ``dynsolve simulate``."""

    RK45 = "RK45"
    DOP853 = "DOP853"
    Radau = "Radau"
    LSODA = "LSODA"


@app.command()
def simulate(
    file: Annotated[Path, typer.Argument(help="The .dyn spec with a scene.", show_default=False)],
    until: Annotated[
        str | None,
        typer.Option(
            help="Stop at an event: max, min, 'theta(B) = 0 deg', 'x(B) = 0 m', … "
            "'slack(CORD)' (a cord's tension falls to zero), 'lost(PATH)' (a particle "
            "leaves its circular path: N = 0); a chain: 'theta(BAR) = …', 'y(JOINT) = …'. "
            "Default: the event of the scene's 'travel B: until …' line."
        ),
    ] = None,
    t_end: Annotated[str, typer.Option("--t-end", help="The end time, e.g. '10 s'.")] = "10 s",
    method: Annotated[Method, typer.Option(help="solve_ivp's method.")] = Method.DOP853,
    rtol: Annotated[float, typer.Option(min=1e-14, max=0.1, help="Relative tolerance.")] = 1e-10,
    atol: Annotated[float, typer.Option(min=1e-16, max=1.0, help="Absolute tolerance.")] = 1e-12,
    samples: Annotated[int, typer.Option(min=2, max=1_000_000, help="Output samples.")] = 501,
    output: Annotated[
        Path | None,
        typer.Option("--output", "-o", help="Write the history: .csv or .json.", metavar="FILE"),
    ] = None,
    plot: Annotated[
        Path | None, typer.Option(help="Plot q(t) and the energy: .png, .pdf or .svg.")
    ] = None,
    time_budget: TimeBudget = DEFAULT_SECONDS,
    memory_budget: MemoryBudget = DEFAULT_MEGABYTES,
) -> None:
    """Integrate a scene's motion in time from its state (one coordinate, or a chain of bars).

    Prints the events met (turning points, the --until event), the period of an
    oscillation beside the small-oscillation period, and the drift of T + V − U_f.
    A particle on a circular path adds its normal force N to the history, and
    --until 'lost(PATH)' reports the time, angle and speed where N falls to zero.
    Exit code 0 when simulated, 2 for bad input, a scene it cannot simulate, or an
    --until event not met by the end time (the history is still written).
    """
    for path, suffixes in ((output, (".csv", ".json")), (plot, (".png", ".pdf", ".svg"))):
        if path is not None and path.suffix.lower() not in suffixes:
            _fail(f"cannot write {path}: use {' or '.join(suffixes)}", "choose another name")
        if path is not None:
            _refuse_overwriting_input(file, path)
    options = (until, t_end, method.value, rtol, atol, samples)
    suffixes = (
        output.suffix.lower() if output is not None else "",
        plot.suffix.lower() if plot is not None else "",
    )
    budget = Budget(time_budget, memory_budget)
    outcome = _in_worker(simulate_and_render, (str(file), options, suffixes), budget)
    if isinstance(outcome, _Refused):
        _report(outcome.errors, OutputFormat.text)
        raise typer.Exit(ExitCode.BAD_INPUT)
    stdout.print(outcome.text, markup=False, soft_wrap=True)
    if output is not None and outcome.history is not None:
        _write_output(output, outcome.history)
    if plot is not None and outcome.plot is not None:
        _write_output(plot, outcome.plot)
    if outcome.missed:
        _fail(outcome.missed, "check the start state, or give a longer --t-end")
    raise typer.Exit(ExitCode.OK)


@dataclass(frozen=True)
class _Simulated:
    """A simulation's summary text, its history (CSV or JSON text) and plot, and the
    --until event it missed ("" when met or not asked)."""

    text: str
    history: str | None
    plot: bytes | None
    missed: str


def simulate_and_render(
    file: str, options: tuple, suffixes: tuple[str, str]
) -> _Simulated | _Refused:
    """The worker's job for ``simulate``: integrate the spec's scene and render the summary,
    the history (``suffixes[0]``: .csv or .json) and the plot (``suffixes[1]``), under the
    run's budget like a solve."""
    from dynsolve.errors import DynsolveError
    from dynsolve.simulate.output import history_csv, history_json, history_plot
    from dynsolve.simulate.run import parse_quantity, simulate_spec
    from dynsolve.spec.parser import parse_file
    from dynsolve.units import Dim

    until, t_end, method, rtol, atol, samples = options
    try:
        spec = parse_file(file)
        end = parse_quantity(t_end, Dim(0, 0, 1), spec.system, "--t-end")
        history = simulate_spec(spec, until, end, method, rtol, atol, samples)
    except DynsolveError as error:
        return _Refused(_reports(error))
    written = None
    if suffixes[0]:
        written = history_json(history) if suffixes[0] == ".json" else history_csv(history)
    picture = history_plot(history, suffixes[1]) if suffixes[1] else None
    return _Simulated(_simulation_text(history), written, picture, getattr(history, "missed", ""))


def _simulation_text(history: object) -> str:
    """The simulation's summary as lines of text."""
    from dynsolve.simulate.output import summary

    data = summary(history)  # type: ignore[arg-type]
    unit = "rad" if history.motion.unit == "rad" else history.columns()[1][3:-1]  # type: ignore[attr-defined]
    lines = [
        f"{data['problem']}: simulated in q = {data['coordinate']} [{unit}]",
        f"  solve_ivp {data['method']}, rtol {data['rtol']:.0e}, atol {data['atol']:.0e}: "
        f"t = 0 … {data['t_end']:.6g} s, {data['evaluations']} evaluations"
        + (f", stopped by '{data['stopped_by']}'" if data["stopped_by"] else ""),
    ]
    for event in data["events"][:20]:  # type: ignore[index]
        lines.append(
            f"  {event['event']:<12} t = {event['t']:.9g} s  q = {event['q']:.9g}  "
            f"q' = {event['q_dot']:.6g}"
        )
    if len(data["events"]) > 20:  # type: ignore[arg-type]
        lines.append(f"  … {len(data['events']) - 20} more events")  # type: ignore[arg-type]
    if data["period"] is not None:
        lines.append(f"  period (turning points): {data['period']:.9g} s")
    if data["small_oscillation_period"] is not None:
        lines.append(
            f"  small-oscillation period 2π√(M/V'') about q* = {data['equilibrium']:.6g}: "
            f"{data['small_oscillation_period']:.9g} s"
        )
    constant = data.get("constant_acceleration")
    if constant is not None:
        lines.append(
            f"  constant q'' = {constant['q_ddot']:.9g}: closed form q = q'₀ t + ½ q'' t², "  # type: ignore[index]
            f"largest difference {constant['difference']:.2e} of the largest |q|"  # type: ignore[index]
        )
    lines += _contact_lines(history, data)
    invariant = str(data["invariant"]).replace(" - ", " − ").replace("Omega", "Ω")
    lines.append(f"  energy drift |Δ({invariant})|/scale: {data['energy_drift']:.2e}")
    return "\n".join(lines)


def _contact_lines(history: object, data: dict) -> list[str]:
    """Where a particle left its circular path (or that the path pushed the other way)."""
    contact = data.get("contact")
    if not contact:
        return []
    length = "ft" if getattr(history, "system", "SI") == "FPS" else "m"
    lost = contact["lost"]
    if lost is not None:
        top = lost["angle_from_top_deg"]
        rise = lost["rise"]
        return [
            f"  contact with {contact['path']} lost ({contact['force']} = 0, {contact['side']} "
            f"the circle): t = {lost['t']:.9g} s, turned {lost['angle_turned_deg']:.7g}°"
            + (f", {top:.7g}° from the top" if top is not None else "")
            + f", speed {lost['speed']:.7g} {length}/s"
            + (f", G rose {rise:.7g} {length}" if rise is not None else "")
        ]
    flips = [e for e in data["events"] if e["event"] == f"{contact['force']} = 0"]
    if not flips:
        return []
    return [
        f"  note: {contact['force']} changes sign at t = {flips[0]['t']:.9g} s: a surface lets "
        f"go there (--until 'lost({contact['path']})'); past it the run holds "
        f"{contact['body']} on {contact['path']} as a bead on a wire"
    ]


class UnitsChoice(enum.StrEnum):
    """Units of the variants: as drawn (si), US customary twins (us), or both."""

    si = "si"
    us = "us"
    both = "both"


@app.command("sweep")
def sweep_command(
    file: Annotated[
        Path, typer.Argument(help="The .dyn spec.", show_default=False, metavar="FILE")
    ],
    ranges: Annotated[
        list[str],
        typer.Argument(
            help="Ranges in the vary: grammar: 'm_b=10..30 kg', 'm_b=10..30 kg step 0.5', "
            "'k=±10%'. Two ranges give a grid.",
            show_default=False,
            metavar="RANGE...",
        ),
    ],
    points: Annotated[
        int | None,
        typer.Option(
            min=2, max=1_000_000, help="Points of a range without a step (default 51).", metavar="N"
        ),
    ] = None,
    output: Annotated[
        Path | None,
        typer.Option("--output", "-o", help="Write the table: .csv or .json.", metavar="FILE"),
    ] = None,
    plot: Annotated[
        Path | None,
        typer.Option(
            help="Plot the answers (contours over two givens): .png, .svg or .pdf.",
            metavar="FILE",
        ),
    ] = None,
    answers: Annotated[
        str | None,
        typer.Option(help="Only these finds, comma-separated: 'alpha,T'.", metavar="NAMES"),
    ] = None,
    mode: Annotated[Mode, typer.Option(help="Solve mode of the full solves.")] = Mode.exact,
    time_budget: TimeBudget = DEFAULT_SECONDS,
    memory_budget: MemoryBudget = DEFAULT_MEGABYTES,
) -> None:
    """Sweep givens over ranges and tabulate every answer at every point (docs/sweep.md).

    Answers come from the problem's closed form where it has one (one per regime: the
    no-slip check fails and the point is solved slipping, ...), from a full solve per point
    elsewhere; the table's path and regime columns say which. Exit code 0 when swept, 2
    for bad input or past the time or memory budget.
    """
    from dynsolve.errors import DynsolveError
    from dynsolve.parametric.command import TABLE_FORMATS, SweepRequest, parse_answers
    from dynsolve.parametric.terminal import sweep_renderables
    from dynsolve.plots import FORMATS

    for path, suffixes in ((output, TABLE_FORMATS), (plot, FORMATS)):
        if path is not None and path.suffix.lower() not in suffixes:
            _fail(f"cannot write {path}: use {' or '.join(suffixes)}", "choose another name")
        if path is not None:
            _refuse_overwriting_input(file, path)
    try:
        names = parse_answers(answers) if answers is not None else None
    except DynsolveError as error:
        _report(_reports(error, ("text", answers or "")))
        raise typer.Exit(ExitCode.BAD_INPUT) from None
    suffixes = (output.suffix.lower() if output else "", plot.suffix.lower() if plot else "")
    request = SweepRequest(str(file), tuple(ranges), points, names, *suffixes)
    budget = Budget(time_budget, memory_budget)
    outcome = _in_worker(sweep_in_worker, (request, answers or "", mode.value, budget), budget)
    if isinstance(outcome, _Refused):
        _report(outcome.errors)
        raise typer.Exit(ExitCode.BAD_INPUT)
    for renderable in sweep_renderables(outcome.result):
        stdout.print(renderable)
    if output is not None:
        _write_output(output, outcome.table)
    if plot is not None and outcome.plot is not None:
        _write_output(plot, outcome.plot)
    raise typer.Exit(ExitCode.OK)


def sweep_in_worker(
    request: SweepRequest, answers: str, mode: str, budget: Budget
) -> SweepOutput | _Refused:
    """The worker's job for ``sweep``: every point answered, the table and plot made."""
    from dynsolve.startup import import_solver

    import_solver()
    from dynsolve.errors import DynsolveError
    from dynsolve.parametric.command import input_text, sweep_job

    try:
        return sweep_job(request, _options(mode, budget), budget.seconds)
    except DynsolveError as error:
        text = input_text(error, request.ranges, answers)
        return _Refused(
            _reports(error, ("text", text) if text is not None else ("file", request.spec))
        )


@app.command("variants")
def variants_command(
    file: Annotated[
        Path, typer.Argument(help="The .dyn spec with a vary: section.", metavar="FILE")
    ],
    roster: Annotated[
        Path, typer.Option(help="CSV of students (column student or id).", metavar="FILE")
    ],
    seed: Annotated[
        int, typer.Option(help="Seed: the same seed draws the same variants.", metavar="N")
    ],
    output: Annotated[
        Path, typer.Option("--output", "-o", help="The variants CSV to write.", metavar="FILE")
    ],
    units: Annotated[
        UnitsChoice, typer.Option(help="si: as drawn; us: US customary; both: a twin row each.")
    ] = UnitsChoice.si,
    mode: Annotated[Mode, typer.Option(help="Solve mode for each variant.")] = Mode.exact,
) -> None:
    """Draw each student's givens from the spec's vary: ranges; solve and check each.

    A variant whose assumptions (no slip, contact kept, ...) or checks come out
    otherwise than the base problem's is redrawn (unless vary: says 'allow
    changes'). Reproducible: a student's variant depends only on the seed and
    their id. Exit code 0 when written, 2 for bad input (docs/grading.md).
    """
    from dynsolve.errors import DynsolveError
    from dynsolve.grade.generate import make_variants
    from dynsolve.grade.variants import read_roster, write_variants
    from dynsolve.spec.parser import parse_file
    from dynsolve.system import SolveOptions

    _refuse_overwriting_input(file, output)
    if output.exists() and roster.exists() and output.resolve() == roster.resolve():
        _fail(f"refusing to write the variants over the roster {roster}", "choose another -o")
    try:
        spec = parse_file(file)
        students = read_roster(roster)
        with _counter(len(students)) as advance:
            rows = make_variants(
                spec, students, seed, units.value, SolveOptions(mode=mode.value), advance
            )
        names = list(dict.fromkeys(n for row in rows for n in row.cells))
        write_variants(output, rows, names)
    except DynsolveError as error:
        _report(_reports(error, _where(error)))
        raise typer.Exit(ExitCode.BAD_INPUT) from None
    stderr.print(f"wrote {output}: {len(rows)} variants of {len(students)} students")


export_app = typer.Typer(
    help="Write grades and quizzes in the formats courses use (docs/grading.md).",
    no_args_is_help=True,
    context_settings={"help_option_names": ["-h", "--help"]},
)
app.add_typer(export_app, name="export")
Force = Annotated[bool, typer.Option("--force", help="Replace a non-empty output file or folder.")]
Points = Annotated[
    float | None,
    typer.Option(
        "--points",
        min=0.01,
        metavar="N",
        help="Scale every total to N points (default: out of the sum of the weights).",
    ),
]
GradebookFile = Annotated[
    Path,
    typer.Argument(
        help="The gradebook CSV of 'dynsolve grade --gradebook' (student,score,points,max_points).",
        show_default=False,
        metavar="GRADEBOOK",
    ),
]
OutputFile = Annotated[
    Path, typer.Option("--output", "-o", help="The file to write.", metavar="FILE")
]


class CanvasId(enum.StrEnum):
    """The Canvas column that holds the student ids of the answers file (without --roster)."""

    sis_user_id = "sis-user-id"
    sis_login_id = "sis-login-id"
    canvas_id = "canvas-id"


CANVAS_COLUMNS = {"sis-user-id": "SIS User ID", "sis-login-id": "SIS Login ID", "canvas-id": "ID"}


@export_app.command("canvas")
def export_canvas(
    gradebook: GradebookFile,
    output: OutputFile,
    assignment: Annotated[
        str,
        typer.Option(
            metavar="NAME",
            help="The assignment column: 'Name (12345)' with the Canvas assignment id updates "
            "that assignment; a new name creates one.",
        ),
    ],
    points: Points = None,
    roster: Annotated[
        Path | None,
        typer.Option(
            metavar="FILE",
            help="Canvas's own gradebook export: ids matched against its ID, SIS User ID and "
            "SIS Login ID; names and sections copied.",
        ),
    ] = None,
    id_column: Annotated[
        CanvasId, typer.Option(help="Without --roster: the Canvas column the ids go in.")
    ] = CanvasId.sis_user_id,
    force: Force = False,
) -> None:
    """Write the graded class as a Canvas gradebook import (Grades > Import).

    Columns Student, ID, SIS User ID, SIS Login ID, Section and the assignment, after a
    Points Possible row. Every cell is escaped against formula injection.
    """
    from dynsolve.grade.export.command import GradebookRequest

    column = CANVAS_COLUMNS[id_column.value]
    request = GradebookRequest(
        gradebook, output, "canvas", assignment, points, roster, column, force
    )
    _export_gradebook(request)


@export_app.command("scores")
def export_scores(
    gradebook: GradebookFile, output: OutputFile, points: Points = None, force: Force = False
) -> None:
    """Write the graded class as SID,Total Score,Max Points for Gradescope or Moodle.

    Moodle (Grades > Import > CSV file): map SID to the ID number and Total Score to the
    grade item. Every cell is escaped against formula injection.
    """
    from dynsolve.grade.export.command import GradebookRequest

    _export_gradebook(GradebookRequest(gradebook, output, "scores", "", points, None, "", force))


def _export_gradebook(request: GradebookRequest) -> None:
    from dynsolve.errors import DynsolveError
    from dynsolve.grade.export.command import export_gradebook

    try:
        count = export_gradebook(request)
    except DynsolveError as error:
        _report(_reports(error, _where(error)))
        raise typer.Exit(ExitCode.BAD_INPUT) from None
    stderr.out(f"wrote {request.output}: {count} students", highlight=False)


QuizProblem = Annotated[
    Path, typer.Argument(help="The .dyn problem.", metavar="PROBLEM", show_default=False)
]
QuizVariants = Annotated[
    Path | None,
    typer.Option(
        metavar="FILE",
        help="Each student's givens (dynsolve variants); default: the problem as written.",
    ),
]
QuizRtol = Annotated[
    str | None, typer.Option("--rtol", help="Relative tolerance: '1%' or 0.01.", metavar="TOL")
]
QuizAtol = Annotated[
    str | None,
    typer.Option(
        "--atol",
        metavar="QUANTITY",
        help="Absolute tolerance with a unit ('0.01 m/s'), for the parts of its dimension.",
    ),
]
QuizSigfig = Annotated[
    int | None,
    typer.Option("--sigfig", min=1, max=15, metavar="N", help="Grade to N significant figures."),
]
QuizDecdig = Annotated[
    int | None,
    typer.Option("--decdig", min=0, max=15, metavar="N", help="Grade to N decimal digits."),
]


@export_app.command("moodle-xml")
def export_moodle(
    problem: QuizProblem,
    output: OutputFile,
    variants: QuizVariants = None,
    category: Annotated[
        str,
        typer.Option(metavar="PATH", help="Question bank category (default: dynsolve/TITLE)."),
    ] = "",
    calculated: Annotated[
        bool,
        typer.Option(
            "--calculated",
            help="One calculated question per part whose dataset items are the variants "
            "(Moodle draws one per attempt), instead of a numerical question per student.",
        ),
    ] = False,
    rtol: QuizRtol = None,
    atol: QuizAtol = None,
    sigfig: QuizSigfig = None,
    decdig: QuizDecdig = None,
    force: Force = False,
) -> None:
    """Write the variants as a Moodle XML quiz: a numerical question per student and part.

    Each question states the student's givens and has their answer with its unit and
    the tolerance of the part's grading rule (Question bank > Import > Moodle XML).
    """
    from dynsolve.grade.export.command import QuizRequest

    overrides = _quiz_rules(rtol, sigfig, decdig)
    _export_quiz(
        QuizRequest(
            problem, output, "moodle", variants, overrides, atol or "", category, calculated,
            force=force,
        )
    )  # fmt: skip


@export_app.command("prairielearn")
def export_prairielearn(
    problem: QuizProblem,
    output: Annotated[
        Path,
        typer.Option("--output", "-o", help="The question folder to create.", metavar="FOLDER"),
    ],
    variants: QuizVariants = None,
    topic: Annotated[str, typer.Option(help="info.json topic.", metavar="TEXT")] = "Dynamics",
    tag: Annotated[
        list[str] | None, typer.Option(help="An info.json tag (repeatable).", metavar="TEXT")
    ] = None,
    rtol: QuizRtol = None,
    atol: QuizAtol = None,
    sigfig: QuizSigfig = None,
    decdig: QuizDecdig = None,
    force: Force = False,
) -> None:
    """Write the variants as a PrairieLearn question folder.

    info.json, question.html (pl-number-input per part, graded by the part's rule) and
    server.py, whose generate() draws a row of the pre-computed variant table: the
    course server needs no dynsolve.
    """
    from dynsolve.grade.export.command import QuizRequest

    overrides = _quiz_rules(rtol, sigfig, decdig)
    _export_quiz(
        QuizRequest(
            problem, output, "prairielearn", variants, overrides, atol or "", topic=topic,
            tags=tuple(tag or ()), force=force,
        )
    )  # fmt: skip


def _quiz_rules(rtol: str | None, sigfig: int | None, decdig: int | None) -> Rule:
    """The grading options of a quiz export, as overrides of the spec's rules."""
    from dynsolve.grade.semantics import Rule

    return Rule(
        rtol=_fraction_option("--rtol", rtol) if rtol else Rule().rtol,
        sigfig=sigfig or 0,
        decdig=decdig or 0,
    )


def _export_quiz(request: QuizRequest) -> None:
    from dynsolve.errors import DynsolveError
    from dynsolve.grade.export.command import export_quiz

    try:
        table = export_quiz(request)
    except DynsolveError as error:
        _report(_reports(error, _where(error)))
        raise typer.Exit(ExitCode.BAD_INPUT) from None
    for warning in table.warnings:
        stderr.out(f"warning: {warning}", highlight=False)
    count = len(table.variants)
    stderr.out(
        f"wrote {request.output}: {count} variant{'s' * (count != 1)} x {len(table.parts)} parts",
        highlight=False,
    )


def _where(error: Exception) -> tuple[str, str] | None:
    """The file an error points into (a spec, a roster, a variants file), for its line."""
    position = getattr(error, "position", None)
    return ("file", position.file) if position is not None and position.file else None


def _variant_cells(student: str | None, variants: Path | None) -> tuple[str, dict[str, str]] | None:
    """One student's row of a variants file, for ``solve --variant``."""
    if student is None and variants is None:
        return None
    if student is None or variants is None:
        _fail("--variant and --variants go together", "give both, or neither")
    from dynsolve.errors import DynsolveError
    from dynsolve.grade.variants import read_variants

    assert student is not None and variants is not None
    try:
        table = read_variants(variants)
    except DynsolveError as error:
        _report(_reports(error, _where(error)))
        raise typer.Exit(ExitCode.BAD_INPUT) from None
    if student not in table:
        import difflib

        close = difflib.get_close_matches(student, list(table), n=1)
        _fail(
            f"no student '{student}' in {variants}",
            f"did you mean '{close[0]}'?" if close else "check the id",
        )
    return student, table[student]


class _counter:
    """A progress bar on stderr (when it is a terminal) advanced by the callable it yields."""

    def __init__(self, total: int) -> None:
        self.total = total
        self.progress: object = None

    def __enter__(self) -> Callable[[int], None]:
        if self.total < CHECK_PROGRESS_THRESHOLD or not stderr.is_terminal:
            return lambda done: None
        from rich.progress import Progress

        progress = Progress(console=stderr, transient=True)
        progress.start()
        task = progress.add_task("variants", total=self.total)
        self.progress = progress
        return lambda done: progress.update(task, completed=done)

    def __exit__(self, *exc: object) -> None:
        if self.progress is not None:
            self.progress.stop()  # type: ignore[attr-defined]


def _collect(paths: list[Path]) -> list[Path]:
    files: list[Path] = []
    for path in paths:
        if path.is_dir():
            files.extend(sorted(path.rglob("*.dyn")))
        elif path.exists() or path.is_symlink():
            files.append(path)  # reading it says why when it is not a regular file
        else:
            _fail(f"{path}: no such file or folder", "check the path")
    if not files:
        _fail("no .dyn files found", "pass spec files or folders that hold them")
    return files


def _progress(items: Iterator[_Outcome], total: int) -> Iterator[_Outcome]:
    if total < CHECK_PROGRESS_THRESHOLD or not stderr.is_terminal:
        yield from items
        return
    from rich.progress import track

    yield from track(items, total=total, description="checking", console=stderr, transient=True)


def solve_and_render(
    source: tuple[str, str],
    mode: str,
    budget: Budget,
    target: _Target,
    variant: tuple[str, dict[str, str]] | None = None,
) -> _Done | _Refused:
    """The worker's job for ``solve``: solve, check and render one spec (a file's path, or
    stdin's text; or one student's variant of it: their givens replaced, the answer key
    dropped) to text."""
    from dynsolve.startup import import_solver

    import_solver()
    from dynsolve.budget import step
    from dynsolve.errors import DynsolveError
    from dynsolve.pipeline import solve_file, solve_text

    kind, value = source
    try:
        if target.plot:  # refused before the solve, so no derivation is lost
            _figure(source, variant, "")
        if variant is not None:
            from dataclasses import replace

            from dynsolve.grade.substitute import with_variant
            from dynsolve.pipeline import solve_spec
            from dynsolve.spec.parser import parse_file, parse_spec

            spec = parse_file(value) if kind == "file" else parse_spec(value, STDIN_NAME)
            spec = with_variant(spec, variant[1], variant[0])
            spec = replace(spec, title=f"{spec.title} (student {variant[0]})")
            solution = solve_spec(spec, _options(mode, budget))
        elif kind == "file":
            solution = solve_file(value, _options(mode, budget))
        else:
            solution = solve_text(value, STDIN_NAME, _options(mode, budget))
        sheet_figure = _sheet_plot(source, variant) if target.figure else None
        if sheet_figure is not None:
            from dataclasses import replace

            solution = replace(solution, figure=target.figure)
        with step("rendering the output"):
            text = _render(solution, target)
        figure = _figure(source, variant, target.plot) if target.plot else None
    except DynsolveError as error:
        return _Refused(_reports(error, source))
    code = ExitCode.OK if solution.passed else ExitCode.FAILED
    return _Done(text, code, figure, sheet_figure)


def _sheet_plot(
    source: tuple[str, str], variant: tuple[str, dict[str, str]] | None
) -> bytes | None:
    """A kinematics spec's motion plot for its sheet (PDF), or None where there is none."""
    from dynsolve.errors import DynsolveError

    try:
        return _figure(source, variant, ".pdf")
    except DynsolveError:  # not a kinematics spec, or nothing to draw: a sheet without
        return None


def _figure(
    source: tuple[str, str], variant: tuple[str, dict[str, str]] | None, suffix: str
) -> bytes:
    """The --plot figure of a kinematics spec (the worker's part of ``solve --plot``); with
    no ``suffix`` only the check that there is one to draw."""
    from dynsolve.budget import step
    from dynsolve.modes.kinematics_mode import build_kinematics_problem
    from dynsolve.plots import motion_plot, not_plottable
    from dynsolve.spec.parser import parse_file, parse_spec

    kind, value = source
    spec = parse_file(value) if kind == "file" else parse_spec(value, STDIN_NAME)
    if variant is not None:
        from dynsolve.grade.substitute import with_variant

        spec = with_variant(spec, variant[1], variant[0])
    if not spec.kinematics:
        raise not_plottable(spec.file)
    if not suffix:  # only the check
        return b""
    with step("drawing the plot"):
        return motion_plot(build_kinematics_problem(spec), suffix)


def solve_and_check(file: Path, mode: str, budget: Budget) -> tuple[Check, ...] | _Refused:
    """The worker's job for ``check``: the failed checks of one spec (none: it passed)."""
    from dynsolve.startup import import_solver

    import_solver()
    from dynsolve.errors import DynsolveError
    from dynsolve.pipeline import solve_file

    try:
        solution = solve_file(file, _options(mode, budget))
    except DynsolveError as error:
        return _Refused(_reports(error, ("file", str(file))))
    return tuple(c for c in solution.checks if c.failed)


def _options(mode: str, budget: Budget) -> SolveOptions:
    """Solve options whose per-block symbolic budget leaves room for the numeric fallback."""
    from dynsolve.system import SolveOptions

    return SolveOptions(mode=mode, time_budget=min(BLOCK_SECONDS, budget.seconds / 4))


def _render(solution: Solution, target: _Target) -> str:
    from dynsolve.render import renderer

    if target.format != OutputFormat.text or not target.to_terminal:
        return renderer(target.format, target.layout, target.source)(solution)  # type: ignore[arg-type]
    import io

    from dynsolve.render.terminal import solution_renderable

    buffer = io.StringIO()
    console = Console(
        file=buffer,
        width=target.width,
        force_terminal=target.terminal,
        color_system=target.colours,  # type: ignore[arg-type]
        highlight=False,
    )
    console.print(solution_renderable(solution))
    return buffer.getvalue()


def _in_worker(
    job: Callable[..., _Outcome], args: tuple[object, ...], budget: Budget
) -> _Outcome | _Refused:
    """``job(*args)`` in a worker under ``budget``, or the error that stopped it."""
    from dynsolve.budget import run
    from dynsolve.errors import DynsolveError

    try:
        return run(job, args, budget)
    except DynsolveError as error:
        return _Refused(_reports(error))


def _refused_if_stopped(outcome: _Outcome | Exception) -> _Outcome | _Refused:
    """A job's outcome; the reason as _Refused when the budget or a bug stopped it."""
    from dynsolve.errors import DynsolveError, ErrorReport

    if isinstance(outcome, DynsolveError):
        return _Refused(_reports(outcome))
    if isinstance(outcome, Exception):
        last = str(outcome).strip().splitlines()[-1:] or ["no detail"]
        bug = f"internal error (a bug in dynsolve; please report it): {last[0]}"
        return _Refused((ErrorReport(bug),))
    return outcome


def _reports(error: Exception, source: tuple[str, str] | None = None) -> tuple[ErrorReport, ...]:
    """``error`` and the others it carries, each with the spec line it points at."""
    from dynsolve.errors import ErrorReport, all_errors

    text = _spec_text(source) if source is not None else None
    return tuple(ErrorReport.of(each, text) for each in all_errors(error))  # type: ignore[arg-type]


def _spec_text(source: tuple[str, str]) -> str | None:
    """The spec's text, for quoting the line an error points at (None when unreadable)."""
    from dynsolve.files import FileAccessError, read_capped
    from dynsolve.spec.parser import MAX_FILE_BYTES

    kind, value = source
    if kind != "file":
        return value
    try:
        return read_capped(value, MAX_FILE_BYTES).decode("utf-8-sig", errors="replace")
    except FileAccessError:
        return None


def _read_stdin(chosen: OutputFormat) -> tuple[str, str]:
    """("text", the spec read from stdin), byte-capped like a file."""
    import sys

    from dynsolve.errors import ErrorReport, Position, SpecError
    from dynsolve.spec.parser import MAX_FILE_BYTES

    raw = sys.stdin.buffer.read(MAX_FILE_BYTES + 1)
    try:
        if len(raw) > MAX_FILE_BYTES:
            raise SpecError(
                f"{STDIN_NAME} is over {MAX_FILE_BYTES} bytes; specs are limited to that",
                Position(STDIN_NAME, 1, 1),
                hint="split the problem into several files",
            )
        return ("text", raw.decode("utf-8-sig"))
    except UnicodeDecodeError:
        error = SpecError("stdin is not valid UTF-8 text", Position(STDIN_NAME, 1, 1), "send UTF-8")
    except SpecError as exc:
        error = exc
    _report((ErrorReport.of(error),), chosen)
    raise typer.Exit(ExitCode.BAD_INPUT)


def _format_of(output: Path | None) -> OutputFormat:
    """The format an output path's suffix asks for (text when it names none)."""
    if output is None:
        return OutputFormat.text
    return SUFFIX_FORMATS.get(output.suffix.lower(), OutputFormat.text)


def _refuse_overwriting_input(spec: Path, output: Path) -> None:
    same = output.exists() and spec.exists() and output.resolve() == spec.resolve()
    if same or output.suffix.lower() == ".dyn":
        _fail(f"refusing to write output to {output}: it is a spec file", "choose another -o path")
    _refuse_unwritable(output)


def _refuse_unwritable(output: Path) -> None:
    from dynsolve.files import FileAccessError, check_writable

    try:
        check_writable(output)  # before any work: a device, FIFO or /proc file is refused
    except FileAccessError as error:
        _fail_with(error)


def _write_output(output: Path, text: str | bytes) -> None:
    from dynsolve.files import FileAccessError, write_text

    try:
        write_text(output, text)
    except FileAccessError as error:
        _fail_with(error)
    stderr.print(f"wrote {output}", markup=False)


def _write_pdf(output: Path, latex: str, files: dict[str, bytes] | None = None) -> None:
    from dynsolve.errors import DynsolveError
    from dynsolve.pdf import compile_pdf

    try:
        pdf = compile_pdf(latex, files)
    except DynsolveError as error:
        _fail_with(error)
    _write_output(output, pdf)


def _fail(message: str, hint: str) -> None:
    stderr.out(f"error: {message} (hint: {hint})", highlight=False)
    raise typer.Exit(ExitCode.BAD_INPUT)


def _fail_with(error: Exception) -> NoReturn:
    from dynsolve.errors import ErrorReport

    _report((ErrorReport.of(error),))
    raise typer.Exit(ExitCode.BAD_INPUT)


def _report(reports: tuple[ErrorReport, ...], chosen: OutputFormat = OutputFormat.text) -> None:
    """Errors to stderr, each with its source line and caret; as JSON on stdout too for
    ``--format json``."""
    from dynsolve.render.errors import error_text, errors_json

    for report in reports:
        stderr.out(error_text(report), highlight=False)
    if chosen == OutputFormat.json:
        stdout.out(errors_json(reports), highlight=False)


def main() -> None:
    """Console-script entry point."""
    app()
