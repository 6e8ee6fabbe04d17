"""Rigid bodies in 3D from a scene: a body turning about a fixed axis on its bearings.

:mod:`~dynsolve.rigid3d.inertia` holds the 3D shape table and turns principal moments
into the scene's inertia tensor; :mod:`~dynsolve.rigid3d.model` reads the scene's 3D
lines; :mod:`~dynsolve.rigid3d.problem` writes ΣF = m a_G and ΣM_G = Ḣ_G with
Ḣ_G = I_G α + ω × H_G (Hibbeler 21.4) and the targets, for the pipeline to solve;
:mod:`~dynsolve.rigid3d.energy` writes T1 + ΣU1-2 = T2 between two states (a gear
rolling on a fixed gear).
"""
