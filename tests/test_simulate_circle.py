"""The simulation check of until events on a circle (issue 8: "where a stage can be
simulated, integrate its equations of motion and compare"): the integrated event agrees
with the principle's closed form, and a wrong principle answer turns the check red.

Hand result: a bob on a cord of length L moving at v at the bottom goes slack where
cos θ = (2 g L − v²)/(3 g L), at speed √(−g L cos θ).
"""

import math

import pytest
import sympy

from dynsolve.model.scene import Body, Link, Scene, Travel
from dynsolve.simulate.circle import circle_check, circle_event

G = 9.81
g = sympy.Symbol("g")


def bob_scene(v: float, L: float = 1.0) -> tuple[Scene, Travel]:
    bob = Body("bob", 2, 0, (0, -L), (0, -L), "particle", (), {}, True, "", 0, 0)
    cord = Link("cord", "bob", (0, -L), "", (0, 0))
    slack = Travel("bob", "until", until="slack", until_name="cord")
    scene = Scene(
        {"bob": bob}, {}, (), (), (), (0, -1), {}, links=(cord,),
        velocities={"bob": (v, 0)}, travels={"bob": slack},
    )  # fmt: skip
    return scene, slack


@pytest.mark.parametrize("v, L", [(5.5, 1.0), (6.8, 1.0), (4.0, 0.5), (-6.0, 1.0)])
def test_the_integrated_event_is_the_hand_one(v, L):
    scene, slack = bob_scene(v, L)
    angle, speed, why = circle_event(scene, slack, {"g": g}, {g: sympy.Float(G)})
    c = (2 * G * L - v * v) / (3 * G * L)
    assert why == ""
    assert angle == pytest.approx(math.acos(c), rel=1e-9)
    assert speed == pytest.approx(math.sqrt(-G * L * c), rel=1e-9)


def test_a_wrong_principle_answer_turns_the_check_red():
    scene, slack = bob_scene(6.0)
    c = (2 * G - 36) / (3 * G)
    right = (sympy.Float(math.acos(c)), sympy.Float(math.sqrt(-G * c)))
    wrong = (right[0] * 1.001, right[1])
    values = {g: sympy.Float(G)}
    assert circle_check("simulation", scene, slack, right, {"g": g}, values, "SI").passed
    assert not circle_check("simulation", scene, slack, wrong, {"g": g}, values, "SI").passed


def test_a_bob_that_swings_back_never_goes_slack_in_the_simulation():
    # v² < 2 g L: it stops below the horizontal and swings back
    scene, slack = bob_scene(3.0)
    _, speed, why = circle_event(scene, slack, {"g": g}, {g: sympy.Float(G)})
    assert "swings back" in why and speed == 0.0
