"""Parametric studies (``dynsolve sweep``, ``dynsolve.sweep``): sweep givens over ranges and see
every answer move. (The package is not named ``sweep``: that name is the API function.)

:mod:`.ranges` reads the ranges (the ``vary:`` grammar), :mod:`.evaluate` answers every
point (a closed form per regime, full solves elsewhere), :mod:`.table` writes CSV or JSON,
:mod:`.plot` draws the answers against the givens, :mod:`.terminal` lays out the table and
summary the command line prints, :mod:`.command` is the command's work in its worker and
:mod:`.result` the API's pint view of a sweep.
"""
