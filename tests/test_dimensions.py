"""Dimension inference and homogeneity checks (before any solving)."""

import pytest

from dynsolve.dimensions import check_dimensions, likely_cause
from dynsolve.errors import DimensionError
from dynsolve.spec.parser import parse_spec
from dynsolve.units import Dim

KNOWN = {
    "m": Dim.of("mass"),
    "g": Dim.of("acceleration"),
    "r": Dim.of("length"),
    "v": Dim.of("velocity"),
    "k": Dim.of("stiffness"),
    "t": Dim.of("time"),
    "theta": Dim.of("angle"),
    "pi": Dim(),
}


def check(*lines, requested=None, wanted=()):
    text = "equations:\n" + "".join(f"  {line}\n" for line in lines)
    spec = parse_spec(text, "d.dyn")
    return check_dimensions(spec.equations, KNOWN, "d.dyn", "SI", requested, wanted)


def test_infers_unknowns_through_a_chain():
    report = check("a = alpha*r", "F = m*a", "F*r = I*alpha", requested={"alpha": Dim(0, 0, -2)})
    assert report.dims["a"] == Dim.of("acceleration")
    assert report.dims["F"] == Dim.of("force")
    assert report.dims["I"] == Dim.of("moment_of_inertia")
    assert all(c.ok for c in report.checks)


def test_energy_balance_with_spring_and_square_root():
    report = check("T_2 = m*v_2^2/2 + k*s^2/2", "s = sqrt(2)*r", "w = sqrt(k/m)")
    assert report.dims["T_2"] == Dim.of("energy")
    assert report.dims["v_2"] == Dim.of("velocity")
    assert report.dims["w"] == Dim.of("angular_velocity")


def test_zero_fits_any_dimension():
    report = check("F - m*g = 0", "omega >= 0", "omega = v/r")
    assert report.dims["F"] == Dim.of("force")


def test_sides_conflict_names_line_sides_and_cause():
    with pytest.raises(DimensionError) as caught:
        check("F = m*g", "F = m*v")
    error = caught.value
    assert (error.position.line, error.position.column) == (3, 3)
    assert "left side is a force [N]" in error.message
    assert "right side is a momentum [kg·m/s]" in error.message
    assert error.hint == "a missing time derivative?"


def test_terms_conflict_points_at_the_odd_term():
    with pytest.raises(DimensionError) as caught:
        check("F = m*(g + v)")
    assert caught.value.position.column == 14  # the 'v'
    assert "acceleration" in caught.value.message and "velocity" in caught.value.message


@pytest.mark.parametrize("function", ["sin", "cos", "tan", "exp", "log"])
def test_function_arguments_must_be_dimensionless(function):
    with pytest.raises(DimensionError) as caught:
        check(f"y = {function}(r)")
    assert "must be an angle or a pure number" in caught.value.message
    assert "length" in caught.value.message


def test_angles_are_dimensionless_arguments():
    report = check("y = r*sin(theta) + r*cos(omega*t)")
    assert report.dims["y"] == Dim.of("length")
    assert report.dims["omega"] == Dim.of("angular_velocity")
    assert "theta" in report.angles


def test_atan2_needs_matching_arguments():
    with pytest.raises(DimensionError):
        check("phi = atan2(r, v)")
    assert check("phi = atan2(r, 2*r)").dims["phi"] == Dim()


def test_all_conflicts_are_collected():
    with pytest.raises(DimensionError) as caught:
        check("F = m*g", "F = m*v", "E = m*g + v")
    assert len(caught.value.others) == 1


def test_undeterminable_dimension_asks_for_a_unit_when_wanted():
    with pytest.raises(DimensionError) as caught:
        check("q = z*w", wanted=("q",))
    assert "cannot infer the dimension of q" in caught.value.message
    assert "find" in caught.value.hint


def test_open_dimensions_of_unasked_unknowns_are_pinned_and_reported():
    # A_lat + B_lat = 0 and A_lat*r = B_lat*r hold whatever A_lat's dimension is
    report = check("A_up = m*g", "A_lat + B_lat = 0", "A_lat*r - B_lat*r = 0", "A_axial = 0",
                   wanted=("A_up",))  # fmt: skip
    assert report.dims["A_up"] == Dim.of("force")
    assert set(report.free) == {"A_lat", "A_axial"}
    assert report.dims["B_lat"] == Dim()


def test_a_bare_number_where_g_belongs():
    # numbers in equations are dimensionless: m*9.81 is a mass, not a weight
    with pytest.raises(DimensionError) as caught:
        check("F = m*g", "F = m*9.81")
    assert "left side is a force" in caught.value.message
    assert caught.value.hint == "weight vs mass: W = m g?"


@pytest.mark.parametrize(
    ("left", "right", "cause"),
    [
        ("force", "momentum", "a missing time derivative?"),
        ("force", "mass", "weight vs mass: W = m g?"),
        ("moment", "force", "an extra length: a moment arm where none belongs?"),
        ("moment_of_inertia", "mass", "a moment of inertia vs a mass: I = m k²?"),
    ],
)
def test_likely_causes(left, right, cause):
    assert likely_cause(Dim.of(left), Dim.of(right)) == cause
