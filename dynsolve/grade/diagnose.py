"""Name the classic mistake that reproduces a wrong answer, on the problem's own model.

Two kinds of candidates. Answer-side slips need no solve: a power of ten or unit prefix
(×10^±1, ±2, ±3, ±6), an angular value in degrees written with a radian unit or the
reverse, another part's answer, a force given its static value (a mass given times g, or
a weight given ``W…``: T = m g as if nothing accelerated) and, with variants, the answer
of the problem as printed instead of the student's own variant.
Model-side mistakes re-solve the spec with one given or equation changed: degrees taken as
radians (or the reverse) for an angle given, a weight in lb used as a mass (×32.2) or
slug/lbm swapped, g missing (g = 1) or from the other unit system, μs and μk swapped,
the diameter used for a radius (or the radius for a diameter), and I_G used for I_O (an
``I_O = I_G + m*d^2`` equation with the parallel-axis term dropped). The re-solves are
made once per problem and cached; the first candidate that reproduces the student's
magnitude within tolerance gives the sentence.

>>> from dynsolve.spec.parser import parse_spec
>>> from dynsolve.grade.semantics import Rule
>>> spec = parse_spec("given:\\n  m = 2 kg\\n  g = 9.81 m/s^2\\n"
...                   "equations:\\n  W = m*g\\nfind: W\\n", "w.dyn")
>>> doctor = Diagnoser(spec)
>>> keys = {"W": Key("W", 19.62, Dim.of("force"), "N")}
>>> doctor.diagnose("W", 2.0, keys, Rule())
'g left out (g = 1)'
>>> doctor.diagnose("W", 1962.0, keys, Rule())
'a power-of-ten slip (x100): check the unit prefix'
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from fractions import Fraction

from dynsolve.errors import DynsolveError
from dynsolve.grade.semantics import ANGULAR_UNITS, Key, Rule
from dynsolve.principles.newton_euler import parallel_axis_forgotten
from dynsolve.quantities import resolve_unit, unit_info
from dynsolve.spec.ast import Binary, EquationStmt, Given, Name, Quantity, Spec
from dynsolve.spec.parser import parse_quantity, parse_unit
from dynsolve.system import SolveOptions
from dynsolve.units import GRAVITY, Dim

MAX_CACHED = 100_000  # students whose givens are kept
MATCH_RTOL = 0.01  # a mistake reproduces an answer within 1 % (or the part's rtol if wider)
POWERS = (1, -1, 2, -2, 3, -3, 6, -6)
G_FACTOR = Fraction(322, 10)  # ft/s^2 per slug/lbm and lb as mass
DEGREE = math.pi / 180
FORCE, MASS = Dim.of("force"), Dim.of("mass")
BASE_NUMBERS = "the numbers of the problem as printed used, not those of your own variant"

__all__ = ["Diagnoser", "Dim", "Key"]


@dataclass(frozen=True)
class Mistake:
    """A model-side mistake: its sentence and the answers (signed SI) it leads to."""

    sentence: str
    values: Mapping[str, float]


class Diagnoser:
    """The classic mistakes of one problem (one variant), re-solved lazily and once."""

    def __init__(
        self,
        spec: Spec,
        options: SolveOptions | None = None,
        model: bool = True,
        variants: Mapping[str, Mapping[str, str]] | None = None,
    ) -> None:
        self.spec = spec
        self.options = options or SolveOptions()
        self.model = model  # False: answer-side slips only
        self.variants = variants  # each student's givens: their own models' mistakes
        self._by_student: dict[str, list[Mistake]] | None = None
        self._mistakes: list[Mistake] | None = None
        self._slips: dict[tuple[str, tuple[float, ...]], list[tuple[str, float]]] = {}
        self._base: dict[str, float] | None = None  # the printed problem's answers
        self._givens: dict[str, list[tuple[str, float, Dim]]] = {}  # per student, in SI

    def diagnose(
        self, part: str, value: float, keys: Mapping[str, Key], rule: Rule, student: str = ""
    ) -> str:
        """The sentence naming the mistake that gives ``value`` for ``part``, or ""."""
        key = keys[part]
        tolerance = max(MATCH_RTOL, rule.rtol)
        signature = (part, tuple(k.value for k in keys.values()))
        if signature not in self._slips:  # the same keys (no variants): built once
            self._slips[signature] = self._answer_side(part, keys)
        if self.variants is not None and self.model:
            base = self.base_answers().get(part, key.value)  # none: nothing to tell apart
            if not _close(base, key.value, 1e-6) and _close(value, base, tolerance):
                return BASE_NUMBERS
        slips = self._slips[signature]
        if key.dim == FORCE:
            slips = slips + self._static(part, student)
        for sentence, candidate in slips:
            if _close(value, candidate, tolerance) and not _close(candidate, key.value, 1e-9):
                return sentence
        for mistake in self.mistakes(student):
            candidate = mistake.values.get(part)
            if candidate is None or _close(candidate, key.value, 1e-6):
                continue  # this mistake does not change this part
            if _close(value, candidate, tolerance):
                return mistake.sentence
        return ""

    def mistakes(self, student: str = "") -> list[Mistake]:
        """Every model-side mistake that solves, each re-solved once (with variants: the
        student's own, all students' evaluated together on the first call)."""
        if self.variants is not None and self.model:
            if self._by_student is None:
                self._by_student = variant_mistakes(self.spec, self.variants, self.options)
            return self._by_student.get(student, [])
        if self._mistakes is None:
            self._mistakes = []
            if not self.model:
                return self._mistakes
            for sentence, spec in _variants(self.spec):
                values = _solve(spec, self.options)
                if values is not None:
                    self._mistakes.append(Mistake(sentence, values))
            if _pinned_scene(self.spec):
                with parallel_axis_forgotten():
                    values = _solve(self.spec, self.options)
                if values is not None:
                    self._mistakes.append(Mistake(PINNED_I_G, values))
        return self._mistakes

    def base_answers(self) -> dict[str, float]:
        """The answers of the problem as printed (signed SI), solved once."""
        if self._base is None:
            self._base = _solve(self.spec, self.options) or {}
        return self._base

    def _static(self, part: str, student: str) -> list[tuple[str, float]]:
        """A force answered with its static value: a mass given times g, or a weight."""
        givens = self.givens(student)
        g = next((v for name, v, _ in givens if name == "g"), None)
        if g is None:
            number, unit = GRAVITY[self.spec.system]
            g = float(number) * unit_info(unit).factor
        out = []
        for name, value, dim in givens:
            if dim == MASS:
                out.append(
                    (f"the static answer {part} = {name} g, as if nothing accelerated", value * g)
                )
            elif dim == FORCE and name.startswith(("W", "w")):
                out.append((f"the static answer {part} = {name}, as if nothing accelerated", value))
        return out

    def givens(self, student: str = "") -> list[tuple[str, float, Dim]]:
        """The student's givens (their variant's, else the spec's) with a unit: name, value
        in SI base units, dimension."""
        if student in self._givens:
            return self._givens[student]
        cells = (self.variants or {}).get(student, {})
        out = []
        for given in self.spec.givens:
            quantity, text = given.quantity, cells.get(given.name, "")
            try:
                quantity = parse_quantity(text) if text.strip() else quantity
                if quantity is None or quantity.unit is None:
                    continue
                info = resolve_unit(quantity.unit, "<given>")
            except DynsolveError:
                continue
            out.append((given.name, float(quantity.value) * info.factor, info.dim))
        if len(self._givens) < MAX_CACHED:
            self._givens[student] = out
        return out

    def _answer_side(self, part: str, keys: Mapping[str, Key]) -> list[tuple[str, float]]:
        key = keys[part]
        out = [
            (
                f"a power-of-ten slip (x{_power(p)}): check the unit prefix",
                key.value * 10.0**p,
            )
            for p in POWERS
        ]
        if any(unit in key.unit for unit in ANGULAR_UNITS):  # either way round
            out.append(("a value in degrees labelled as radians (x57.3)", key.value / DEGREE))
            out.append(("a value in radians labelled as degrees (/57.3)", key.value * DEGREE))
        for other, other_key in keys.items():
            if other != part:
                scaled = other_key.value / other_key.factor * key.factor
                out.append((f"the answer of {other} given for {part}", scaled))
        return out


def _power(p: int) -> str:
    return str(10**p) if p > 0 else f"1/{10**-p}"


def _close(a: float, b: float, rtol: float) -> bool:
    return abs(abs(a) - abs(b)) <= rtol * max(abs(b), 1e-300)


def _solve(spec: Spec, options: SolveOptions) -> dict[str, float] | None:
    from dynsolve.grade.key import keys_of
    from dynsolve.pipeline import solve_spec

    try:
        return {name: key.value for name, key in keys_of(solve_spec(spec, options)).items()}
    except Exception:
        return None


Change = Callable[[Quantity], Quantity]


def variant_mistakes(
    spec: Spec, variants: Mapping[str, Mapping[str, str]], options: SolveOptions
) -> dict[str, list[Mistake]]:
    """The given-level mistakes on every student's own variant: each mistake is one more
    set of variants (the student's cells changed), solved for the whole class at once by
    :func:`dynsolve.grade.expected.expected_answers` (vectorized where it can)."""
    from dynsolve.grade.cells import NEGATIVE
    from dynsolve.grade.expected import expected_answers

    givens = {g.name: g.quantity for g in spec.givens if g.quantity is not None}
    out: dict[str, list[Mistake]] = {student: [] for student in variants}
    for sentence, changes in modifications(spec):
        modified: dict[str, dict[str, str]] = {}
        for student, cells in variants.items():
            row = dict(cells)
            for name, change in changes.items():
                try:
                    text = cells.get(name, "")
                    quantity = parse_quantity(text) if text.strip() else givens[name]
                except DynsolveError:
                    break
                changed = change(quantity)
                row[name] = f"{changed.text} {changed.unit.text if changed.unit else ''}".strip()
            else:
                modified[student] = row
        try:
            result = expected_answers(spec, modified, options)
        except Exception:
            continue
        for student, expected in getattr(result, "students", result).items():
            if expected.error:
                continue
            values = {
                name: (-1.0 if answer.direction in NEGATIVE else 1.0) * answer.value
                for name, answer in expected.answers.items()
            }
            out[student].append(Mistake(sentence, values))
    if _pinned_scene(spec):
        out = _merge(out, _forgotten_parallel_axis(spec, variants, options))
    return out


PINNED_I_G = (
    "I_G used for the moment of inertia about the pin (the parallel-axis term m r_G² forgotten)"
)


def _pinned_scene(spec: Spec) -> bool:
    """A scene with a pinned body: where I about the pin may be mistaken for I_G."""
    return any(stmt.kind == "pin" for stmt in spec.scene)


def _forgotten_parallel_axis(
    spec: Spec, variants: Mapping[str, Mapping[str, str]], options: SolveOptions
) -> dict[str, list[Mistake]]:
    """Every student's answers with I_G taken for I about the pin (scene mode)."""
    from dynsolve.grade.cells import NEGATIVE
    from dynsolve.grade.expected import expected_answers

    try:
        with parallel_axis_forgotten():
            result = expected_answers(spec, variants, options)
    except Exception:
        return {}
    out: dict[str, list[Mistake]] = {}
    for student, expected in getattr(result, "students", result).items():
        if not expected.error:
            values = {
                name: (-1.0 if answer.direction in NEGATIVE else 1.0) * answer.value
                for name, answer in expected.answers.items()
            }
            out[student] = [Mistake(PINNED_I_G, values)]
    return out


def _merge(
    first: dict[str, list[Mistake]], second: dict[str, list[Mistake]]
) -> dict[str, list[Mistake]]:
    return {student: first.get(student, []) + second.get(student, []) for student in first}


def _variants(spec: Spec) -> list[tuple[str, Spec]]:
    """Each mistaken model, with the sentence that names it."""
    out = [(sentence, _changed(spec, changes)) for sentence, changes in modifications(spec)]
    return out + _parallel_axis(spec)


def modifications(spec: Spec) -> list[tuple[str, dict[str, Change]]]:
    """Each given-level mistake: its sentence and how it changes which givens' quantities.

    >>> from dynsolve.spec.parser import parse_spec
    >>> spec = parse_spec("given:\\n  r = 0.4 m\\nequations:\\n  x = 2*r\\nfind: x\\n", "p")
    >>> [(sentence, list(changes)) for sentence, changes in modifications(spec)]
    [('the diameter used for the radius r', ['r'])]
    """
    out: list[tuple[str, dict[str, Change]]] = []
    givens = {g.name: g for g in spec.givens if g.quantity is not None}
    for name, given in givens.items():
        unit = _unit_text(given)
        if unit in ("deg", "rad"):
            other = "rad" if unit == "deg" else "deg"
            words = ("degrees", "radians") if unit == "deg" else ("radians", "degrees")
            out.append((f"{name} in {words[0]} taken as {words[1]}", {name: _unit_to(other)}))
        elif unit == "lb" and spec.system == "FPS":
            sentence = f"the weight {name} in lb used as a mass (x32.2)"
            out.append((sentence, {name: _times(G_FACTOR)}))
        elif unit in ("slug", "lbm"):
            other = "lbm" if unit == "slug" else "slug"
            out.append((f"{name} in {unit} taken as {other}", {name: _unit_to(other)}))
        if name == "g":
            out.append(("g left out (g = 1)", {name: _set(Fraction(1))}))
            if unit == "m/s^2":
                sentence = "g from the US system (32.2) in an SI problem"
                out.append((sentence, {name: _set(G_FACTOR)}))
            elif unit == "ft/s^2":
                sentence = "g from SI (9.81) in a US-system problem"
                out.append((sentence, {name: _set(Fraction(981, 100))}))
        if _is_radius(name):
            sentence = f"the diameter used for the radius {name}"
            out.append((sentence, {name: _times(Fraction(2))}))
        elif _is_diameter(name):
            sentence = f"the radius used for the diameter {name}"
            out.append((sentence, {name: _times(Fraction(1, 2))}))
    if "mu_s" in givens and "mu_k" in givens:
        mu_s, mu_k = givens["mu_s"].quantity, givens["mu_k"].quantity
        assert mu_s is not None and mu_k is not None
        swap = {"mu_s": _swap_with(mu_k.value), "mu_k": _swap_with(mu_s.value)}
        out.append(("mu_s and mu_k swapped", swap))
    return out


def _unit_to(unit: str) -> Change:
    return lambda q: replace(q, unit=parse_unit(unit))


def _times(factor: Fraction) -> Change:
    return lambda q: _valued_quantity(q, q.value * factor)


def _set(value: Fraction) -> Change:
    return lambda q: _valued_quantity(q, value)


def _swap_with(value: Fraction) -> Change:
    return lambda q: _valued_quantity(q, value)


def _valued_quantity(quantity: Quantity, value: Fraction) -> Quantity:
    return replace(quantity, value=value, text=format(float(value), ".12g"))


def _changed(spec: Spec, changes: Mapping[str, Change]) -> Spec:
    givens = tuple(
        replace(g, quantity=changes[g.name](g.quantity))
        if g.name in changes and g.quantity is not None
        else g
        for g in spec.givens
    )
    return replace(spec, givens=givens)


def _parallel_axis(spec: Spec) -> list[tuple[str, Spec]]:
    """``I_O = I_G + m*d^2`` with the parallel-axis term dropped (equation mode only)."""
    out = []
    for index, equation in enumerate(spec.equations):
        lhs, rhs = equation.lhs, equation.rhs
        if (
            isinstance(lhs, Name)
            and lhs.text.startswith("I_")
            and isinstance(rhs, Binary)
            and rhs.op == "+"
        ):
            kept = rhs.left if _has_square(rhs.right) else rhs.right
            changed: EquationStmt = replace(equation, rhs=kept)
            equations = (*spec.equations[:index], changed, *spec.equations[index + 1 :])
            sentence = f"I_G used for {lhs.text} (the parallel-axis term m d^2 forgotten)"
            out.append((sentence, replace(spec, equations=equations)))
    return out


def _has_square(expr: object) -> bool:
    if isinstance(expr, Binary):
        if expr.op == "^":
            return True
        return _has_square(expr.left) or _has_square(expr.right)
    return False


def _is_radius(name: str) -> bool:
    return name in ("r", "R") or name.startswith(("r_", "R_"))


def _is_diameter(name: str) -> bool:
    return name in ("d", "D") or name.startswith(("d_", "D_"))


def _unit_text(given: Given) -> str:
    assert given.quantity is not None
    return given.quantity.unit.text.replace(" ", "") if given.quantity.unit else ""
