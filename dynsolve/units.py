"""The one pint registry, with the textbook conventions (lb is pound-force, g per system).

Built once per process (pint caches its parsed definitions on disk), it knows SI and
US customary units; ``lb`` means pound-force and ``lbm`` pound-mass, as in every
dynamics text. Each unit name looked up is also kept in a small on-disk cache, so a
warm run does not import pint at all. Dimensions are exponent vectors over length,
mass and time (:class:`Dim`); angles are dimensionless.

>>> q = registry().Quantity(40, "lb")
>>> round(q.to("N").magnitude, 2)
177.93
>>> natural_unit(Dim.of("force"), "FPS")
'lb'
"""

from __future__ import annotations

import difflib
import functools
import hashlib
import json
import math
import os
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Literal

if TYPE_CHECKING:
    import pint
    import sympy

System = Literal["SI", "FPS"]

# Base units of each system: every quantity is solved in these coherent units.
BASE_UNITS: dict[System, tuple[str, str, str]] = {
    "SI": ("m", "kg", "s"),
    "FPS": ("ft", "slug", "s"),
}
GRAVITY: dict[System, tuple[str, str]] = {"SI": ("9.81", "m/s^2"), "FPS": ("32.2", "ft/s^2")}

_EXTRA_DEFINITIONS = (
    "lb = pound_force",  # textbook convention: lb is a force
    "lbm = pound",
    "rev = revolution",
)
_BASE_DIMENSIONS = ("[length]", "[mass]", "[time]")


@dataclass(frozen=True)
class Dim:
    """A physical dimension as exponents of length, mass and time.

    >>> Dim.of("force") / Dim.of("mass") == Dim.of("acceleration")
    True
    >>> str(Dim(1, 1, -2))
    'force'
    """

    L: Fraction = Fraction(0)
    M: Fraction = Fraction(0)
    T: Fraction = Fraction(0)

    def __post_init__(self) -> None:
        for name in ("L", "M", "T"):
            exponent = getattr(self, name)
            if type(exponent) is not Fraction:  # (products of dimensions are already)
                object.__setattr__(self, name, Fraction(exponent))

    @staticmethod
    def of(name: str) -> Dim:
        """The dimension called ``name`` in :data:`NAMED_DIMENSIONS`."""
        return NAMED_DIMENSIONS[name]

    def __mul__(self, other: Dim) -> Dim:
        return Dim(self.L + other.L, self.M + other.M, self.T + other.T)

    def __truediv__(self, other: Dim) -> Dim:
        return Dim(self.L - other.L, self.M - other.M, self.T - other.T)

    def __pow__(self, power: Fraction | int) -> Dim:
        p = Fraction(power)
        return Dim(self.L * p, self.M * p, self.T * p)

    @property
    def dimensionless(self) -> bool:
        """True for pure numbers and angles."""
        return self.L == self.M == self.T == 0

    @property
    def name(self) -> str:
        """A textbook name (``force``), else the exponent form (``[length]^2/[time]``)."""
        return DIMENSION_NAMES.get(self, self.formula)

    @property
    def formula(self) -> str:
        """The exponent form, e.g. ``[mass]·[length]/[time]^2``."""
        parts = []
        for label, exp in (("mass", self.M), ("length", self.L), ("time", self.T)):
            if exp == 1:
                parts.append(f"[{label}]")
            elif exp != 0:
                parts.append(f"[{label}]^{exp}")
        return "·".join(parts) or "dimensionless"

    def __str__(self) -> str:
        return self.name


NAMED_DIMENSIONS: dict[str, Dim] = {
    "dimensionless": Dim(),
    "angle": Dim(),
    "length": Dim(1),
    "distance": Dim(1),
    "mass": Dim(0, 1),
    "time": Dim(0, 0, 1),
    "velocity": Dim(1, 0, -1),
    "speed": Dim(1, 0, -1),
    "acceleration": Dim(1, 0, -2),
    "angular_velocity": Dim(0, 0, -1),
    "frequency": Dim(0, 0, -1),
    "angular_acceleration": Dim(0, 0, -2),
    "force": Dim(1, 1, -2),
    "weight": Dim(1, 1, -2),
    "moment": Dim(2, 1, -2),
    "torque": Dim(2, 1, -2),
    "energy": Dim(2, 1, -2),
    "work": Dim(2, 1, -2),
    "power": Dim(2, 1, -3),
    "momentum": Dim(1, 1, -1),
    "impulse": Dim(1, 1, -1),
    "angular_momentum": Dim(2, 1, -1),
    "moment_of_inertia": Dim(2, 1, 0),
    "inertia": Dim(2, 1, 0),
    "stiffness": Dim(0, 1, -2),
    "torsional_stiffness": Dim(2, 1, -2),
    "damping": Dim(0, 1, -1),
    "pressure": Dim(-1, 1, -2),
    "density": Dim(-3, 1, 0),
    "area": Dim(2),
    "volume": Dim(3),
}

# The name shown for a dimension in messages (first one wins for shared dimensions).
DIMENSION_NAMES: dict[Dim, str] = {
    Dim(): "dimensionless",
    Dim(1): "length",
    Dim(0, 1): "mass",
    Dim(0, 0, 1): "time",
    Dim(1, 0, -1): "velocity",
    Dim(1, 0, -2): "acceleration",
    Dim(0, 0, -1): "angular velocity",
    Dim(0, 0, -2): "angular acceleration",
    Dim(1, 1, -2): "force",
    Dim(2, 1, -2): "moment or energy",
    Dim(2, 1, -3): "power",
    Dim(1, 1, -1): "momentum",
    Dim(2, 1, -1): "angular momentum",
    Dim(2, 1, 0): "moment of inertia",
    Dim(0, 1, -2): "stiffness",
    Dim(0, 1, -1): "mass flow or damping",
    Dim(-1, 1, -2): "pressure",
    Dim(-3, 1, 0): "density",
    Dim(2): "area",
    Dim(3): "volume",
}

# Natural output unit per dimension and system (pint-parsable; lb is pound-force).
_NATURAL: dict[Dim, tuple[str, str]] = {
    Dim(): ("", ""),
    Dim(1): ("m", "ft"),
    Dim(0, 1): ("kg", "slug"),
    Dim(0, 0, 1): ("s", "s"),
    Dim(1, 0, -1): ("m/s", "ft/s"),
    Dim(1, 0, -2): ("m/s^2", "ft/s^2"),
    Dim(0, 0, -1): ("rad/s", "rad/s"),
    Dim(0, 0, -2): ("rad/s^2", "rad/s^2"),
    Dim(1, 1, -2): ("N", "lb"),
    Dim(2, 1, -2): ("N*m", "lb*ft"),
    Dim(2, 1, -3): ("W", "ft*lb/s"),
    Dim(1, 1, -1): ("kg*m/s", "slug*ft/s"),
    Dim(2, 1, -1): ("kg*m^2/s", "slug*ft^2/s"),
    Dim(2, 1, 0): ("kg*m^2", "slug*ft^2"),
    Dim(0, 1, -2): ("N/m", "lb/ft"),
    Dim(-1, 1, -2): ("Pa", "lb/ft^2"),
    Dim(-3, 1, 0): ("kg/m^3", "slug/ft^3"),
    Dim(2): ("m^2", "ft^2"),
    Dim(3): ("m^3", "ft^3"),
}
_ENERGY_UNITS = ("J", "ft*lb")
_ENERGY_NAMES = ("T", "U", "V", "E", "W", "K")  # kinetic/potential energy, work
_ENERGY = Dim(2, 1, -2)  # (shared with moments)


def natural_unit(dim: Dim, system: System, name: str = "") -> str:
    """The unit an answer of dimension ``dim`` is shown in when none was requested.

    Moments and energies share a dimension; an unknown whose name starts like an
    energy (T, U, V, E, W) is shown in J (ft·lb), anything else in N·m (lb·ft).

    >>> natural_unit(Dim(2, 1, -2), "SI", "T_1"), natural_unit(Dim(2, 1, -2), "SI", "M")
    ('J', 'N*m')
    """
    column = 0 if system == "SI" else 1
    if dim == _ENERGY and name[:1] in _ENERGY_NAMES:
        return _ENERGY_UNITS[column]
    if dim in _NATURAL:
        return _NATURAL[dim][column]
    base = BASE_UNITS[system]
    parts = []
    for unit, exp in zip(base, (dim.L, dim.M, dim.T), strict=True):
        if exp == 1:
            parts.append(unit)
        elif exp != 0:
            parts.append(f"{unit}^{exp}" if exp.denominator == 1 else f"{unit}^({exp})")
    return "*".join(parts)


def with_unit(value: float, kind: str | Dim, system: System, spec: str = ".4g") -> str:
    """``value`` (in the system's base units) to 4 significant figures (or ``spec``) with
    its unit, as a check or an assumption states it; ``kind`` names its dimension (force,
    velocity, acceleration, energy, moment, length: :data:`NAMED_DIMENSIONS`) or is it.

    >>> with_unit(19.7712, "force", "SI"), with_unit(20.0, "velocity", "FPS")
    ('19.77 N', '20 ft/s')
    >>> with_unit(-3.5, "energy", "FPS"), with_unit(2.0, "acceleration", "SI")
    ('-3.5 ft·lb', '2 m/s²')
    >>> with_unit(740.35372, "energy", "SI", ".7g"), with_unit(2.89, "moment", "FPS")
    ('740.3537 J', '2.89 lb·ft')
    """
    from dynsolve.format import pretty_unit

    dim = kind if isinstance(kind, Dim) else Dim.of(kind)
    unit = natural_unit(dim, system, "T" if kind in ("energy", "work") else "")
    return f"{format(value, spec)} {pretty_unit(unit)}"


@dataclass(frozen=True)
class InSystem:
    """A number in a system's base units, for a template written before the system is
    known: a format spec that names a kind after a space (``{value:.4g force}``) shows
    the value with that kind's unit (:func:`with_unit`); a spec without one, the number
    alone (the template writes its own unit, as ``Δt = {value:.4g} s``).

    >>> "{value:.4g force} > 0".format(value=InSystem(19.7712, "FPS"))
    '19.77 lb > 0'
    >>> "Δt = {value:.3g} s".format(value=InSystem(0.1234, "SI"))
    'Δt = 0.123 s'
    """

    value: float
    system: System

    def __format__(self, spec: str) -> str:
        number, _, kind = spec.partition(" ")
        if not kind:
            return format(self.value, number)
        return with_unit(self.value, kind, self.system, number or ".4g")


def base_unit(dim: Dim, system: System) -> str:
    """The coherent base-unit expression of ``dim`` in ``system`` (what the solver uses).

    >>> base_unit(Dim(1, 1, -2), "FPS")
    'ft*slug*s^-2'
    """
    parts = []
    for unit, exp in zip(BASE_UNITS[system], (dim.L, dim.M, dim.T), strict=True):
        if exp == 1:
            parts.append(unit)
        elif exp != 0:
            parts.append(f"{unit}^({exp})" if exp.denominator != 1 else f"{unit}^{exp}")
    return "*".join(parts) or "dimensionless"


@dataclass(frozen=True)
class UnitInfo:
    """A unit as its size in SI base units (m, kg, s; radian counted as 1) and dimension.

    >>> (unit_named("ft") * unit_named("lb")).dim == Dim.of("moment")
    True
    """

    factor: float
    dim: Dim

    def __mul__(self, other: UnitInfo) -> UnitInfo:
        return UnitInfo(self.factor * other.factor, self.dim * other.dim)

    def __pow__(self, power: Fraction) -> UnitInfo:
        return UnitInfo(self.factor ** float(power), self.dim**power)


ONE = UnitInfo(1.0, Dim())


def unit_named(name: str) -> UnitInfo | None:
    """One unit name (``lb``, ``rpm``, ``kN``) looked up: in this process's memory, then
    in the on-disk cache, then in pint (whose import and registry are paid only on a
    miss). ``None`` when pint does not know the name; ``ValueError`` for a unit
    outside mechanics (a temperature, a current).

    >>> unit_named("kip").factor == 1000 * unit_named("lb").factor
    True
    """
    cache = _unit_cache()
    if name in cache.entries:
        return cache.entries[name]
    info = _pint_lookup(name)
    if info is not None:
        cache.store(name, info)
    return info


def _pint_lookup(name: str) -> UnitInfo | None:
    ureg = registry()
    try:
        quantity = ureg.Quantity(1.0, ureg.Unit(name)).to_base_units()
    except Exception:  # pint raises several types (UndefinedUnitError, …) for unknown names
        return None
    return UnitInfo(float(quantity.magnitude), dim_of_unit(quantity.units))


def system_factor(dim: Dim, system: System) -> float:
    """The size, in SI base units, of the system's coherent unit of ``dim``.

    >>> round(system_factor(Dim.of("force"), "FPS"), 6)
    4.448222
    """
    factor = 1.0
    for name, exp in zip(BASE_UNITS[system], (dim.L, dim.M, dim.T), strict=True):
        if exp:
            info = unit_named(name)
            assert info is not None
            factor *= info.factor ** float(exp)
    return factor


def to_base(magnitude: Fraction, unit: UnitInfo, system: System) -> sympy.Expr:
    """Convert ``magnitude unit`` to the system's coherent base units, exactly.

    Conversion factors are floats (from pint); they are made exact by :func:`_exact`,
    so that exact inputs stay exact (40 lb is 40 slug·ft/s², not 39.99…), and angle
    factors that are rational multiples of π are kept as such (30 rpm is π rad/s).

    >>> to_base(Fraction(30), unit_named("rpm"), "SI")
    pi
    """
    import sympy

    factor = unit.factor / system_factor(unit.dim, system)
    return sympy.Rational(magnitude.numerator, magnitude.denominator) * _exact(factor)


def from_base(value: float, unit: UnitInfo, system: System) -> float:
    """Convert a value in the system's base units into ``unit`` (of the same dimension).

    >>> round(from_base(1.0, unit_named("N"), "FPS"), 4)
    4.4482
    """
    return value * system_factor(unit.dim, system) / unit.factor


@functools.cache
def registry() -> pint.UnitRegistry:
    """The process-wide registry, built once; pint caches its parsed definitions on disk."""
    import pint

    try:
        ureg = pint.UnitRegistry(cache_folder=":auto:", on_redefinition="ignore")
    except OSError:  # unwritable cache folder: build without the disk cache
        ureg = pint.UnitRegistry(on_redefinition="ignore")
    for definition in _EXTRA_DEFINITIONS:
        ureg.define(definition)
    return ureg


def dim_of_unit(unit: pint.Unit) -> Dim:
    """The :class:`Dim` of a pint unit; raises ``ValueError`` for non-mechanical units.

    >>> dim_of_unit(registry().Unit("ft*lb"))
    Dim(L=Fraction(2, 1), M=Fraction(1, 1), T=Fraction(-2, 1))
    """
    dimensionality = unit.dimensionality
    extra = [d for d in dimensionality if d not in _BASE_DIMENSIONS]
    if extra:
        raise ValueError(f"dimension {extra[0]} is outside mechanics (length, mass, time)")
    return Dim(
        *(Fraction(dimensionality.get(d, 0)).limit_denominator(12) for d in _BASE_DIMENSIONS)
    )


class _UnitCache:
    """Unit lookups kept on disk between runs, so a warm run need not import pint.

    The file holds plain JSON (name → factor and dimension exponents), keyed by the
    pint version and dynsolve's own definitions; a missing, unreadable or corrupt file
    is simply rebuilt, and an unwritable folder only costs speed.
    """

    def __init__(self, path: Path | None) -> None:
        self.path = path
        self.entries: dict[str, UnitInfo] = {}
        if path is not None:
            self.entries = _read_cache(path)

    def store(self, name: str, info: UnitInfo) -> None:
        self.entries[name] = info
        if self.path is None:
            return
        data = {
            n: [i.factor, str(i.dim.L), str(i.dim.M), str(i.dim.T)] for n, i in self.entries.items()
        }
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            temporary = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
            temporary.write_text(json.dumps(data), encoding="utf-8")
            os.replace(temporary, self.path)
        except OSError:
            self.path = None  # read-only cache folder: keep working without it


def _read_cache(path: Path) -> dict[str, UnitInfo]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        return {
            str(name): UnitInfo(float(factor), Dim(Fraction(L), Fraction(M), Fraction(T)))
            for name, (factor, L, M, T) in data.items()
        }
    except (OSError, ValueError, TypeError, AttributeError):
        return {}


@functools.cache
def _unit_cache() -> _UnitCache:
    folder = os.environ.get("DYNSOLVE_CACHE_DIR")
    if folder == "":
        return _UnitCache(None)  # DYNSOLVE_CACHE_DIR= (empty) turns the cache off
    if folder is None:
        import platformdirs

        folder = platformdirs.user_cache_dir("dynsolve")
    key = hashlib.sha256("\n".join((*_EXTRA_DEFINITIONS, _pint_install())).encode()).hexdigest()[
        :12
    ]
    return _UnitCache(Path(folder) / f"units-v2-{key}.json")


def _pint_install() -> str:
    """Where pint is installed and when: a new pint (or a reinstall) starts a new cache.

    Cheaper than ``importlib.metadata.version`` (which imports the metadata machinery and
    scans the installed distributions) and pint itself is not imported.

    >>> "pint" in _pint_install()
    True
    """
    import importlib.util

    spec = importlib.util.find_spec("pint")
    origin = spec.origin if spec is not None else None
    if origin is None:
        return "pint: not found"
    try:
        stamp = os.stat(origin).st_mtime_ns
    except OSError:
        stamp = 0
    return f"{origin}:{stamp}"


def _exact(factor: float) -> sympy.Expr:
    """A float conversion factor as an exact number: a short decimal, a simple fraction,
    a rational multiple of π, or else the decimal to 15 significant figures.

    >>> _exact(0.017453292519943295), _exact(0.3048), _exact(1 / 12)
    (pi/180, 381/1250, 1/12)
    """
    import sympy

    decimal = f"{factor:.15g}"
    if len(decimal.replace(".", "").replace("-", "").lstrip("0")) <= 10:
        return sympy.Rational(decimal)
    for multiple, limit, tolerance in ((1, 1_000_000, 1e-14), (math.pi, 100_000, 1e-13)):
        ratio = Fraction(factor / multiple).limit_denominator(limit)
        if abs(float(ratio) * multiple - factor) <= tolerance * abs(factor):
            exact = sympy.Rational(ratio.numerator, ratio.denominator)
            return exact * sympy.pi if multiple != 1 else exact
    return sympy.Rational(decimal)


def known_unit_names() -> list[str]:
    """Names and symbols the registry knows, common engineering units first."""
    ureg = registry()
    names = list(COMMON_UNITS)
    names += [n for n in ureg._units if n not in COMMON_UNITS]
    return names


COMMON_UNITS = (
    "m", "mm", "cm", "km", "kg", "g", "Mg", "s", "min", "h", "N", "kN", "J", "kJ", "W", "kW",
    "Pa", "kPa", "MPa", "rad", "deg", "rev", "rpm", "ft", "in", "mi", "yd", "slug", "lb", "lbf",
    "lbm", "kip", "psi", "hp", "Hz",
)  # fmt: skip


def suggest_unit(name: str) -> str:
    """A "did you mean" hint for an unknown unit name, or an empty string.

    >>> suggest_unit("kgs")
    "did you mean 'kg'?"
    """
    matches = difflib.get_close_matches(name, COMMON_UNITS, n=1, cutoff=0.6)
    if not matches:
        matches = difflib.get_close_matches(name, known_unit_names(), n=1, cutoff=0.75)
    return f"did you mean '{matches[0]}'?" if matches else ""
