"""Cold-start help: import the solver's heavy modules without garbage collection, then freeze them.

Importing sympy creates a few hundred thousand long-lived objects; a cyclic garbage
collection pass during the import finds nothing to free, and every later full pass
walks them all again. :func:`quiet_imports` turns the collector off while a block
imports, then moves everything alive into the permanent generation (``gc.freeze``)
and turns the collector back on, so later passes only look at what the work creates.

>>> import gc
>>> with quiet_imports():
...     import fractions
>>> gc.isenabled()
True
"""

from __future__ import annotations

import gc
import sys
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def quiet_imports() -> Iterator[None]:
    """Collector off inside the block; afterwards what is alive frozen and the collector on
    (if it was on before)."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        if was_enabled:
            gc.enable()


def import_solver() -> None:
    """Import the pipeline and what sympy imports lazily on the first sum (its tensor
    module, ≈ 0.1 s), quietly.

    >>> import_solver()
    >>> import sys; "dynsolve.pipeline" in sys.modules
    True
    """
    if "dynsolve.pipeline" in sys.modules:
        return  # imported already (a worker's second job): nothing to freeze again
    with quiet_imports():
        import sympy.tensor.tensor  # noqa: F401  (Add.flatten imports it on first use)

        import dynsolve.pipeline  # noqa: F401
