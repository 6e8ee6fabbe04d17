"""Mass moments of inertia: the shape table, parallel axis, composites (textbook examples)."""

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from dynsolve.model.inertia import (
    DENSITY_DIM,
    INERTIA_DIM,
    MASS,
    SHAPES,
    SIZE_DIM,
    Composite,
    Part,
    composite,
    from_gyration,
    inertia_about_G,
    mass_from_density,
    parallel_axis,
    shape_named,
    to_G,
)
from dynsolve.units import Dim

m, L, R, r, a, b, c, t, rho, k, d = sympy.symbols("m L R r a b c t rho k d", positive=True)
Q = sympy.Rational  # exact decimals: Q("0.25")


def same(x: sympy.Expr, y: sympy.Expr) -> bool:
    return sympy.simplify(x - y) == 0


# Hibbeler 12e, inside back cover ("Center of gravity and mass moment of inertia of
# homogeneous solids"); Meriam & Kraige, Dynamics, table D/4. All about the z axis
# through G that the planar motion turns about.
TABLE = [
    ("rod", (L,), m * L**2 / 12),  # slender rod, axis ⟂ rod through G
    ("ring", (R,), m * R**2),  # thin ring, axis ⟂ its plane through the centre
    ("disk", (R,), m * R**2 / 2),  # solid disk / cylinder, its own axis
    ("cylinder", (R,), m * R**2 / 2),  # the same entry, by its other word
    ("hollow", (R, r), m * (R**2 + r**2) / 2),  # hollow cylinder, its own axis
    ("sphere", (R,), 2 * m * R**2 / 5),  # solid sphere, any diameter
    ("shell", (R,), 2 * m * R**2 / 3),  # thin spherical shell, any diameter
    ("plate", (a, b), m * (a**2 + b**2) / 12),  # thin a × b plate, axis ⟂ plate through G
    ("block", (a, b), m * (a**2 + b**2) / 12),  # block, axis ⟂ the a × b face through G
    ("particle", (), sympy.Integer(0)),  # point mass
]


@pytest.mark.parametrize(("shape", "sizes", "textbook"), TABLE, ids=[row[0] for row in TABLE])
def test_each_shape_matches_the_textbook_table(shape, sizes, textbook):
    assert same(inertia_about_G(shape, m, sizes), textbook)


def test_the_table_has_the_nine_shapes_each_stating_its_axis():
    assert list(SHAPES) == [
        "rod", "ring", "disk", "hollow", "sphere", "shell", "plate", "block", "particle"
    ]  # fmt: skip
    for shape in SHAPES.values():
        assert shape.axis and shape.words and shape.key in shape.words
        assert shape.inertia.free_symbols <= {MASS, *shape.size_symbols}


@pytest.mark.parametrize(
    ("shape", "sizes", "thickness", "volume"),
    [
        ("disk", (R,), t, sympy.pi * R**2 * t),
        ("hollow", (R, r), t, sympy.pi * (R**2 - r**2) * t),
        ("sphere", (R,), None, 4 * sympy.pi * R**3 / 3),
        ("shell", (R,), t, 4 * sympy.pi * R**2 * t),
        ("plate", (a, b), t, a * b * t),
        ("block", (a, b), c, a * b * c),
    ],
)
def test_mass_is_density_times_volume(shape, sizes, thickness, volume):
    assert same(mass_from_density(shape, rho, sizes, thickness), rho * volume)


def test_shape_words_resolve_case_and_punctuation_free():
    assert shape_named("Solid Cylinder").key == "disk"
    assert shape_named("thin-walled sphere").key == "shell"
    assert shape_named("point_mass").key == "particle"
    assert shape_named(SHAPES["rod"]) is SHAPES["rod"]


def test_dimensions_follow_units_conventions():
    assert Dim.of("length") == SIZE_DIM
    assert Dim.of("mass") == DENSITY_DIM * SIZE_DIM**3
    assert Dim.of("mass") * SIZE_DIM**2 == INERTIA_DIM


def test_radius_of_gyration():
    assert from_gyration(m, k) == m * k**2
    assert from_gyration(50, Q("0.3")) == Q(9, 2)


def test_parallel_axis_slender_rod_about_its_end():
    assert same(parallel_axis(inertia_about_G("rod", m, (L,)), m, L / 2), m * L**2 / 3)


def test_parallel_axis_disk_about_a_rim_point():
    assert same(parallel_axis(inertia_about_G("disk", m, (R,)), m, R), 3 * m * R**2 / 2)


def test_to_G_reverses_the_parallel_axis():
    # A k_O given about a pin O, d from G, moves to G: I_G = m k_O² − m d².
    assert same(to_G(from_gyration(m, k), m, d), m * (k**2 - d**2))
    assert to_G(parallel_axis(Q(3, 10), 10, Q("0.3")), 10, Q("0.3")) == Q(3, 10)


def test_hibbeler_17_3_plate_with_a_hole():
    # Hibbeler 12e Example 17.3: steel plate ρ = 8000 kg/m³, t = 10 mm; disk R = 250 mm,
    # concentric hole r = 125 mm; O on the outer edge.
    # m_d = ρπR²t = 15.71 kg, m_h = 3.93 kg,
    # I_O = [½ m_d R² + m_d R²] − [½ m_h r² + m_h R²] = 1.20 kg·m² (exact: 1.197).
    density, thickness, outer, inner = 8000, Q("0.010"), Q("0.250"), Q("0.125")
    m_d = mass_from_density("disk", density, (outer,), thickness)
    m_h = mass_from_density("disk", density, (inner,), thickness)
    assert float(m_d) == pytest.approx(15.71, abs=0.005)
    assert float(m_h) == pytest.approx(3.93, abs=0.005)

    body = composite(
        [
            Part("disk", "disk", m_d, (outer,), (0, 0)),
            Part("hole", "disk", m_h, (inner,), (0, 0), True),
        ]
    )
    pin = (-outer, 0)
    textbook = (m_d * outer**2 / 2 + m_d * outer**2) - (m_h * inner**2 / 2 + m_h * outer**2)
    assert body.about(pin) == textbook
    assert float(body.about(pin)) == pytest.approx(1.197, abs=5e-4)
    assert round(float(body.about(pin)), 2) == 1.20
    assert body.G == (0, 0)
    assert body.mass == m_d - m_h

    terms = body.terms(pin)
    assert [(t.name, t.sign) for t in terms] == [("disk", 1), ("hole", -1)]
    assert sum(t.total for t in terms) == body.about(pin)
    assert terms[0].inertia == m_d * outer**2 / 2 and terms[0].transfer == m_d * outer**2

    lines = body.derivation(pin, "kg·m²")
    assert lines == [
        "disk: I = 15.71*0.25^2/2 + 15.71*0.25^2 = 1.473 kg·m²",
        "hole: I = -(3.927*0.125^2/2 + 3.927*0.25^2) = -0.2761 kg·m²",
    ]
    text = body.text(pin, "kg·m²", label="I_O")
    assert "disk" in text and "hole" in text
    assert text.splitlines()[-1] == "I_O = 1.473 - 0.2761 = 1.197 kg·m²"
    assert sympy.latex(terms[0].inertia_shown()) == r"\frac{15.71 \cdot 0.25^{2}}{2}"


def test_seed_000_rod_and_sphere_pendulum():
    # Seed notes 000 (problems/seed/fa_seed_pendulum.dyn): 10-kg rod, 0.6 m, pinned at its
    # end O; 15-kg sphere r = 0.1 m, centre 0.7 m from O.
    # I_O = (1/3)(10)(0.6)² + (2/5)(15)(0.1)² + 15(0.7)² = 1.2 + 0.06 + 7.35 = 8.61 kg·m².
    body = composite(
        [
            Part("rod", "slender rod", 10, (Q("0.6"),), (Q("0.3"), 0)),
            Part("sphere", "sphere", 15, (Q("0.1"),), (Q("0.7"), 0)),
        ]
    )
    pin = (0, 0)
    assert body.about(pin) == Q("8.61")
    assert body.mass == 25
    assert (Q("0.54"), 0) == body.G  # (10·0.3 + 15·0.7) / 25
    assert [t.total for t in body.terms(pin)] == [Q("1.2"), Q("7.41")]
    assert body.text(pin, label="I_O").splitlines()[-1] == "I_O = 1.2 + 7.41 = 8.61"


def test_composite_about_G_and_any_point_agree_with_the_parts():
    body = composite(
        [Part("rod", "rod", m, (L,), (L / 2, 0)), Part("tip", "particle", m, (), (L, 0))]
    )
    assert same(body.G[0], 3 * L / 4)
    assert same(body.about((0, 0)), m * L**2 / 3 + m * L**2)
    assert same(sum(term.total for term in body.terms()), body.I_G)
    assert same(sum(term.total for term in body.terms((0, 0))), body.about((0, 0)))


def test_a_part_known_by_its_radius_of_gyration():
    wheel = Part("wheel", "particle", 20, (), (0, 0), given_I_G=from_gyration(20, Q("0.3")))
    body = composite([wheel, Part("block", "particle", 5, (), (Q("0.5"), 0))])
    assert body.about((0, 0)) == Q("1.8") + Q("1.25")
    assert isinstance(body, Composite)


rationals = st.fractions(min_value=0, max_value=100, max_denominator=50)
positive = st.fractions(min_value=Q(1, 50), max_value=100, max_denominator=50)


@st.composite
def parts(draw: st.DrawFn, name: str = "part") -> Part:
    shape = draw(st.sampled_from(sorted(SHAPES)))
    count = len(SHAPES[shape].sizes)
    sizes = draw(st.lists(positive, min_size=count, max_size=count))
    if shape == "hollow":
        sizes.sort(reverse=True)
    position = (draw(st.fractions(-10, 10, max_denominator=20)), draw(rationals))
    return Part(name, shape, draw(positive), tuple(sizes), position)


@settings(max_examples=40, deadline=None)
@given(parts(), parts("extra"))
def test_one_part_is_itself_and_a_part_then_its_hole_cancel(part, extra):
    alone = composite([part])
    assert alone.mass == part.mass
    assert part.position == alone.G
    assert alone.I_G == part.I_G

    hole = Part(extra.name, extra.shape, extra.mass, extra.sizes, extra.position, hole=True)
    cancelled = composite([part, extra, hole])
    assert cancelled.mass == part.mass
    assert part.position == cancelled.G
    assert cancelled.I_G == part.I_G


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: inertia_about_G("disck", 1, (1,)), "unknown shape 'disck' (did you mean 'disk'?)"),
        (lambda: inertia_about_G("disk", 1, (1, 2)), "solid disk takes 1 size(s) (R), got 2"),
        (lambda: inertia_about_G("plate", 1, (1,)), "takes 2 size(s) (a, b), got 1"),
        (lambda: inertia_about_G("hollow", 1, (1, 2)), "inner radius r = 2 exceeds"),
        (lambda: inertia_about_G("disk", 1, (-1,)), "must not be negative"),
        (lambda: inertia_about_G("disk", -1, (1,)), "give a cut-out as a hole"),
        (lambda: mass_from_density("rod", 7850, (1,)), "density cannot give the mass of a slender"),
        (lambda: mass_from_density("ring", rho, (R,)), "needs its cross-section"),
        (lambda: mass_from_density("particle", rho, ()), "particle has no volume"),
        (lambda: mass_from_density("disk", rho, (R,)), "needs its thickness of the disk"),
        (lambda: mass_from_density("sphere", rho, (R,), t), "takes no thickness"),
        (lambda: to_G(1, 2, 1), "less than m d²"),
        (lambda: composite([]), "at least one part"),
        (
            lambda: composite(
                [Part("plate", "particle", 2), Part("cut", "particle", 3, hole=True)]
            ),
            "holes (cut: 3) are at least as heavy as the solid parts (2)",
        ),
        (lambda: Part("p", "disk", 1, (1,), (0, 0, 0)), "two coordinates"),
        (lambda: Part("wheel", "disk", 1, ()), "wheel: a solid disk takes 1 size(s)"),
    ],
)
def test_errors_say_what_is_wrong(call, message):
    with pytest.raises(ValueError) as error:
        call()
    assert message in str(error.value)


def test_text_is_never_sympified():
    with pytest.raises(TypeError):
        inertia_about_G("disk", "__import__('os')", (1,))
