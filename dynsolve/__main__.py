"""``python -m dynsolve``: the same as the ``dynsolve`` command."""

from dynsolve.cli import main

if __name__ == "__main__":  # a spawned worker (macOS, Windows) imports this module again
    main()
