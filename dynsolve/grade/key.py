"""Each student's expected answers: the base problem solved once, or their own variant.

Without variants every student shares one :class:`Key` per find, from one solve of the
spec. With a variants file, :func:`dynsolve.grade.expected.expected_answers` (branch
``variants``) gives each student's; :class:`Keys` hides which, behind ``for_student``.

>>> from dynsolve.spec.parser import parse_spec
>>> spec = parse_spec("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n", "w.dyn")
>>> keys = base_keys(spec)
>>> round(keys.for_student("s1")["W"].value, 3)
19.62
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from dynsolve.errors import SpecError
from dynsolve.grade.cells import NEGATIVE
from dynsolve.grade.semantics import Key
from dynsolve.pipeline import solve_spec
from dynsolve.quantities import unit_info
from dynsolve.results import Solution
from dynsolve.spec.ast import Spec
from dynsolve.system import SolveOptions


@dataclass
class Keys:
    """The expected answers of every student: shared, or per student (variants)."""

    shared: Mapping[str, Key]
    per_student: Mapping[str, Mapping[str, Key]] = field(default_factory=dict)
    errors: Mapping[str, str] = field(default_factory=dict)  # student -> why no key
    path: str = "one solve"
    variants: Mapping[str, Mapping[str, str]] = field(default_factory=dict)  # their givens
    by_variant: bool = False  # a variants file was given: every student needs a row in it

    def for_student(self, student: str) -> Mapping[str, Key]:
        """The keys ``student`` is graded against (their variant's, else the base's)."""
        return self.per_student.get(student, self.shared)

    def unknown(self, student: str) -> bool:
        """Graded by variants, but ``student`` has no row in the variants file (never
        graded against the base problem instead)."""
        return self.by_variant and student not in self.per_student and student not in self.errors

    expected_for = for_student  # the name the variants interface agreed on


def keys_of(solution: Solution) -> dict[str, Key]:
    """Keys from a solved spec: signed SI values (a cw/down/left magnitude made negative)."""
    keys: dict[str, Key] = {}
    for answer in solution.answers:
        if answer.value is None:
            raise SpecError(
                f"{answer.name} is a formula ({answer.formula}): only numbers can be graded",
                None,
                "give every symbolic given a value",
            )
        info = unit_info(answer.unit)
        sign = -1.0 if answer.direction in NEGATIVE else 1.0
        keys[answer.name] = Key(
            answer.name,
            sign * answer.value * info.factor,
            info.dim,
            answer.unit,
            info.factor,
            answer.direction or "",
        )
    return keys


def base_keys(spec: Spec, options: SolveOptions | None = None) -> Keys:
    """Every student graded against the spec as written: one solve."""
    return Keys(keys_of(solve_spec(spec, options)))


def variant_keys(
    spec: Spec, variants: Mapping[str, Mapping[str, str]], options: SolveOptions
) -> Keys:
    """Each student's keys from their own variant (needs ``dynsolve.grade.expected``)."""
    try:
        from dynsolve.grade.expected import expected_answers  # type: ignore[import-not-found]
    except ImportError:
        raise SpecError(
            "variants need the 'dynsolve variants' support (dynsolve.grade.expected)",
            None,
            "grade without --variants, against the problem as written",
        ) from None
    result = expected_answers(spec, variants, options)
    students = getattr(result, "students", result)
    per_student: dict[str, dict[str, Key]] = {}
    errors: dict[str, str] = {}
    for student, expected in students.items():
        if expected.error:
            errors[student] = expected.error
            continue
        per_student[student] = {}
        for name, answer in expected.answers.items():
            info = unit_info(answer.unit)
            sign = -1.0 if answer.direction in NEGATIVE else 1.0
            per_student[student][name] = Key(
                name, sign * answer.value, answer.dim, answer.unit, info.factor, answer.direction
            )
    base = keys_of(solve_spec(spec, options))
    path = getattr(result, "path", "per-variant")
    return Keys(base, per_student, errors, path, variants, by_variant=True)
