"""Benchmark figures into docs/benchmarks.md: each script replaces its own section, stamped.

Every section a script writes starts with its heading and a line naming the machine, the
date and the command, so the figures in the document are the ones the scripts produced
(never typed), and say where and when.

    >>> stamp("python bench/x.py").startswith("Measured ")
    True
"""

from __future__ import annotations

import datetime
import os
import platform
import re
from pathlib import Path

DOC = Path(__file__).resolve().parent.parent / "docs" / "benchmarks.md"


def stamp(command: str) -> str:
    """One line: the date, the machine (CPU count, Python, load average) and the command."""
    today = datetime.date.today().isoformat()
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    machine = (
        f"{platform.system()} {platform.machine()}, {os.cpu_count()} CPUs, "
        f"Python {platform.python_version()}, load average {load:.2f}"
    )
    return f"Measured {today} on {machine} with `{command}`."


def write_section(heading: str, body: str, command: str, doc: Path = DOC) -> None:
    """Replace the section under ``heading`` (a ``## `` line) in ``doc``, or append it."""
    section = f"{heading}\n\n{stamp(command)}\n\n{body.strip()}\n"
    text = doc.read_text(encoding="utf-8") if doc.exists() else "# Benchmarks\n"
    pattern = re.compile(rf"{re.escape(heading)}\n.*?(?=\n## |\Z)", re.S)
    if pattern.search(text):
        text = pattern.sub(lambda _: section, text)
    else:
        text = text.rstrip("\n") + "\n\n" + section
    doc.write_text(text, encoding="utf-8")
