"""The parsed spec as immutable data: expressions, quantities and section statements.

Nothing here evaluates anything; :mod:`dynsolve.spec.parser` builds these nodes from
text and later stages turn them into sympy objects.

>>> Name("alpha", 3, 5).text
'alpha'
>>> str(Binary("*", Num(Fraction(2), "2", 1, 1), Name("m", 1, 3), 1, 2))
'2*m'
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from typing import Literal

__all__ = [
    "Answer",
    "Binary",
    "Call",
    "Direction",
    "EquationStmt",
    "Expr",
    "FindItem",
    "Fraction",
    "Given",
    "Location",
    "Name",
    "Num",
    "Prop",
    "Quantity",
    "QuantityRef",
    "SceneStmt",
    "Spec",
    "Tolerance",
    "Unary",
    "UnitExpr",
    "UnitFactor",
    "VaryStmt",
    "children",
]


def children(node: object) -> list[object]:
    """What a walk of the spec visits under ``node``: a tuple's or list's items, a node's
    fields in their order; nothing under a leaf (a name's text, a number).

    >>> children(Binary("*", Num(Fraction(2), "2", 1, 1), Name("m", 1, 3), 1, 2))[:3]
    ['*', Num(value=Fraction(2, 1), text='2', line=1, column=1), Name(text='m', line=1, column=3)]
    """
    if isinstance(node, tuple | list):
        return list(node)
    return [getattr(node, name) for name in _field_names(type(node))]


@cache  # dataclasses.fields per node was a fifth of a big scene's walks
def _field_names(cls: type) -> tuple[str, ...]:
    """The field names of a dataclass, none for any other class."""
    if not dataclasses.is_dataclass(cls):
        return ()
    return tuple(field.name for field in dataclasses.fields(cls))


def _as_written(node: object) -> str:
    """The node printed as written, names unchanged."""
    from dynsolve.spec.printing import expr_text

    return expr_text(node, str)  # type: ignore[arg-type]


@dataclass(frozen=True)
class Num:
    """A number literal, kept exact."""

    value: Fraction
    text: str
    line: int
    column: int

    def __str__(self) -> str:
        return self.text


@dataclass(frozen=True)
class Name:
    """A name: a given, an unknown, or the constants ``g`` and ``pi``."""

    text: str
    line: int
    column: int

    def __str__(self) -> str:
        return self.text


@dataclass(frozen=True)
class Unary:
    """``-operand`` (a leading ``+`` is dropped by the parser)."""

    op: Literal["-"]
    operand: Expr
    line: int
    column: int

    __str__ = _as_written


@dataclass(frozen=True)
class Binary:
    """``left op right`` for ``+ - * / ^``."""

    op: Literal["+", "-", "*", "/", "^"]
    left: Expr
    right: Expr
    line: int
    column: int

    __str__ = _as_written


@dataclass(frozen=True)
class Call:
    """A function call such as ``sin(theta)``."""

    function: str
    args: tuple[Expr, ...]
    line: int
    column: int

    __str__ = _as_written


Expr = Num | Name | Unary | Binary | Call


@dataclass(frozen=True)
class UnitFactor:
    """One unit name raised to a power inside a unit expression (``s^-2``)."""

    name: str
    exponent: Fraction
    line: int
    column: int


@dataclass(frozen=True)
class UnitExpr:
    """A unit expression as written (``kg*m^2``), flattened into factors."""

    text: str
    factors: tuple[UnitFactor, ...]
    line: int
    column: int


@dataclass(frozen=True)
class Quantity:
    """A number with an optional unit: ``60 kg``, ``0.6`` (dimensionless)."""

    value: Fraction
    text: str
    unit: UnitExpr | None
    line: int
    column: int


@dataclass(frozen=True)
class Given:
    """A ``given`` line: a value (``m = 60 kg``) or only a dimension (``m: mass``)."""

    name: str
    quantity: Quantity | None
    dimension: UnitExpr | None  # a dimension name or a unit, for symbolic givens
    description: str
    line: int
    column: int


@dataclass(frozen=True)
class EquationStmt:
    """An ``equations`` line: an equation (``=``) or a constraint (``>=``, ``<`` …)."""

    lhs: Expr
    relation: Literal["=", ">=", "<=", ">", "<"]
    rhs: Expr
    text: str
    note: str  # the trailing comment: the principle it states
    line: int
    column: int


@dataclass(frozen=True)
class QuantityRef:
    """A scene quantity named in find: ``alpha(drum)``, ``I(plate, O)``, ``trial(F_A)``."""

    function: str
    args: tuple[str, ...]
    line: int
    column: int


@dataclass(frozen=True)
class FindItem:
    """A name to solve for, with an optional output unit and, in scene mode, what it names."""

    name: str
    unit: UnitExpr | None
    line: int
    column: int
    ref: QuantityRef | None = None


@dataclass(frozen=True)
class Tolerance:
    """How close an answer must be: relative (``± 0.5%``) or absolute (``± 0.01 N``)."""

    kind: Literal["rel", "abs"]
    value: Fraction
    unit: UnitExpr | None
    text: str


DirectionWord = Literal["cw", "ccw", "up", "down", "left", "right"]


@dataclass(frozen=True)
class Answer:
    """An ``answers`` line: the expected value or formula of one found name."""

    name: str
    quantity: Quantity | None
    formula: Expr | None
    tolerance: Tolerance | None
    direction: DirectionWord | None
    line: int
    column: int


Vector = tuple[Expr, Expr]


@dataclass(frozen=True)
class Direction:
    """A direction: a word (``up``, ``cw``), an angle from +x, toward a point, or a vector."""

    kind: Literal["word", "angle", "toward", "vector"]
    word: str = ""
    angle: Expr | None = None
    point: str = ""
    vector: Vector | None = None
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Location:
    """Where something acts: a named point or a position relative to the body's G."""

    point: str = ""
    vector: Vector | None = None
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Prop:
    """One ``key value`` property of a body or contact (``mass m``, ``mu_s 0.3``)."""

    key: str
    values: tuple[Expr, ...] = ()
    about: str = ""  # for gyration/inertia about a point
    direction: Direction | None = None
    vector: Vector | None = None
    word: str = ""  # a shape name or component axes
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class SceneStmt:
    """One line of the ``scene`` section.

    ``kind`` is the leading keyword (body, part, hole, point, pin, contact, rolls, base,
    cord, force, couple, gravity, omega, motion); the other fields are filled as that
    kind needs them.
    """

    kind: str
    name: str = ""  # the body, point, load, cord or base being declared
    body: str = ""  # the body it acts on or belongs to
    props: tuple[Prop, ...] = ()
    location: Location | None = None
    direction: Direction | None = None
    other: str = ""  # the second body of a cord
    other_location: Location | None = None
    vectors: tuple[Vector, ...] = ()
    value: Expr | None = None
    word: str = ""  # cw/ccw, a motion, "fixed"
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class GradingRule:
    """A ``grading:`` line: ``rtol 1%``, ``atol 0.01 m/s``, ``sigfig 3``, ``alpha weight 2``."""

    part: str  # the find it applies to; "" for every part
    key: str  # rtol, atol, sigfig, decdig, weight, partial; signed (1, or 0: magnitude)
    value: Fraction
    text: str  # the number as written
    unit: UnitExpr | None  # atol's unit
    line: int
    column: int


@dataclass(frozen=True)
class VaryStmt:
    """A ``vary`` line: a range ``m = 40..60 kg step 5`` or ``k = ±10% sigfig 3``.

    ``kind`` is "range" (``low``, ``high``, ``step`` in ``unit``), "percent"
    (``percent`` of the given's value either side, rounded to ``sigfig`` figures), or
    "allow" (the line ``allow changes``: a variant's assumptions may differ from the base
    problem's; ``name`` is empty).
    """

    name: str
    kind: Literal["range", "percent", "allow"]
    low: Fraction = Fraction(0)
    high: Fraction = Fraction(0)
    step: Fraction = Fraction(0)
    unit: UnitExpr | None = None
    percent: Fraction = Fraction(0)
    sigfig: int = 3
    text: str = ""
    line: int = 0
    column: int = 0


@dataclass(frozen=True)
class Spec:
    """A whole parsed spec file."""

    file: str
    title: str
    source: str
    system: Literal["SI", "FPS"]
    givens: tuple[Given, ...]
    equations: tuple[EquationStmt, ...]
    finds: tuple[FindItem, ...]
    answers: tuple[Answer, ...]
    system_line: int = 0
    scene: tuple[SceneStmt, ...] = ()
    kinematics: tuple[EquationStmt, ...] = ()  # rectilinear motion: a(t), a(v), a(x) or x(t)
    defines: tuple[EquationStmt, ...] = ()  # derived finds: NAME = expression (scene mode)
    grading: tuple[GradingRule, ...] = ()  # how ``dynsolve grade`` judges answers
    vary: tuple[VaryStmt, ...] = ()  # per-student variants of givens (dynsolve variants)
