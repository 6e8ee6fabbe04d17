"""Motion in time: a one-degree-of-freedom scene's equation of motion, integrated with solve_ivp.

:mod:`~dynsolve.simulate.equations` writes M(q) q'' + ½ M'(q) q'² = Q(q, q') for a scene
whose placement is a function of one coordinate q; :mod:`~dynsolve.simulate.integrator`
is the one integrator (scipy's ``solve_ivp``); :mod:`~dynsolve.simulate.crosscheck`
integrates each travel stage of a solved scene and compares its end state with the
principle's answer; :mod:`~dynsolve.simulate.run` serves ``dynsolve simulate``.
"""
