"""Planar linkages at an instant: bars, joints and sliders of a scene (Hibbeler ch. 16).

A scene with ``bar`` lines is a linkage. :mod:`~dynsolve.linkage.model` reads its lines,
:mod:`~dynsolve.linkage.position` places every joint (loop closure and the choice of
assembly), :mod:`~dynsolve.linkage.relations` writes the relative velocity and
acceleration equations, and :mod:`~dynsolve.linkage.problem` turns them into a problem the
pipeline solves and checks like any other.
"""
