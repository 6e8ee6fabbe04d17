"""Unit conventions: lb is pound-force, g per system, exact conversions (DESIGN.md conventions)."""

from fractions import Fraction

import pytest
import sympy

from dynsolve.quantities import convert, unit_info
from dynsolve.units import (
    Dim,
    _UnitCache,
    dim_of_unit,
    natural_unit,
    registry,
    suggest_unit,
    to_base,
    unit_named,
)


def test_registry_is_built_once():
    assert registry() is registry()


def test_lb_is_pound_force_and_lbm_pound_mass():
    ureg = registry()
    assert dim_of_unit(ureg.Unit("lb")) == Dim.of("force")
    assert dim_of_unit(ureg.Unit("lbm")) == Dim.of("mass")
    # 1 lbf = 4.4482216152605 N exactly (NIST SP 811); 1 lbm = 0.45359237 kg.
    assert ureg.Quantity(1, "lb").to("N").magnitude == pytest.approx(4.4482216152605, rel=1e-14)
    assert ureg.Quantity(1, "lbm").to("kg").magnitude == pytest.approx(0.45359237, rel=1e-14)


def test_a_40_lb_weight_is_1_242_slug():
    # m = W/g = 40 lb / 32.2 ft/s^2 = 1.2422 slug (textbook convention g = 32.2 ft/s^2).
    weight = to_base(Fraction(40), unit_info("lb"), "FPS")
    assert weight == 40  # exact: lb is the FPS force unit slug*ft/s^2
    assert float(weight / sympy.Rational("32.2")) == pytest.approx(1.242, abs=5e-4)


def test_15_ft_lb_is_20_34_joule():
    # 15 ft*lb = 15 * 0.3048 m * 4.4482216152605 N = 20.337 J.
    value = to_base(Fraction(15), unit_info("ft*lb"), "SI")
    assert float(value) == pytest.approx(20.34, abs=5e-3)
    assert float(to_base(Fraction(15), unit_info("lb*ft"), "SI")) == float(value)


def test_30_rpm_is_pi_rad_per_s_exactly():
    # 30 rev/min = 30 * 2*pi / 60 rad/s = pi rad/s.
    assert to_base(Fraction(30), unit_info("rpm"), "SI") == sympy.pi
    assert to_base(Fraction(30), unit_info("rev/min"), "FPS") == sympy.pi


@pytest.mark.parametrize(
    ("value", "unit", "system", "expected"),
    [
        (45, "deg", "SI", sympy.pi / 4),
        (10, "rev", "SI", 20 * sympy.pi),
        (2, "Mg", "SI", 2000),
        (10, "mm", "SI", sympy.Rational(1, 100)),
        (1, "ft", "SI", sympy.Rational("0.3048")),
        (12, "in", "FPS", 1),
        (1, "kip", "FPS", 1000),
        (60, "mi/h", "FPS", 88),  # 60 mi/h = 88 ft/s
        (36, "km/h", "SI", 10),
    ],
)
def test_exact_conversions(value, unit, system, expected):
    assert sympy.nsimplify(to_base(Fraction(value), unit_info(unit), system) - expected) == 0


def test_mixed_systems_convert_both_ways():
    # 1 slug = 14.5939 kg; a slug in SI base units and back.
    kg = float(to_base(Fraction(1), unit_info("slug"), "SI"))
    assert kg == pytest.approx(14.5939029, rel=1e-8)
    assert convert(kg, "slug", "SI") == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize(
    ("dim", "system", "name", "unit"),
    [
        ("force", "SI", "T", "N"),
        ("force", "FPS", "T", "lb"),
        ("acceleration", "FPS", "a", "ft/s^2"),
        ("angular_acceleration", "SI", "alpha", "rad/s^2"),
        ("moment", "SI", "M", "N*m"),
        ("energy", "SI", "T_1", "J"),
        ("energy", "FPS", "U_12", "ft*lb"),
        ("moment", "FPS", "M_O", "lb*ft"),
        ("mass", "FPS", "m", "slug"),
        ("moment_of_inertia", "SI", "I_G", "kg*m^2"),
    ],
)
def test_natural_units(dim, system, name, unit):
    assert natural_unit(Dim.of(dim), system, name) == unit
    # every natural unit is a string pint parses (with lb meaning pound-force)
    assert dim_of_unit(registry().Unit(unit)) == Dim.of(dim)


def test_unknown_unit_suggestion():
    assert suggest_unit("kgs") == "did you mean 'kg'?"
    assert suggest_unit("slugs") == "did you mean 'slug'?"
    assert suggest_unit("qqqqqq") == ""


def test_unit_lookups_agree_with_pint_and_survive_a_cache_round_trip(tmp_path):
    # The on-disk lookup cache must give exactly what pint gives.
    cache_file = tmp_path / "units.json"
    cache = _UnitCache(cache_file)
    for name in ("lb", "slug", "rpm", "deg", "kip", "ft", "N", "mi"):
        info = unit_named(name)
        assert info is not None
        quantity = registry().Quantity(1.0, name).to_base_units()
        assert info.factor == pytest.approx(quantity.magnitude, rel=1e-15)
        assert info.dim == dim_of_unit(quantity.units)
        cache.store(name, info)
    reread = _UnitCache(cache_file)
    assert reread.entries == cache.entries


def test_a_corrupt_cache_file_is_ignored(tmp_path):
    cache_file = tmp_path / "units.json"
    cache_file.write_text("{not json")
    assert _UnitCache(cache_file).entries == {}
    cache_file.write_text('{"lb": [1, "x", 0, 0]}')
    assert _UnitCache(cache_file).entries == {}


def test_an_unknown_unit_is_none():
    assert unit_named("kgs") is None
