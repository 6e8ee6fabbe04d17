"""Answer every point of a sweep: a closed form per regime where the answers have one, a full
solve per point elsewhere, and at every point the regime (which assumptions fail there).

The closed form is grading's (:mod:`dynsolve.grade.vectorized`): the problem solved once
with the swept givens as symbols, its answers and the conditions that solve relied on (no
slip, contact kept, cord taut, no tipping, a root's constraint) compiled for numpy. The
points where a condition comes out otherwise than at the spec's own values form another
regime: the problem is solved again at one of them (slipping, say), compiled again, and
those points are evaluated by that form; at most :data:`MAX_REGIMES` forms. Each form is
checked against full solves of a sample of its points (:func:`dynsolve.grade.expected.verify`:
same assumptions, answers within 1e-9). The points no form answers (at a condition's edge,
not finite, a given past the sign its symbol assumes) are solved one by one, as
``dynsolve solve`` solves them.

>>> import numpy as np
>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.parametric.ranges import Axis
>>> text = "given:\\n  m = 2 kg\\n  F = 10 N\\nequations:\\n  F = m*a\\nfind: a"
>>> spec = parse_spec(text, "p.dyn")
>>> axis = Axis("m", "kg", np.array([1.0, 2.0, 5.0]), 1.0)
>>> result = sweep_points(spec, (axis,), (axis.values,), (3,))
>>> result.answers[0].values.tolist(), result.answers[0].unit, result.counts()
([10.0, 5.0, 2.0], 'm/s^2', {'closed form': 3, 'per point': 0})
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np

from dynsolve.budget import step
from dynsolve.errors import DynsolveError, Position, SpecError
from dynsolve.grade.expected import verify
from dynsolve.grade.substitute import with_variant
from dynsolve.grade.vectorized import NotClosedForm, build_closed_form, evaluate_arrays
from dynsolve.parametric.ranges import Axis
from dynsolve.quantities import unit_info
from dynsolve.results import Solution
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions

MAX_REGIMES = 4  # closed forms built for one sweep (each: one symbolic solve, ~0.1-0.5 s)
CLOSED = "closed form"
PER_POINT = "per point"
ANSWERS_FILE = "<--answers>"  # where an error in the --answers list points


@dataclass(frozen=True)
class Answer:
    """One find at every point, in its display unit (as ``dynsolve solve`` shows it): a
    magnitude where a direction is stated, NaN where the point has no value."""

    name: str
    unit: str
    values: np.ndarray
    directions: tuple[str, ...]  # per point ("" where none is stated); () when never


@dataclass(frozen=True)
class Sweep:
    """Every point of a sweep: the swept givens, the answers, the regime and how each point
    was answered. Arrays are flat, one entry per point (a grid in C order: the first
    axis outermost); ``shape`` is the grid's."""

    file: str
    title: str
    axes: tuple[Axis, ...]
    shape: tuple[int, ...]
    givens: Mapping[str, np.ndarray]  # each swept given per point, in its axis's unit
    answers: tuple[Answer, ...]
    regimes: np.ndarray  # per point: "as assumed", "slips at C", "cord T goes slack", …
    paths: np.ndarray  # per point: CLOSED or PER_POINT
    notes: Mapping[int, str]  # point → why it has no answers (its solve failed)
    reasons: tuple[str, ...]  # why points were solved one by one
    build_seconds: float = 0.0  # closed forms: symbolic solves, lambdify, checks
    evaluate_seconds: float = 0.0  # closed forms evaluated at their points
    solve_seconds: float = 0.0  # the full solves, one per point

    @property
    def size(self) -> int:
        """The number of points."""
        return len(self.paths)

    def counts(self) -> dict[str, int]:
        """How many points each path answered."""
        closed = int(np.count_nonzero(self.paths == CLOSED))
        return {CLOSED: closed, PER_POINT: self.size - closed}


def selected(spec: Spec, answers: Sequence[str] | None) -> Spec:
    """``spec`` with only the finds in ``answers`` (all when None) and no answer key (the
    key is for the spec's own values, not a sweep's)."""
    if answers is None:
        return replace(spec, answers=())
    finds = {f.name: f for f in spec.finds}
    column = 1
    for name in answers:
        if name not in finds:
            raise SpecError(
                f"'{name}' is not a find of {spec.file}",
                Position(ANSWERS_FILE, 1, column),
                hint=f"the finds are: {', '.join(finds)}",
            )
        column += len(name) + 1
    return replace(spec, finds=tuple(finds[n] for n in dict.fromkeys(answers)), answers=())


def sweep_points(
    spec: Spec,
    axes: Sequence[Axis],
    columns: Sequence[np.ndarray],
    shape: tuple[int, ...],
    answers: Sequence[str] | None = None,
    options: SolveOptions | None = None,
    vectorize: bool = True,
    deadline: float | None = None,
) -> Sweep:
    """Every point of ``spec`` with its ``axes``' givens set to ``columns`` (one flat array
    per axis, in the axis's unit); ``vectorize=False`` solves every point (the baseline).
    ``deadline`` (a ``time.perf_counter()`` instant) stops the full solves early, with an
    :class:`~dynsolve.budget.OverBudget` that says how long they would take, when the
    first of them show that the rest cannot finish by then."""
    options = options or SolveOptions()
    spec = selected(spec, answers)
    names = tuple(axis.name for axis in axes)
    points = _Points(axes, columns)
    n = len(points)
    base = [column * axis.factor for axis, column in zip(axes, columns, strict=True)]
    state = _State(n)
    remaining = np.arange(n)
    reasons: list[str] = []
    regime_spec = spec
    for _ in range(MAX_REGIMES if vectorize else 0):
        start = time.perf_counter()
        try:
            with step("solving the sweep in closed form"):
                form = build_closed_form(regime_spec, names, options)
        except NotClosedForm as error:
            reasons.append(str(error))
            break
        except DynsolveError as error:
            reasons.append(error.message)
            break
        middle = time.perf_counter()
        batch = evaluate_arrays(form, [column[remaining] for column in base])
        state.evaluate_seconds += time.perf_counter() - middle
        start += time.perf_counter() - middle  # the build's time leaves the evaluation out
        with step("checking the closed form against full solves"):
            labels = _Labels(remaining)
            disagreement = verify(regime_spec, form, batch, labels, points.at(remaining), options)
        regime = regime_words((c.label, c.holds) for c in form.conditions)
        state.build_seconds += time.perf_counter() - start
        if disagreement:
            reasons.append(disagreement.removeprefix("student "))
            break
        accepted = remaining[batch.fast]
        for target in form.targets:
            state.store(target.name, target.unit, accepted, batch.values[target.name][batch.fast])
            state.direct(
                target.name, accepted, np.asarray(batch.directions[target.name])[batch.fast]
            )
        state.paths[accepted] = CLOSED
        state.regimes[accepted] = regime
        flipped = [i for i, why in batch.why_slow.items() if why.endswith((" fails", " holds"))]
        for i, why in batch.why_slow.items():
            state.why[int(remaining[i])] = why
        if not flipped:  # MAX_REGIMES bounds the forms built
            break
        representative = int(remaining[flipped[len(flipped) // 2]])
        remaining = remaining[~batch.fast]
        regime_spec = with_variant(spec, points[representative], "sweep")
    else:
        if vectorize and np.any(state.paths[remaining] != CLOSED):
            reasons.append(f"more than {MAX_REGIMES} regimes")
    todo = np.flatnonzero(state.paths != CLOSED)
    reasons.extend(dict.fromkeys(state.why[int(i)] for i in todo if int(i) in state.why))
    if not vectorize:
        reasons.append("closed form turned off")
    start = time.perf_counter()
    for k, i in enumerate(todo):
        with step(f"solving point {k + 1} of {len(todo)} one by one"):
            state.solved(int(i), _solve(with_variant(spec, points[int(i)], "sweep"), options))
        if deadline is not None:
            _within(deadline, start, k + 1, len(todo), reasons)
    state.solve_seconds = time.perf_counter() - start
    return Sweep(
        spec.file,
        spec.title,
        tuple(axes),
        shape,
        {axis.name: column for axis, column in zip(axes, columns, strict=True)},
        state.answers(spec),
        state.regimes,
        state.paths,
        state.notes,
        tuple(dict.fromkeys(_said(r) for r in reasons)),
        state.build_seconds,
        state.evaluate_seconds,
        state.solve_seconds,
    )


def _said(reason: str) -> str:
    """A reason from grading's closed form, in a sweep's words."""
    return reason.replace("per variant", "per point")


def _within(deadline: float, start: float, done: int, total: int, reasons: list[str]) -> None:
    """Stop (OverBudget) when the full solves so far show the rest cannot end by ``deadline``."""
    from dynsolve.budget import OverBudget

    now = time.perf_counter()
    each = (now - start) / done
    if done < 3 or now + each * (total - done) <= deadline:
        return
    why = f" ({_said(reasons[0])})" if reasons else ""
    raise OverBudget(
        f"{total} points need a full solve each{why}: about {each:.2g} s a point, "
        f"{each * total:.0f} s in all, past the time budget",
        "solving the points one by one",
        hint="use fewer --points, leave out a find that has no closed form (--answers), "
        "or give a larger --time-budget",
    )


def regime_of(solution: Solution | str) -> str:
    """The regime of a solve in words (:func:`regime_words` of its assumptions); "not
    solved" when the solve failed.

    >>> from dynsolve.pipeline import solve_text
    >>> solution = solve_text("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")
    >>> regime_of(solution), regime_of("no solution")
    ('', 'not solved')
    """
    if isinstance(solution, str):
        return "not solved"
    return regime_words((a.name, a.holds) for a in solution.assumptions)


def regime_words(assumptions: Iterable[tuple[str, bool]]) -> str:
    """The assumptions that fail, in words ("slips at C", "cord T goes slack", "tips on B",
    "loses contact at A"); "as assumed" when every one holds, "" when none is made. Also
    reads a closed form's conditions (their labels are the assumptions' names; a root's
    constraint and the sense of a slip are not assumptions).

    >>> regime_words([("no slip at C", False), ("contact at C kept", True)])
    'slips at C'
    >>> regime_words([("cord T taut", True)]), regime_words([("constraint v >= 0", True)])
    ('as assumed', '')
    """
    words = []
    made = False
    for name, holds in assumptions:
        if name.startswith(("constraint ", "sense of the slip at ")):
            continue
        made = True
        if holds:
            continue
        if name.startswith("no slip at "):
            words.append(f"slips at {name.removeprefix('no slip at ')}")
        elif name.startswith("contact at ") and name.endswith(" kept"):
            words.append(f"loses contact at {name[len('contact at ') : -len(' kept')]}")
        elif name.startswith("cord ") and name.endswith(" taut"):
            words.append(f"{name.removesuffix(' taut')} goes slack")
        elif name.startswith("no tipping on base "):
            words.append(f"tips on {name.removeprefix('no tipping on base ')}")
        else:
            words.append(f"{name}: fails")
    if words:
        return "; ".join(words)
    return "as assumed" if made else ""


def _solve(spec: Spec, options: SolveOptions) -> Solution | str:
    """A full solve, as ``dynsolve solve`` makes it, or why it failed."""
    from dynsolve.pipeline import solve_spec

    try:
        return solve_spec(spec, options)
    except DynsolveError as error:
        return error.message.removeprefix("student sweep: ")


class _Points(Sequence[dict[str, str]]):
    """Each point's swept givens as cell text (``12.5 kg``), made when asked for."""

    def __init__(self, axes: Sequence[Axis], columns: Sequence[np.ndarray]) -> None:
        self.units = [axis.unit for axis in axes]
        self.names = [axis.name for axis in axes]
        self.columns = columns
        self.index: np.ndarray | None = None

    def at(self, index: np.ndarray) -> _Points:
        """The points at ``index`` (positions in this view become those of ``index``)."""
        view = _Points([], self.columns)
        view.units, view.names, view.index = self.units, self.names, index
        return view

    def __len__(self) -> int:
        return len(self.index) if self.index is not None else len(self.columns[0])

    def __getitem__(self, i: int) -> dict[str, str]:  # type: ignore[override]
        point = int(self.index[i]) if self.index is not None else i
        return {
            name: f"{float(column[point])!r} {unit}".strip()
            for name, unit, column in zip(self.names, self.units, self.columns, strict=True)
        }


class _Labels(Sequence[str]):
    """Each point's name in messages ("point 17", counted from 1)."""

    def __init__(self, index: np.ndarray) -> None:
        self.index = index

    def __len__(self) -> int:
        return len(self.index)

    def __getitem__(self, i: int) -> str:  # type: ignore[override]
        return f"point {int(self.index[i]) + 1}"


class _State:
    """The answers gathered so far: values in SI base units, directions, regimes, paths."""

    def __init__(self, n: int) -> None:
        self.n = n
        self.values: dict[str, np.ndarray] = {}
        self.units: dict[str, str] = {}
        self.directions: dict[str, np.ndarray] = {}
        self.regimes = np.full(n, "", dtype=object)
        self.paths = np.full(n, PER_POINT, dtype=object)
        self.notes: dict[int, str] = {}
        self.why: dict[int, str] = {}
        self.build_seconds = self.evaluate_seconds = self.solve_seconds = 0.0

    def store(self, name: str, unit: str, index: object, si: object) -> None:
        """Values of ``name`` (SI base units) at the points ``index``."""
        if name not in self.values:
            self.values[name] = np.full(self.n, np.nan)
            self.units[name] = unit
        self.values[name][index] = si

    def direct(self, name: str, index: object, words: object) -> None:
        """Direction words of ``name`` at the points ``index`` (kept only when stated)."""
        if not np.any(np.asarray(words, dtype=object) != ""):
            return
        if name not in self.directions:
            self.directions[name] = np.full(self.n, "", dtype=object)
        self.directions[name][index] = words

    def solved(self, i: int, solution: Solution | str) -> None:
        """Point ``i`` answered by a full solve (or its failure noted)."""
        self.regimes[i] = regime_of(solution)
        if isinstance(solution, str):
            self.notes[i] = solution
            return
        failed = [c for c in solution.checks if not c.passed and not c.name.startswith("answer ")]
        if failed:
            self.notes[i] = f"check '{failed[0].name}' fails: {failed[0].detail}"
            if self.regimes[i] in ("", "as assumed"):
                self.regimes[i] = "a check fails"
            return
        for row in solution.answers:
            if row.value is None or not math.isfinite(row.value):
                self.notes.setdefault(i, f"{row.name} is {row.shown}")
                continue
            self.store(row.name, row.unit, i, row.value * unit_info(row.unit).factor)
            self.direct(row.name, [i], [row.direction])

    def answers(self, spec: Spec) -> tuple[Answer, ...]:
        """Every find, in order, in its display unit."""
        out = []
        for find in spec.finds:
            unit = self.units.get(find.name, find.unit.text if find.unit else "")
            si = self.values.get(find.name, np.full(self.n, np.nan))
            words = self.directions.get(find.name)
            out.append(
                Answer(
                    find.name,
                    unit,
                    si / unit_info(unit).factor,
                    tuple(words.tolist()) if words is not None else (),
                )
            )
        return tuple(out)
