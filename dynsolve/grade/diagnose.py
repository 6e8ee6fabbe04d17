"""Name the classic mistake that reproduces a wrong answer, on the problem's own model.

Two kinds of candidates. Answer-side slips need no solve: a power of ten or unit prefix
(×10^±1, ±2, ±3, ±6), degrees given for radians or the reverse, another part's answer.
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
from collections.abc import Mapping
from dataclasses import dataclass, replace
from fractions import Fraction

from dynsolve.grade.semantics import Key, Rule
from dynsolve.spec.ast import Binary, EquationStmt, Given, Name, Spec
from dynsolve.spec.parser import parse_unit
from dynsolve.system import SolveOptions
from dynsolve.units import Dim

MATCH_RTOL = 0.01  # a mistake reproduces an answer within 1 % (or the part's rtol if wider)
POWERS = (1, -1, 2, -2, 3, -3, 6, -6)
G_FACTOR = Fraction(322, 10)  # ft/s^2 per slug/lbm and lb as mass
DEGREE = math.pi / 180

__all__ = ["Diagnoser", "Dim", "Key"]


@dataclass(frozen=True)
class Mistake:
    """A model-side mistake: its sentence and the answers (signed SI) it leads to."""

    sentence: str
    values: Mapping[str, float]


class Diagnoser:
    """The classic mistakes of one problem (one variant), re-solved lazily and once."""

    def __init__(self, spec: Spec, options: SolveOptions | None = None, model: bool = True) -> None:
        self.spec = spec
        self.options = options or SolveOptions()
        self.model = model  # False: answer-side slips only (each student has own variant)
        self._mistakes: list[Mistake] | None = None
        self._slips: dict[tuple[str, tuple[float, ...]], list[tuple[str, float]]] = {}

    def diagnose(self, part: str, value: float, keys: Mapping[str, Key], rule: Rule) -> str:
        """The sentence naming the mistake that gives ``value`` for ``part``, or ""."""
        key = keys[part]
        tolerance = max(MATCH_RTOL, rule.rtol)
        signature = (part, tuple(k.value for k in keys.values()))
        if signature not in self._slips:  # the same keys (no variants): built once
            self._slips[signature] = self._answer_side(part, keys)
        for sentence, candidate in self._slips[signature]:
            if _close(value, candidate, tolerance) and not _close(candidate, key.value, 1e-9):
                return sentence
        for mistake in self.mistakes():
            candidate = mistake.values.get(part)
            if candidate is None or _close(candidate, key.value, 1e-6):
                continue  # this mistake does not change this part
            if _close(value, candidate, tolerance):
                return mistake.sentence
        return ""

    def mistakes(self) -> list[Mistake]:
        """Every model-side mistake that solves, each re-solved once."""
        if self._mistakes is None:
            self._mistakes = []
            if not self.model:
                return self._mistakes
            for sentence, spec in _variants(self.spec):
                values = _solve(spec, self.options)
                if values is not None:
                    self._mistakes.append(Mistake(sentence, values))
        return self._mistakes

    def _answer_side(self, part: str, keys: Mapping[str, Key]) -> list[tuple[str, float]]:
        key = keys[part]
        out = [
            (
                f"a power-of-ten slip (x{_power(p)}): check the unit prefix",
                key.value * 10.0**p,
            )
            for p in POWERS
        ]
        if "rad" in key.unit:
            out.append(("degrees given where radians are asked", key.value / DEGREE))
        if "deg" in key.unit:
            out.append(("radians given where degrees are asked", key.value * DEGREE))
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


def _variants(spec: Spec) -> list[tuple[str, Spec]]:
    """Each mistaken model, with the sentence that names it."""
    out: list[tuple[str, Spec]] = []
    givens = {g.name: g for g in spec.givens if g.quantity is not None}
    for given in givens.values():
        unit = _unit_text(given)
        if unit == "deg":
            out.append(
                (f"{given.name} in degrees taken as radians", _with_unit(spec, given, "rad"))
            )
        elif unit == "rad":
            out.append(
                (f"{given.name} in radians taken as degrees", _with_unit(spec, given, "deg"))
            )
        elif unit == "lb" and spec.system == "FPS":
            out.append(
                (
                    f"the weight {given.name} in lb used as a mass (x32.2)",
                    _scaled(spec, given, G_FACTOR),
                )
            )
        elif unit in ("slug", "lbm"):
            other = "lbm" if unit == "slug" else "slug"
            out.append((f"{given.name} in {unit} taken as {other}", _with_unit(spec, given, other)))
        if given.name == "g":
            out.append(("g left out (g = 1)", _valued(spec, given, Fraction(1))))
            if unit == "m/s^2":
                out.append(
                    ("g from the US system (32.2) in an SI problem", _valued(spec, given, G_FACTOR))
                )
            elif unit == "ft/s^2":
                out.append(
                    (
                        "g from SI (9.81) in a US-system problem",
                        _valued(spec, given, Fraction(981, 100)),
                    )
                )
        if _is_radius(given.name):
            out.append(
                (
                    f"the diameter used for the radius {given.name}",
                    _scaled(spec, given, Fraction(2)),
                )
            )
        elif _is_diameter(given.name):
            out.append(
                (
                    f"the radius used for the diameter {given.name}",
                    _scaled(spec, given, Fraction(1, 2)),
                )
            )
    if "mu_s" in givens and "mu_k" in givens:
        swapped = [
            replace(g, quantity=givens["mu_k" if g.name == "mu_s" else "mu_s"].quantity)
            if g.name in ("mu_s", "mu_k")
            else g
            for g in spec.givens
        ]
        out.append(("mu_s and mu_k swapped", replace(spec, givens=tuple(swapped))))
    out.extend(_parallel_axis(spec))
    return out


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


def _swap(spec: Spec, given: Given, new: Given) -> Spec:
    return replace(spec, givens=tuple(new if g is given else g for g in spec.givens))


def _with_unit(spec: Spec, given: Given, unit: str) -> Spec:
    assert given.quantity is not None
    quantity = replace(given.quantity, unit=parse_unit(unit))
    return _swap(spec, given, replace(given, quantity=quantity))


def _valued(spec: Spec, given: Given, value: Fraction) -> Spec:
    assert given.quantity is not None
    quantity = replace(given.quantity, value=value, text=str(value))
    return _swap(spec, given, replace(given, quantity=quantity))


def _scaled(spec: Spec, given: Given, factor: Fraction) -> Spec:
    assert given.quantity is not None
    return _valued(spec, given, given.quantity.value * factor)
