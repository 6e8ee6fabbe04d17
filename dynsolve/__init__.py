"""dynsolve: solve and check engineering-dynamics problems written as plain-text specs."""

__version__ = "0.1.0"
