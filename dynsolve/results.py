"""The solution as plain data: what every renderer shows and what ``check`` compares.

Built by :mod:`dynsolve.pipeline`; frozen, no sympy objects, so renderers stay pure.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from dynsolve.names import pretty


@dataclass(frozen=True)
class GivenRow:
    """A given as written and in the base units of the problem's system (SI or FPS)."""

    name: str
    written: str  # "40 lb", or "mass" for a symbolic given
    base: str  # in the system's base units: "177.9 N" (SI), "40 lb" (FPS)
    description: str
    symbolic: bool
    latex_name: str
    latex_value: str


@dataclass(frozen=True)
class EquationRow:
    """An equation or constraint as written, with its dimension check."""

    line: int
    text: str  # as written, with Greek letters
    latex: str
    note: str  # the principle, from the trailing comment
    dimension: str  # "force [N]"
    dimension_ok: bool
    constraint: bool


@dataclass(frozen=True)
class Formula:
    """One unknown's result within a step: symbolic formula (optional) and value."""

    name: str
    formula: str  # "" when not shown
    formula_latex: str
    value: str  # 3 s.f. with unit, or the formula for symbolic problems
    value_latex: str
    substituted: str = ""  # the formula with the numbers put in (base units), "" when none
    substituted_latex: str = ""


@dataclass(frozen=True)
class Step:
    """One block of the solve order: which equations give which unknowns, and how."""

    index: int
    lines: tuple[int, ...]
    unknowns: tuple[str, ...]
    method: str  # "linear", "symbolic" or "numeric"
    results: tuple[Formula, ...]
    discarded: tuple[str, ...]  # "ω = -3.00 rad/s: violates omega >= 0 (line 9)"
    note: str
    heading: str = ""  # replaces "Equation (line n) gives X" for a step not from equations


@dataclass(frozen=True)
class AnswerRow:
    """A found quantity: full-precision value in its display unit, or a formula."""

    name: str
    value: float | None  # None for a symbolic answer
    unit: str  # pint-parsable, lb = pound-force
    shown: str  # 3 significant figures with the unit, e.g. "-5.91 rad/s²"
    formula: str  # exact form, e.g. "15696/3475" or "sqrt(2*g*h)"
    latex: str
    direction: str  # "cw", "ccw" … when the answer key states one, else ""


PASSED, FAILED, NOT_RUN = "passed", "failed", "not_run"


@dataclass(frozen=True)
class Check:
    """A check (dimensions, residuals, roots, answer key, simulation …) that passed, failed,
    or did not run: it could not run or could not decide (``ran`` False, ``detail`` says
    why). A check that did not run is never a pass, and never fails the solution.

    >>> Check.not_run("simulation", "symbolic givens have no values").status
    'not_run'
    >>> Check("dimensions", True, "").status, Check("root", False, "").failed
    ('passed', True)
    """

    name: str
    passed: bool
    detail: str
    ran: bool = True

    @classmethod
    def not_run(cls, name: str, reason: str) -> Check:
        """A check that could not run or could not decide, and why."""
        return cls(name, False, reason, ran=False)

    @property
    def status(self) -> str:
        """ "passed", "failed" or "not_run"."""
        return NOT_RUN if not self.ran else PASSED if self.passed else FAILED

    @property
    def failed(self) -> bool:
        """True when the check ran and failed."""
        return self.ran and not self.passed

    @property
    def shown_detail(self) -> str:
        """The detail as shown: led by "not run: " for a check that did not run, unless it
        says so itself ("not simulated: …", "cannot be decided …")."""
        return _led(self.status, self.detail, "not run")


def check_counts(checks: Iterable[Check]) -> tuple[int, int, int]:
    """How many checks passed, failed and did not run.

    >>> check_counts([Check("a", True, ""), Check.not_run("b", "no values")])
    (1, 0, 1)
    """
    statuses = [c.status for c in checks]
    return statuses.count(PASSED), statuses.count(FAILED), statuses.count(NOT_RUN)


@dataclass(frozen=True)
class KeyComparison:
    """One answer-key entry compared with the computed answer."""

    name: str
    expected: str
    got: str
    passed: bool
    detail: str


@dataclass(frozen=True)
class ForceRow:
    """One force or couple on a free-body diagram."""

    name: str  # "T", "W_drum", "N_A", "M"
    kind: str  # a ForceTerm kind (principles/newton_euler.py) or "couple"
    point: str  # where it acts: "G", "A", "(0.4, 0)"
    x: float  # the point relative to the body's mass centre, SI metres (for drawing)
    y: float
    direction: str  # "down", "up", "angle 36.9°", "cw"
    dx: float  # unit vector of the drawn arrow (0, 0 for a couple)
    dy: float
    known: bool  # False for an unknown reaction, tension or friction
    value: str  # the magnitude, shown with its unit once solved ("" before)


@dataclass(frozen=True)
class FreeBody:
    """A body's free-body and kinetic diagrams, as data."""

    body: str
    shape: str  # "disk", "rod", "block", "plate", "particle", "ring", "sphere", …
    size: tuple[float, ...]  # the shape's sizes in SI metres (radius; length; width, height)
    motion: str  # "translation", "rotation about O", "general plane motion"
    forces: tuple[ForceRow, ...]
    kinetic: tuple[str, ...]  # kinetic-diagram terms: "m a_Gx", "I_G α"
    moment_point: str  # the point moments are taken about, and why
    # incline axes (t down the slope, n out of it) as unit vectors, where the equations use them
    axes: tuple[tuple[float, float], tuple[float, float]] | None = None
    omega: str = ""  # the body's sense of rotation at the instant, "ccw" or "cw", when it turns
    # a composite's parts, (shape, x, y, sizes, angle in degrees, hole), metres from G
    parts: tuple[tuple, ...] = ()


@dataclass(frozen=True)
class Assumption:
    """An assumption made to solve (no slip, no tipping, contact kept, cord taut) and its
    check; ``decided`` is False where the check could not decide (``detail`` says why)."""

    name: str
    holds: bool
    detail: str
    decided: bool = True

    @classmethod
    def undecided(cls, name: str, reason: str) -> Assumption:
        """An assumption made, whose check could not decide it, and why."""
        return cls(name, False, reason, decided=False)

    @property
    def status(self) -> str:
        """ "passed" (it holds), "failed" or "not_run" (undecided)."""
        return NOT_RUN if not self.decided else PASSED if self.holds else FAILED

    @property
    def shown_detail(self) -> str:
        """The detail as shown: led by "not decided: " for an undecided assumption, unless
        it says so itself."""
        return _led(self.status, self.detail, "not decided")


def _led(status: str, detail: str, words: str) -> str:
    """``detail`` led by ``words`` when the status is not run and it does not say so.

    >>> _led(NOT_RUN, "0 = 0 checks nothing", "not run"), _led(NOT_RUN, "cannot be", "x")
    ('not run: 0 = 0 checks nothing', 'cannot be')
    """
    if status != NOT_RUN or detail.startswith(("not ", "cannot ")):
        return detail
    return f"{words}: {detail}"


@dataclass(frozen=True)
class Trial:
    """A case assumed first and rejected by its check (no slip, then slipping): the trial's
    equations and solve, the check with its numbers, and what changed in the re-solve."""

    assumption: str  # "no slip at A"
    equations: tuple[EquationRow, ...]
    steps: tuple[Step, ...]
    verdict: str  # "|F| = 300 > μs N = 294.3; re-solved with F = μk N opposing the slip"
    remarks: tuple[str, ...] = ()  # "α changes sense: 0.667 rad/s² in the trial, -0.428 after"
    second_moments: tuple[EquationRow, ...] = ()  # ΣM_G when the trial's moments were about A


@dataclass(frozen=True)
class EnergyTerm:
    """One term of a work–energy equation as the textbook lists it: T1, each U, T2."""

    name: str  # "T1", "U_W", "T2"
    meaning: str  # "kinetic energy in state 1", "W·Δr_G (disk)"
    formula: str  # in the givens' symbols, "" when it is a number
    formula_latex: str
    value: str  # with its unit, e.g. "9.38 lb·ft"
    value_latex: str


@dataclass(frozen=True)
class Remark:
    """What the answers tell: these answers do not depend on these masses (they cancel).

    >>> Remark(("v_2", "theta"), ("m",)).text
    'v_2 and θ do not depend on m: the mass cancels'
    """

    answers: tuple[str, ...]  # names as written in find
    masses: tuple[str, ...]

    @property
    def text(self) -> str:
        """The remark in words, names as the terminal prints them."""
        return self.words([pretty(n) for n in self.answers], [pretty(n) for n in self.masses])

    def words(self, answers: list[str], masses: list[str]) -> str:
        """The remark with the names already typeset (``$v_{2}$`` for LaTeX)."""
        subject = (
            answers[0] if len(answers) == 1 else ", ".join(answers[:-1]) + " and " + answers[-1]
        )
        verb = "does" if len(answers) == 1 else "do"
        plural = "masses cancel" if len(masses) > 1 else "mass cancels"
        return f"{subject} {verb} not depend on {' or '.join(masses)}: the {plural}"


@dataclass(frozen=True)
class LimitRemark:
    """A limit case the answer shows: as a given goes to 0 (nearly from rest, nearly
    smooth) the answer's formula tends to one that no longer depends on some other givens.

    >>> LimitRemark("theta", "v_1", "nearly from rest", "acos(2/3)", "", "48.2°", "",
    ...             ("R", "g")).text
    'as v_1 → 0 (nearly from rest), θ → acos(2/3) = 48.2°, whatever R and g'
    """

    answer: str
    given: str
    case: str
    formula: str  # the answer's formula in the limit, as the terminal prints it
    formula_latex: str
    value: str  # with its unit
    value_latex: str
    whatever: tuple[str, ...]  # the givens the limit does not depend on
    direction: str = ""  # "down", "cw", … as the answers table gives it

    @property
    def text(self) -> str:
        """The remark in words, names as the terminal prints them."""
        value = f"{self.value} {self.direction}".strip()
        return self.words(
            pretty(self.given), pretty(self.answer), self.formula, value,
            [pretty(n) for n in self.whatever],
        )  # fmt: skip

    def words(
        self, given: str, answer: str, formula: str, value: str, whatever: list[str], to: str = "→"
    ) -> str:
        """The remark with its parts already typeset (``$v_{1}$`` for LaTeX)."""
        names = (
            whatever[0] if len(whatever) == 1 else ", ".join(whatever[:-1]) + " and " + whatever[-1]
        )
        tends = f"{answer} {to} {formula}" + (f" = {value}" if value and value != formula else "")
        return f"as {given} {to} 0 ({self.case}), {tends}, whatever {names}"


@dataclass(frozen=True)
class SceneSketch:
    """A planar scene as the problem's figure, in SI metres (see
    :mod:`dynsolve.modes.scene_sketch`): each entry a name, then numbers."""

    # name, shape, x_G, y_G, sizes, angle (degrees, ccw), a composite's parts:
    # (shape, x, y, sizes, angle, hole) each
    bodies: tuple[tuple, ...]
    pins: tuple[tuple[str, float, float], ...]  # name, x, y
    # name, x, y (under G), n (pushing on the body), half its length
    surfaces: tuple[tuple[str, float, float, float, float, float], ...]
    # name, x, y, along the cord, how far to its other end (0: to a support off the figure)
    cords: tuple[tuple[str, float, float, float, float, float], ...]
    springs: tuple[tuple[str, float, float, float, float], ...]  # name, one end, the other
    links: tuple[tuple[str, float, float, float, float], ...]  # name, one end, the other
    forces: tuple[tuple[str, float, float, float, float], ...]  # name, x, y, direction
    couples: tuple[tuple[str, float, float, int], ...]  # name, where (G), sense (+1 ccw)
    paths: tuple[tuple[str, tuple[tuple[float, float], ...]], ...]  # name, sampled points
    gravity: bool
    # a two-sided guide (a collar's rod, a slot): name, x, y, its normal, half its length
    guides: tuple[tuple[str, float, float, float, float, float], ...] = ()


@dataclass(frozen=True)
class LinkageFigure:
    """A linkage at the instant, as data for a drawing (positions in metres)."""

    joints: tuple[tuple[str, float, float, bool], ...]  # name, x, y, fixed to the ground
    bars: tuple[tuple[str, tuple[str, ...]], ...]  # name, its joints in order
    guides: tuple[tuple[str, float, float], ...]  # a slider's joint and its guide's direction
    wheels: tuple[tuple[str, str, float], ...]  # a wheel or gear: bar, centre joint, radius
    grounds: tuple[tuple[float, float, float, float], ...] = ()  # where a wheel rolls: K, n


@dataclass(frozen=True)
class Solution:
    """Everything about one solved spec."""

    file: str
    title: str
    source: str
    system: str
    mode: str
    givens: tuple[GivenRow, ...]
    equations: tuple[EquationRow, ...]
    steps: tuple[Step, ...]
    answers: tuple[AnswerRow, ...]
    checks: tuple[Check, ...]
    key: tuple[KeyComparison, ...]
    status: str
    messages: tuple[str, ...] = ()
    free_body: tuple[FreeBody, ...] = ()
    assumptions: tuple[Assumption, ...] = ()
    warnings: tuple[str, ...] = ()  # likely slips in the spec: a bare-number angle, lb as a mass
    trials: tuple[Trial, ...] = ()  # cases assumed, checked and rejected before the answer
    energy: tuple[EnergyTerm, ...] = ()  # work and energy term by term (a scene's travel)
    linkage: LinkageFigure | None = None  # a linkage's joints and bars at the instant
    sketch: SceneSketch | None = None  # a planar scene as the problem's figure
    # what the answers tell: a mass that cancels, a limit case
    remarks: tuple[Remark | LimitRemark, ...] = ()
    figure: str = ""  # a LaTeX sheet's motion plot: its file, beside the sheet ("" for none)
    # the other moment equation (about G where the solve took moments about A), as a check
    second_moments: tuple[EquationRow, ...] = ()

    @property
    def passed(self) -> bool:
        """True when no check (answer key included) failed; a check that did not run
        does not fail the solution (it is shown as not run)."""
        return not any(c.failed for c in self.checks)
