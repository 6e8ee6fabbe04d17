"""Mass moments of inertia of bodies about the z axis through G (the planar-kinetics I).

Planar kinetics needs only the moment of inertia about the axis perpendicular to the
plane of motion (z). This module gives it, as exact sympy expressions, for

* the common shapes of the textbook tables (:data:`SHAPES`; Hibbeler, *Engineering
  Mechanics: Dynamics* 12e, inside back cover; Meriam & Kraige, *Dynamics*, table D/4),
  each about the z axis through its own mass centre G, as each entry's ``axis`` states;
* a radius of gyration (:func:`from_gyration`), moved between G and another point P by
  the parallel-axis theorem (:func:`parallel_axis`, :func:`to_G`);
* composite bodies of parts and holes (:func:`composite`), with the textbook's
  one-line-per-part derivation as plain data (:class:`Term`) and as text.

Every quantity is a ``sympy.Expr`` (symbols or exact numbers) in one coherent unit
system: masses in kg (slug), lengths in m (ft), densities in kg/m³ (slug/ft³), I in
kg·m² (slug·ft²). Spec text is never parsed here; the scene front end builds the numbers.

>>> import sympy
>>> m, R = sympy.symbols("m R", positive=True)
>>> parallel_axis(inertia_about_G("disk", m, (R,)), m, R)  # disk about a rim point
3*R**2*m/2
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction

import sympy

from dynsolve.numbers import tidy
from dynsolve.shown import formula_text
from dynsolve.units import Dim

Number = sympy.Expr | int | Fraction | float
"""What the functions accept for a quantity: a sympy expression, or a Python number."""

SIZE_DIM = Dim.of("length")
"""Dimension of every size parameter and of a thickness."""
DENSITY_DIM = Dim.of("density")
"""Dimension of the density given to :func:`mass_from_density`."""
INERTIA_DIM = Dim.of("moment_of_inertia")
"""Dimension of every moment of inertia returned here."""

MASS = sympy.Symbol("m", positive=True)
"""The mass symbol used in each shape's formula (:attr:`Shape.inertia`)."""


def _symbol(name: str) -> sympy.Symbol:
    return sympy.Symbol(name, positive=True)


_L, _R, _r, _a, _b, _c, _t = (_symbol(n) for n in ("L", "R", "r", "a", "b", "c", "t"))


@dataclass(frozen=True)
class Shape:
    """One entry of the shape table: I about the z axis through G, and the volume.

    ``inertia`` is I_G in the symbols :data:`MASS` (``m``) and the size parameters
    named by ``sizes``; ``volume`` is in the sizes and, when ``thickness`` names one,
    the out-of-plane dimension (a plate's thickness, a cylinder's length, a block's
    depth), or ``None`` when a density cannot give the mass (``no_volume`` says why).

    >>> SHAPES["hollow"].inertia
    m*(R**2 + r**2)/2
    >>> SHAPES["disk"].volume, SHAPES["disk"].thickness
    (pi*R**2*t, 't')
    """

    key: str
    title: str
    words: tuple[str, ...]
    sizes: tuple[str, ...]
    axis: str
    inertia: sympy.Expr
    volume: sympy.Expr | None
    thickness: str | None = None
    thickness_meaning: str = ""
    no_volume: str = ""

    @property
    def size_symbols(self) -> tuple[sympy.Symbol, ...]:
        """The symbols of the size parameters, as used in :attr:`inertia` and :attr:`volume`.

        >>> SHAPES["plate"].size_symbols
        (a, b)
        """
        return tuple(_symbol(name) for name in self.sizes)


_SHAPE_LIST = (
    Shape(
        "rod", "slender rod",
        ("rod", "slender rod", "thin rod", "bar", "slender bar"),
        ("L",),
        "z axis through G perpendicular to the rod",
        _L**2 * MASS / 12,
        None,
        no_volume="a slender rod's volume needs its cross-section; give the rod's mass",
    ),
    Shape(
        "ring", "thin ring",
        ("ring", "thin ring", "hoop"),
        ("R",),
        "z axis through the centre perpendicular to the plane of the ring",
        MASS * _R**2,
        None,
        no_volume="a thin ring's volume needs its cross-section; give the ring's mass",
    ),
    Shape(
        "disk", "solid disk",
        ("disk", "disc", "solid disk", "solid disc", "cylinder", "solid cylinder"),
        ("R",),
        "z axis = the axis of the disk or cylinder (through G)",
        MASS * _R**2 / 2,
        sympy.pi * _R**2 * _t,
        "t", "thickness of the disk, or length of the cylinder",
    ),
    Shape(
        "hollow", "hollow cylinder",
        ("hollow", "hollow cylinder", "hollow disk", "hollow disc", "annulus",
         "annular disk", "tube"),
        ("R", "r"),
        "z axis = the axis of the hollow cylinder (through G); R outer, r inner radius",
        MASS * (_R**2 + _r**2) / 2,
        sympy.pi * (_R**2 - _r**2) * _t,
        "t", "thickness of the annulus, or length of the hollow cylinder",
    ),
    Shape(
        "sphere", "solid sphere",
        ("sphere", "solid sphere", "ball"),
        ("R",),
        "any diameter (z axis through the centre)",
        2 * MASS * _R**2 / 5,
        4 * sympy.pi * _R**3 / 3,
    ),
    Shape(
        "shell", "thin spherical shell",
        ("shell", "spherical shell", "thin spherical shell", "thin walled sphere",
         "thin sphere"),
        ("R",),
        "any diameter (z axis through the centre)",
        2 * MASS * _R**2 / 3,
        4 * sympy.pi * _R**2 * _t,
        "t", "wall thickness of the shell",
    ),
    Shape(
        "plate", "thin rectangular plate",
        ("plate", "thin plate", "rectangular plate", "thin rectangular plate"),
        ("a", "b"),
        "z axis through G perpendicular to the a × b plate",
        MASS * (_a**2 + _b**2) / 12,
        _a * _b * _t,
        "t", "thickness of the plate",
    ),
    Shape(
        "block", "rectangular block",
        ("block", "rectangular block", "box", "rectangular prism"),
        ("a", "b"),
        "z axis through G perpendicular to the a × b face (the plane of motion)",
        MASS * (_a**2 + _b**2) / 12,
        _a * _b * _c,
        "c", "depth of the block, perpendicular to the plane of motion",
    ),
    Shape(
        "particle", "particle",
        ("particle", "point mass"),
        (),
        "any axis through the particle",
        sympy.Integer(0),
        None,
        no_volume="a particle has no volume; give its mass",
    ),
)  # fmt: skip

SHAPES: dict[str, Shape] = {shape.key: shape for shape in _SHAPE_LIST}
"""The shape table, by key (``cylinder`` is a word of ``disk``: see :func:`shape_named`)."""

_WORDS: dict[str, Shape] = {word: shape for shape in _SHAPE_LIST for word in shape.words}


def _normal(word: str) -> str:
    return " ".join(word.lower().replace("-", " ").replace("_", " ").split())


def shape_named(word: str | Shape) -> Shape:
    """The shape a spec word names (key or any of its words; case, ``-`` and ``_`` ignored).

    >>> shape_named("Solid cylinder").key, shape_named("thin-walled sphere").key
    ('disk', 'shell')
    >>> shape_named("disck")
    Traceback (most recent call last):
    ...
    ValueError: unknown shape 'disck' (did you mean 'disk'?); known shapes: rod, ring, ...
    """
    if isinstance(word, Shape):
        return word
    shape = _WORDS.get(_normal(word))
    if shape is not None:
        return shape
    close = difflib.get_close_matches(_normal(word), list(_WORDS), n=1, cutoff=0.6)
    hint = f" (did you mean '{close[0]}'?)" if close else ""
    known = ", ".join(SHAPES)
    raise ValueError(f"unknown shape '{word}'{hint}; known shapes: {known}")


def _expr(value: Number, what: str) -> sympy.Expr:
    """A quantity as a sympy expression; text is refused (spec text is never sympified)."""
    if isinstance(value, sympy.Expr):
        return value
    if isinstance(value, bool) or not isinstance(value, int | float | Fraction):
        raise TypeError(f"{what} must be a sympy expression or a number, not {value!r}")
    if isinstance(value, Fraction):
        return sympy.Rational(value.numerator, value.denominator)
    return sympy.Integer(value) if isinstance(value, int) else sympy.Float(value)


def _not_negative(value: sympy.Expr, what: str) -> sympy.Expr:
    if value.is_negative:
        raise ValueError(f"{what} must not be negative, got {sympy.sstr(value)}")
    return value


def _sizes(shape: Shape, sizes: Sequence[Number]) -> tuple[sympy.Expr, ...]:
    """The sizes checked against the shape: their number, signs, and inner < outer."""
    if isinstance(sizes, str) or not isinstance(sizes, Sequence):
        raise TypeError(f"sizes must be a sequence of numbers or expressions, not {sizes!r}")
    if len(sizes) != len(shape.sizes):
        wanted = ", ".join(shape.sizes) or "none"
        got = ", ".join(sympy.sstr(_expr(s, "a size")) for s in sizes) or "none"
        raise ValueError(
            f"a {shape.title} takes {len(shape.sizes)} size(s) ({wanted}), got {len(sizes)} ({got})"
        )
    values = tuple(
        _not_negative(_expr(size, f"size {name}"), f"the {shape.title}'s {name}")
        for name, size in zip(shape.sizes, sizes, strict=True)
    )
    if shape.key == "hollow" and (values[1] - values[0]).is_positive:
        raise ValueError(
            f"the hollow cylinder's inner radius r = {sympy.sstr(values[1])} "
            f"exceeds its outer radius R = {sympy.sstr(values[0])}"
        )
    return values


def _substitution(shape: Shape, mass: sympy.Expr, sizes: tuple[sympy.Expr, ...]) -> dict:
    return {MASS: mass, **dict(zip(shape.size_symbols, sizes, strict=True))}


def inertia_about_G(shape: str | Shape, mass: Number, sizes: Sequence[Number]) -> sympy.Expr:
    """I_G of a homogeneous shape about the z axis through its G (see :data:`SHAPES`).

    ``sizes`` are the shape's size parameters in the order of ``Shape.sizes``
    (``hollow``: outer R then inner r; ``plate`` and ``block``: a then b).

    >>> inertia_about_G("rod", 10, (sympy.Rational("0.6"),))
    3/10
    >>> m, a, b = sympy.symbols("m a b")
    >>> inertia_about_G("plate", m, (a, b))
    m*(a**2 + b**2)/12
    """
    found = shape_named(shape)
    values = _sizes(found, sizes)
    m = _not_negative(_expr(mass, "mass"), "a mass (give a cut-out as a hole)")
    return found.inertia.xreplace(_substitution(found, m, values))


def from_gyration(mass: Number, k: Number) -> sympy.Expr:
    """I = m k², for a radius of gyration k about the same axis as the I wanted.

    >>> from_gyration(50, sympy.Rational("0.3"))
    9/2
    """
    m, radius = _expr(mass, "mass"), _expr(k, "radius of gyration")
    _not_negative(radius, "a radius of gyration")
    return m * radius**2


def parallel_axis(I_G: Number, mass: Number, d: Number) -> sympy.Expr:
    """I_P = I_G + m d²: from the z axis through G to the parallel axis through P, d away.

    >>> m, L = sympy.symbols("m L")
    >>> parallel_axis(m * L**2 / 12, m, L / 2)  # slender rod about its end
    L**2*m/3
    """
    return _expr(I_G, "I_G") + _expr(mass, "mass") * _expr(d, "distance d") ** 2


def to_G(I_P: Number, mass: Number, d: Number) -> sympy.Expr:
    """I_G = I_P − m d²: an I (or m k²) about P moved to the parallel axis through G.

    Only this direction subtracts, and only to G: I is least about G. A numeric
    I_P smaller than m d² is refused.

    >>> to_G(4, 2, 1)
    2
    >>> to_G(1, 2, 1)
    Traceback (most recent call last):
    ...
    ValueError: I_P = 1 is less than m d² = 2: no body has a negative I_G (check I_P, m and d)
    """
    moved = _expr(mass, "mass") * _expr(d, "distance d") ** 2
    result = _expr(I_P, "I_P") - moved
    if result.is_negative:
        raise ValueError(
            f"I_P = {sympy.sstr(_expr(I_P, 'I_P'))} is less than m d² = {sympy.sstr(moved)}: "
            "no body has a negative I_G (check I_P, m and d)"
        )
    return result


def mass_from_density(
    shape: str | Shape, density: Number, sizes: Sequence[Number], thickness: Number | None = None
) -> sympy.Expr:
    """m = ρ V for a homogeneous shape; ``thickness`` is the out-of-plane dimension
    (``Shape.thickness``: a plate's or disk's thickness, a cylinder's length, a block's
    depth c, a shell's wall), required by those shapes and refused by the others.

    >>> rho, R, t = sympy.symbols("rho R t")
    >>> mass_from_density("disk", rho, (R,), t)
    pi*R**2*rho*t
    >>> mass_from_density("sphere", 8000, (sympy.Rational("0.1"),))
    32*pi/3
    >>> mass_from_density("rod", 7850, (1,))
    Traceback (most recent call last):
    ...
    ValueError: a density cannot give the mass of a slender rod: a slender rod's volume needs its cross-section; give the rod's mass
    """  # noqa: E501
    found = shape_named(shape)
    if found.volume is None:
        raise ValueError(f"a density cannot give the mass of a {found.title}: {found.no_volume}")
    values = _sizes(found, sizes)
    rho = _not_negative(_expr(density, "density"), "a density")
    substitution = dict(zip(found.size_symbols, values, strict=True))
    if found.thickness is not None:
        if thickness is None:
            raise ValueError(
                f"the volume of a {found.title} needs its {found.thickness_meaning} "
                f"({found.thickness})"
            )
        depth = _not_negative(_expr(thickness, "thickness"), f"the {found.thickness_meaning}")
        substitution[_symbol(found.thickness)] = depth
    elif thickness is not None:
        raise ValueError(f"a {found.title} takes no thickness: its volume follows from its sizes")
    return rho * found.volume.xreplace(substitution)


@dataclass(frozen=True)
class Part:
    """One part of a composite body: a shape of some mass, its own G at ``position``
    (body coordinates in the plane of motion), added, or subtracted when ``hole``.

    ``mass`` is the mass of the material (removed, for a hole), never negative.
    ``given_I_G`` overrides the shape formula for a part known only by its I_G or its
    radius of gyration (use shape ``particle``, no sizes, and :func:`from_gyration`).
    Shape words are resolved to keys and numbers to sympy on construction.

    >>> Part("hole", "disk", 2, (1,), (0, 0), hole=True).signed_mass
    -2
    """

    name: str
    shape: str
    mass: sympy.Expr
    sizes: tuple[sympy.Expr, ...] = ()
    position: tuple[sympy.Expr, sympy.Expr] = (sympy.Integer(0), sympy.Integer(0))
    hole: bool = False
    given_I_G: sympy.Expr | None = None

    def __post_init__(self) -> None:
        found = shape_named(self.shape)
        mass = _not_negative(
            _expr(self.mass, f"the mass of {self.name}"),
            f"the mass of {self.name} (give a cut-out as a hole)",
        )
        try:
            sizes = _sizes(found, tuple(self.sizes))
        except ValueError as error:
            raise ValueError(f"{self.name}: {error}") from None
        if len(self.position) != 2:
            raise ValueError(f"{self.name}: a position is two coordinates (x, y)")
        position = tuple(_expr(c, f"a coordinate of {self.name}") for c in self.position)
        object.__setattr__(self, "shape", found.key)
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "sizes", sizes)
        object.__setattr__(self, "position", position)
        if self.given_I_G is not None:
            given = _expr(self.given_I_G, f"the I_G of {self.name}")
            object.__setattr__(self, "given_I_G", _not_negative(given, f"the I_G of {self.name}"))

    @property
    def sign(self) -> int:
        """+1 for material, −1 for a hole.

        >>> Part("a", "particle", 1).sign
        1
        """
        return -1 if self.hole else 1

    @property
    def signed_mass(self) -> sympy.Expr:
        """The mass counted in the composite: negative for a hole.

        >>> Part("a", "particle", 3).signed_mass
        3
        """
        return self.sign * self.mass

    @property
    def I_G(self) -> sympy.Expr:
        """The part's own I about the z axis through its G (positive, even for a hole).

        >>> Part("disk", "cylinder", 4, (sympy.Rational(1, 2),)).I_G
        1/2
        """
        if self.given_I_G is not None:
            return self.given_I_G
        return inertia_about_G(self.shape, self.mass, self.sizes)

    def formula(self) -> tuple[sympy.Expr, dict[sympy.Symbol, sympy.Expr]]:
        """The I_G formula in the table's symbols and the part's values for them.

        >>> Part("d", "disk", 4, (2,)).formula()
        (R**2*m/2, {m: 4, R: 2})
        """
        if self.given_I_G is not None:
            return self.given_I_G, {}
        found = SHAPES[self.shape]
        return found.inertia, _substitution(found, self.mass, self.sizes)


@dataclass(frozen=True)
class Term:
    """One part's line of a composite's I about a point, as plain data for any renderer.

    The part contributes ``sign * (inertia + transfer)``: its own I_G (``formula`` with
    ``values`` substituted) and the parallel-axis term ``transfer`` = m d², where
    ``distance`` d is from the part's G to the point.

    >>> body = composite([Part("disk", "disk", 4, (1,))])
    >>> term = body.terms((1, 0))[0]
    >>> term.inertia, term.transfer, term.total
    (2, 4, 6)
    >>> term.text(unit="kg·m²")
    'disk: I = 4*1^2/2 + 4*1^2 = 6 kg·m²'
    """

    name: str
    sign: int
    mass: sympy.Expr
    distance: sympy.Expr
    inertia: sympy.Expr
    transfer: sympy.Expr
    formula: sympy.Expr
    values: tuple[tuple[sympy.Symbol, sympy.Expr], ...]

    @property
    def total(self) -> sympy.Expr:
        """The signed contribution, ±(I_G + m d²).

        >>> composite([Part("a", "ring", 2, (1,))]).terms()[0].total
        2
        """
        return self.sign * (self.inertia + self.transfer)

    def inertia_shown(self, digits: int = 4) -> sympy.Expr:
        """The I_G formula with the values put in but not evaluated (for sstr or latex),
        numbers rounded to ``digits`` significant figures.

        >>> term = composite([Part("d", "disk", sympy.pi * 5, (sympy.Rational(1, 4),))]).terms()[0]
        >>> sympy.sstr(term.inertia_shown()), sympy.latex(term.inertia_shown())
        ('15.71*0.25**2/2', '\\\\frac{15.71 \\\\cdot 0.25^{2}}{2}')
        """
        if not self.values:
            return _unevaluated(self.formula, digits)
        return self.formula.xreplace({s: _unevaluated(v, digits) for s, v in self.values})

    def transfer_shown(self, digits: int = 4) -> sympy.Expr:
        """m d² with the values put in but not evaluated, rounded to ``digits`` figures.

        >>> body = composite([Part("p", "particle", 2)])
        >>> sympy.sstr(body.terms((sympy.Rational(1, 2), 0))[0].transfer_shown())
        '2*0.5**2'
        """
        mass = _unevaluated(self.mass, digits)
        if self.distance.is_number:
            return sympy.Mul(
                mass, sympy.Pow(_unevaluated(self.distance, digits), 2), evaluate=False
            )
        return sympy.Mul(mass, _unevaluated(sympy.expand(self.distance**2), digits), evaluate=False)

    def text(self, unit: str = "", digits: int = 4) -> str:
        """The textbook line, ``name: I = I_G + m d² = value unit`` (a hole's negated),
        as :func:`~dynsolve.shown.formula_text` writes them; zero terms are left out.

        >>> body = composite([Part("h", "particle", 1, position=(3, 4), hole=True),
        ...                   Part("b", "particle", 5)])
        >>> body.terms((0, 0))[0].text()
        'h: I = -(1*5^2) = -25'
        """
        pieces = []
        if self.inertia != 0:
            pieces.append(formula_text(self.inertia_shown(digits)))
        if self.transfer != 0:
            pieces.append(formula_text(self.transfer_shown(digits)))
        body = " + ".join(pieces) or "0"
        if self.sign < 0 and pieces:
            body = f"-({body})"
        suffix = f" {unit}" if unit else ""
        return f"{self.name}: I = {body} = {_number_text(self.total, digits)}{suffix}"


@dataclass(frozen=True)
class Composite:
    """A composite body: total ``mass``, mass centre ``G`` and ``I_G`` about the z axis
    through G, all in the parts' body coordinates.

    >>> body = composite([Part("p", "particle", 1, position=(0, 0)),
    ...                   Part("q", "particle", 1, position=(2, 0))])
    >>> body.mass, body.G, body.I_G, body.about((0, 0))
    (2, (1, 0), 2, 4)
    """

    parts: tuple[Part, ...]
    mass: sympy.Expr
    G: tuple[sympy.Expr, sympy.Expr]
    I_G: sympy.Expr

    def about(self, point: Sequence[Number]) -> sympy.Expr:
        """I about the z axis through ``point`` (x, y): I_G + m |point − G|².

        >>> composite([Part("rod", "rod", 3, (2,), (1, 0))]).about((0, 0))
        4
        """
        x, y = _point(point)
        return self.I_G + self.mass * ((x - self.G[0]) ** 2 + (y - self.G[1]) ** 2)

    def terms(self, point: Sequence[Number] | None = None) -> tuple[Term, ...]:
        """One :class:`Term` per part for I about ``point`` (default: the composite's G);
        their totals add up to :meth:`about` of that point.

        >>> [t.total for t in composite([Part("a", "ring", 2, (1,), (1, 0))]).terms((0, 0))]
        [4]
        """
        x, y = self.G if point is None else _point(point)
        lines = []
        for part in self.parts:
            squared = (part.position[0] - x) ** 2 + (part.position[1] - y) ** 2
            formula, values = part.formula()
            lines.append(
                Term(
                    name=part.name,
                    sign=part.sign,
                    mass=part.mass,
                    distance=sympy.sqrt(squared),
                    inertia=part.I_G,
                    transfer=part.mass * squared,
                    formula=formula,
                    values=tuple(values.items()),
                )
            )
        return tuple(lines)

    def derivation(
        self, point: Sequence[Number] | None = None, unit: str = "", digits: int = 4
    ) -> list[str]:
        """The textbook lines, one per part, for I about ``point`` (default G).

        >>> composite([Part("a", "ring", 2, (1,), (1, 0))]).derivation((0, 0), "kg·m²")
        ['a: I = 2*1^2 + 2*1^2 = 4 kg·m²']
        """
        return [term.text(unit, digits) for term in self.terms(point)]

    def text(
        self,
        point: Sequence[Number] | None = None,
        unit: str = "",
        digits: int = 4,
        label: str | None = None,
    ) -> str:
        """The derivation lines and the sum, ``label = t1 + t2 - t3 = value unit``
        (``label`` defaults to ``I_G``, or ``I`` about another point).

        >>> body = composite([Part("a", "particle", 1, position=(1, 0)),
        ...                   Part("b", "particle", 1, position=(-1, 0))])
        >>> print(body.text())
        a: I = 1*1^2 = 1
        b: I = 1*1^2 = 1
        I_G = 1 + 1 = 2
        """
        terms = self.terms(point)
        label = label or ("I_G" if point is None else "I")
        value = self.I_G if point is None else self.about(point)
        sums = _number_text(terms[0].total, digits)
        for term in terms[1:]:
            negative = bool(term.total.is_negative) or (term.sign < 0 and not term.total.is_number)
            size = -term.total if negative else term.total
            sums += f" {'-' if negative else '+'} {_number_text(size, digits)}"
        suffix = f" {unit}" if unit else ""
        lines = [term.text(unit, digits) for term in terms]
        if len(terms) > 1:
            lines.append(f"{label} = {sums} = {_number_text(value, digits)}{suffix}")
        else:
            lines.append(f"{label} = {_number_text(value, digits)}{suffix}")
        return "\n".join(lines)


def _point(point: Sequence[Number]) -> tuple[sympy.Expr, sympy.Expr]:
    if len(point) != 2:
        raise ValueError("a point is two coordinates (x, y)")
    return _expr(point[0], "a coordinate"), _expr(point[1], "a coordinate")


def composite(parts: Iterable[Part]) -> Composite:
    """Mass, mass centre and I_G (z axis through the composite's G) of parts and holes.

    G = Σ ±m_i r_i / Σ ±m_i, and I_G = Σ ±(I_Gi + m_i d_i²) with d_i from the part's G
    to the composite's G; holes count negative.

    >>> disk = Part("disk", "disk", 4, (2,))
    >>> hole = Part("hole", "disk", 1, (1,), hole=True)
    >>> body = composite([disk, hole])
    >>> body.mass, body.G, body.I_G
    (3, (0, 0), 15/2)
    >>> composite([hole])
    Traceback (most recent call last):
    ...
    ValueError: the holes (hole: 1) are at least as heavy as the solid parts (0): a hole cannot weigh as much as the body it is cut from
    """  # noqa: E501
    parts = tuple(parts)
    if not parts:
        raise ValueError("a composite body needs at least one part")
    for part in parts:
        if not isinstance(part, Part):
            raise TypeError(f"a composite is made of Part objects, not {part!r}")
    mass = sympy.Add(*(part.signed_mass for part in parts))
    if mass.is_positive is False:
        holes = [part for part in parts if part.hole]
        if holes:
            solid = sympy.Add(*(part.mass for part in parts if not part.hole))
            listed = ", ".join(f"{h.name}: {sympy.sstr(h.mass)}" for h in holes)
            raise ValueError(
                f"the holes ({listed}) are at least as heavy as the solid parts "
                f"({sympy.sstr(solid)}): a hole cannot weigh as much as the body it is cut from"
            )
        raise ValueError("a composite body needs a mass: all its parts are massless")
    G = tuple(
        tidy(sympy.Add(*(part.signed_mass * part.position[i] for part in parts)) / mass)
        for i in (0, 1)
    )
    # each d² tidied on its own (a pendulum's parts at an angle: sin² + cos² = 1 per part),
    # not the whole sum at once, whose tidying costs many times more
    inertia = sympy.Add(
        *(
            part.sign
            * (
                part.I_G
                + part.mass * tidy((part.position[0] - G[0]) ** 2 + (part.position[1] - G[1]) ** 2)
            )
            for part in parts
        )
    )
    return Composite(parts, mass, (G[0], G[1]), inertia)


def _shown_number(value: sympy.Expr, digits: int) -> sympy.Expr:
    """A real number rounded to ``digits`` significant figures for display (10, 0.25, 15.71)."""
    if value.is_Integer or not value.is_number or not value.is_real:
        return value
    text = f"{float(value):.{digits}g}"
    if "e" not in text and "." not in text:
        return sympy.Integer(text)
    mantissa = text.split("e")[0].replace("-", "").replace(".", "").lstrip("0")
    return sympy.Float(text, max(len(mantissa), 1))


def _unevaluated(value: sympy.Expr, digits: int) -> sympy.Expr:
    return sympy.UnevaluatedExpr(_shown_number(value, digits))


def _number_text(value: sympy.Expr, digits: int) -> str:
    return formula_text(_shown_number(value, digits))
