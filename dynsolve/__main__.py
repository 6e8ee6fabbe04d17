"""``python -m dynsolve``: the same as the ``dynsolve`` command."""

from dynsolve.cli import main

main()
