"""The front ends: each turns one kind of spec into a problem the pipeline solves.

``equation_mode`` reads hand-written equations, ``scene_mode`` writes them from a
scene, ``kinematics_mode`` integrates a one-line law, and ``plane_kinematics``
follows a particle in the plane.
"""
