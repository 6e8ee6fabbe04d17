"""Open HTML pages in Debian's headless Chromium in tests: a screenshot, the DOM."""

import subprocess
import tempfile
from pathlib import Path

TIMEOUT_S = 120  # one Chromium run, start to exit
FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)


def run_chromium(chromium: str, page: Path, *flags: str) -> str:
    """Chromium run on ``page`` with ``flags`` (and a fresh profile); its stdout."""
    with tempfile.TemporaryDirectory() as profile:
        result = subprocess.run(
            [chromium, *FLAGS, f"--user-data-dir={profile}", *flags, page.resolve().as_uri()],
            capture_output=True,
            text=True,
            errors="replace",
            timeout=TIMEOUT_S,
            stdin=subprocess.DEVNULL,
        )
    assert result.returncode == 0, result.stderr[-3000:]
    return result.stdout


def screenshot(chromium: str, page: Path, out: Path, size: str = "1000,3000") -> Path:
    """A PNG of ``page`` in a window of ``size`` pixels."""
    run_chromium(chromium, page, f"--screenshot={out}", f"--window-size={size}")
    assert out.is_file() and out.stat().st_size > 0
    return out


def dump_dom(chromium: str, page: Path) -> str:
    """The DOM of ``page`` once Chromium has loaded it, as HTML."""
    return run_chromium(chromium, page, "--dump-dom")
