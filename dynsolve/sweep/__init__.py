"""Parametric studies: sweep one or two givens over a range and see every answer move.

:mod:`~dynsolve.sweep.ranges` reads the ranges (the ``vary:`` grammar),
:mod:`~dynsolve.sweep.evaluate` answers every point (a closed form per regime, full solves
elsewhere), :mod:`~dynsolve.sweep.table` writes CSV or JSON, :mod:`~dynsolve.sweep.plot`
draws the answers against the givens and :mod:`~dynsolve.sweep.terminal` lays out the table
and summary the command line prints.
"""
