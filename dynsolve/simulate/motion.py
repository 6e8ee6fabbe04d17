"""A one-degree-of-freedom scene's equation of motion in its one coordinate.

The coordinate is the first that fits: a travel's own coordinate, the turn of a rigid body
or link, a lone particle's distance along its one straight surface, or its place on a
circular path. Used by ``dynsolve simulate`` and by the vibration check's integration.
"""

from __future__ import annotations

from dynsolve.model.scene import Scene, Travel
from dynsolve.simulate.contact import on_circle
from dynsolve.simulate.crosscheck import travel_motion
from dynsolve.simulate.equations import (
    NotSimulable,
    OneDof,
    Q,
    mechanism,
    numeric_scene,
    straight_line,
)


def motion_of(scene: Scene, symbols: dict, values: dict) -> OneDof:
    """The scene's equation of motion in its one coordinate (see the module's docstring)."""
    travels = [t for t in scene.travels.values() if t.kind not in ("for", "until")]
    scene = numeric_scene(scene, values)
    if travels:
        motion, _ = travel_motion(scene, travels[0], symbols, values, simplify=True)
        return motion
    reasons = []
    names = [n for n, b in scene.bodies.items() if not b.particle]
    names += [link.name for link in scene.links]
    for name in names:
        try:
            turn = Travel(name, "turns", angle=Q)
            return mechanism(scene, turn, symbols, values, f"turn of {name}", "rad", True)
        except NotSimulable as exc:
            reasons.append(str(exc))
    particles = [n for n, b in scene.bodies.items() if b.particle]
    if any(s.constant_speed for s in scene.supports):
        raise NotSimulable(
            "a particle driven along its path at constant speed (', constant') has no motion "
            "to integrate: its speed is given"
        )
    for name in particles:
        guides = [
            s
            for s in scene.supports
            if s.body == name and s.kind == "contact" and (0 + s.normal_acceleration) == 0
        ]  # a curved path is no straight surface
        if len(particles) == 1 and len(guides) == 1:
            what = f"distance of {name} along its surface at {guides[0].name}"
            return straight_line(scene, name, guides[0].tangent, symbols, values, what)
    on_path = on_circle(scene, symbols, values)
    if on_path is not None:
        return on_path[0]
    why = f" ({reasons[0]})" if reasons else ""
    raise NotSimulable(
        "the scene has no one coordinate to simulate in" + why + ": simulate supports "
        "one degree of freedom (a pinned or rolling body, a linkage, a guided particle)"
    )
