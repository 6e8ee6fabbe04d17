"""The journal of a grading run: locked, fingerprinted, one JSON line per graded row.

The journal lives next to the first report (``report.csv.journal``). It is opened
without truncating and locked (``fcntl.flock``, released by the system when the process
ends, however it ends), so a second run on the same report is refused instead of
truncating the first one's rows. Its first line is a fingerprint of everything that
decides a verdict; a journal holding rows is an interrupted run's: it is resumed
(``resume``), started over (``fresh``), or the run is refused. Each row is flushed as it
is written and fsync'd at most every ``SYNC_SECONDS``; a write error (disk full, file-size
limit) is a :class:`JournalError` that keeps what was written.

>>> import pathlib, tempfile
>>> path = pathlib.Path(tempfile.mkdtemp()) / "r.csv.journal"
>>> with Journal.open(path) as journal:
...     _ = journal.start("abc", resume=False)
...     journal.append({"student": "s1", "score": 100.0, "parts": {}})
>>> with Journal.open(path, resume=True) as journal:
...     list(journal.start("abc", resume=True))
['s1']
"""

from __future__ import annotations

import json
import os
import time
from collections.abc import Mapping
from pathlib import Path
from types import TracebackType
from typing import Any

from dynsolve.errors import SpecError

try:
    import fcntl
except ImportError:  # Windows: no advisory lock; two runs on one report are not detected
    fcntl = None  # type: ignore[assignment]

JOURNAL_SUFFIX = ".journal"
SYNC_SECONDS = 1.0  # between fsyncs; each row is flushed to the OS as it is finished


class JournalError(SpecError):
    """The journal cannot be used: locked by another run, another run's, or not writable."""


def journal_path(report: Path) -> Path:
    """The journal kept next to ``report`` while grading."""
    return report.with_name(report.name + JOURNAL_SUFFIX)


class Journal:
    """An open, locked journal (use :meth:`open`, as a context manager). Written with
    ``os.write`` on its descriptor: no buffer holds a row back, or fails again at close."""

    def __init__(self, path: Path, descriptor: int) -> None:
        self.path = path
        self.descriptor = descriptor
        self.held = 0  # graded rows the journal held when opened (an interrupted run's)
        self.rows = 0  # graded rows written since start (resumed ones included)
        self.started = False
        self.synced = time.monotonic()

    @classmethod
    def open(cls, path: Path, resume: bool = False, fresh: bool = False) -> Journal:
        """Open and lock the journal at ``path`` (created empty if absent). Refuses one
        another run holds, and, unless ``resume`` or ``fresh``, one holding graded rows."""
        try:
            descriptor = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError as error:
            raise _unwritable(path, error, 0) from None
        if not _lock(descriptor):
            os.close(descriptor)
            raise JournalError(
                f"another 'dynsolve grade' is writing {path.name.removesuffix(JOURNAL_SUFFIX)}"
                f" now (its journal {path} is locked)",
                None,
                "wait for it to finish, or choose another -o",
            )
        if not _same_file(path, descriptor):  # the run before removed the journal we locked
            os.close(descriptor)
            return cls.open(path, resume, fresh)
        journal = cls(path, descriptor)
        journal.held = max(0, journal._text().count("\n") - 1)
        if journal.held and not resume and not fresh:
            os.close(descriptor)
            raise JournalError(
                f"{path} holds {journal.held} graded rows of an interrupted run",
                None,
                "add --resume to keep them and grade the rest, or --fresh to start over",
            )
        return journal

    def empty(self) -> bool:
        """Nothing to resume from: no graded row written, none held from before."""
        return self.rows == 0 and (self.started or self.held == 0)

    def start(self, stamp: str, resume: bool) -> dict[str, Mapping[str, Any]]:
        """With ``resume``, the rows recorded under ``stamp`` (student → row), the journal
        positioned after them; otherwise the journal emptied and stamped."""
        self.started = True
        if resume:
            done = self._read(stamp)
            if done is not None:
                return done
        self._rewrite(json.dumps({"fingerprint": stamp}) + "\n")
        self.rows = 0
        return {}

    def append(self, row: Mapping[str, Any]) -> None:
        """One graded row, written through to the OS (a killed process loses nothing
        written), fsync'd once ``SYNC_SECONDS`` have passed (a crash of the machine loses
        at most those)."""
        self._write(json.dumps(row) + "\n")  # key order kept: parts in find order
        self.rows += 1
        if time.monotonic() - self.synced >= SYNC_SECONDS:
            self._sync()

    def remove(self) -> None:
        """Delete the journal (the reports are written), still holding the lock."""
        self.path.unlink(missing_ok=True)

    def close(self) -> None:
        """Sync and close (which releases the lock); never raises."""
        try:
            os.fsync(self.descriptor)
        except OSError:
            pass  # a write error was reported; what was written stays
        finally:
            os.close(self.descriptor)

    def __enter__(self) -> Journal:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        trace: TracebackType | None,
    ) -> None:
        self.close()

    def _text(self) -> str:
        os.lseek(self.descriptor, 0, os.SEEK_SET)
        chunks = []
        while chunk := os.read(self.descriptor, 1 << 20):
            chunks.append(chunk)
        return b"".join(chunks).decode("utf-8", "replace")

    def _write(self, text: str) -> None:
        data = memoryview(text.encode("utf-8"))
        try:
            while data:
                data = data[os.write(self.descriptor, data) :]
        except OSError as error:
            raise _unwritable(self.path, error, self.rows) from None

    def _sync(self) -> None:
        try:
            os.fsync(self.descriptor)
        except OSError as error:
            raise _unwritable(self.path, error, self.rows) from None
        self.synced = time.monotonic()

    def _rewrite(self, text: str) -> None:
        """The journal replaced by ``text`` (then appended to), synced."""
        try:
            os.ftruncate(self.descriptor, 0)
            os.lseek(self.descriptor, 0, os.SEEK_SET)
        except OSError as error:
            raise _unwritable(self.path, error, 0) from None
        self._write(text)
        self._sync()

    def _read(self, stamp: str) -> dict[str, Mapping[str, Any]] | None:
        """The rows a killed run finished (None for an empty journal); a torn last line
        (killed mid-write) is dropped."""
        records = []
        for line in self._text().split("\n"):
            try:
                records.append(json.loads(line))
            except json.JSONDecodeError:
                break  # the torn tail: everything before it was written whole
        if not records:
            return None
        if records[0].get("fingerprint") != stamp:
            raise JournalError(
                f"{self.path} is the journal of another run (other problem, answers, "
                "variants, rules or options)",
                None,
                "rerun with --fresh to start over, or with the options of the interrupted run",
            )
        self._rewrite("".join(json.dumps(r) + "\n" for r in records))  # no torn tail
        self.rows = len(records) - 1
        return {str(r["student"]): r for r in records[1:]}


def _lock(descriptor: int) -> bool:
    if fcntl is None:
        return True
    try:
        fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        return False
    return True


def _same_file(path: Path, descriptor: int) -> bool:
    try:
        on_disk = os.stat(path)
    except FileNotFoundError:
        return False
    mine = os.fstat(descriptor)
    return (on_disk.st_dev, on_disk.st_ino) == (mine.st_dev, mine.st_ino)


def _unwritable(path: Path, error: OSError, rows: int) -> JournalError:
    reason = (error.strerror or str(error)).lower()
    kept = f"; the {rows} rows graded so far are kept in it" if rows else ""
    return JournalError(
        f"cannot write the journal {path}: {reason}{kept}",
        None,
        "free disk space (or raise the file-size limit), then rerun with --resume",
    )
