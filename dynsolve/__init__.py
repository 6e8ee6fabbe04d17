"""dynsolve: solve and check engineering-dynamics problems written as plain-text specs.

>>> import dynsolve
>>> dynsolve.solve("given:\\n  m = 2 kg\\nequations:\\n  W = m*g\\nfind: W\\n")["W"]
<Quantity(19.62, 'newton')>

The API is imported on first use, so ``import dynsolve`` (and the command line's
``--help``) stays fast.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"
__all__ = ["FileCheck", "Result", "check", "solve", "sweep"]

if TYPE_CHECKING:
    from dynsolve.api import FileCheck, Result, check, solve, sweep


def __getattr__(name: str) -> Any:
    if name in __all__:
        from dynsolve import api

        return getattr(api, name)
    raise AttributeError(f"module 'dynsolve' has no attribute {name!r}")
