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
from typing import Any, TextIO

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
    """An open, locked journal (use :meth:`open`, as a context manager)."""

    def __init__(self, path: Path, handle: TextIO) -> None:
        self.path = path
        self.handle = handle
        self.rows = 0  # rows in the journal (resumed and new)
        self.synced = time.monotonic()

    @classmethod
    def open(cls, path: Path, resume: bool = False, fresh: bool = False) -> Journal:
        """Open and lock the journal at ``path`` (created empty if absent). Refuses one
        another run holds, and, unless ``resume`` or ``fresh``, one holding graded rows."""
        try:
            descriptor = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError as error:
            raise _unwritable(path, error, 0) from None
        handle = os.fdopen(descriptor, "r+", encoding="utf-8", newline="")
        if not _lock(handle):
            handle.close()
            raise JournalError(
                f"another 'dynsolve grade' is writing {path.name.removesuffix(JOURNAL_SUFFIX)}"
                f" now (its journal {path} is locked)",
                None,
                "wait for it to finish, or choose another -o",
            )
        if not _same_file(path, handle):  # the run before removed the journal we locked
            handle.close()
            return cls.open(path, resume, fresh)
        journal = cls(path, handle)
        rows = journal.graded_rows()
        if rows and not resume and not fresh:
            handle.close()
            raise JournalError(
                f"{path} holds {rows} graded rows of an interrupted run",
                None,
                "add --resume to keep them and grade the rest, or --fresh to start over",
            )
        return journal

    def graded_rows(self) -> int:
        """How many graded rows the journal holds (its lines after the fingerprint)."""
        self.handle.seek(0)
        return max(0, sum(1 for line in self.handle if line.endswith("\n")) - 1)

    def start(self, stamp: str, resume: bool) -> dict[str, Mapping[str, Any]]:
        """With ``resume``, the rows recorded under ``stamp`` (student → row), the journal
        positioned after them; otherwise the journal emptied and stamped."""
        if resume:
            done = self._read(stamp)
            if done is not None:
                return done
        self.handle.seek(0)
        self.handle.truncate()
        self.rows = 0
        self._write({"fingerprint": stamp}, sync=True)
        return {}

    def append(self, row: Mapping[str, Any]) -> None:
        """One graded row, flushed (a killed process loses nothing flushed), fsync'd once
        ``SYNC_SECONDS`` have passed (a crash of the machine loses at most those)."""
        self._write(row, sync=time.monotonic() - self.synced >= SYNC_SECONDS)
        self.rows += 1

    def remove(self) -> None:
        """Delete the journal (the reports are written), still holding the lock."""
        self.path.unlink(missing_ok=True)

    def close(self) -> None:
        """Sync and close (which releases the lock)."""
        try:
            if not self.handle.closed:
                self.handle.flush()
                os.fsync(self.handle.fileno())
        except OSError:
            pass  # the write error was reported; what was written stays
        finally:
            self.handle.close()

    def __enter__(self) -> Journal:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()

    def _write(self, record: Mapping[str, Any], sync: bool) -> None:
        try:
            self.handle.write(json.dumps(record) + "\n")  # key order kept: parts in find order
            self.handle.flush()
            if sync:
                os.fsync(self.handle.fileno())
                self.synced = time.monotonic()
        except OSError as error:
            raise _unwritable(self.path, error, self.rows) from None

    def _read(self, stamp: str) -> dict[str, Mapping[str, Any]] | None:
        """The rows a killed run finished (None for an empty journal); a torn last line
        (killed mid-write) is dropped."""
        self.handle.seek(0)
        lines = self.handle.read().split("\n")
        records = []
        for line in lines:
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
        self.handle.seek(0)
        self.handle.truncate()  # rewritten whole: appends start on a fresh line
        self.handle.write("".join(json.dumps(r) + "\n" for r in records))
        self.handle.flush()
        self.rows = len(records) - 1
        return {str(r["student"]): r for r in records[1:]}


def _lock(handle: TextIO) -> bool:
    if fcntl is None:
        return True
    try:
        fcntl.flock(handle.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        return False
    return True


def _same_file(path: Path, handle: TextIO) -> bool:
    try:
        on_disk = os.stat(path)
    except FileNotFoundError:
        return False
    mine = os.fstat(handle.fileno())
    return (on_disk.st_dev, on_disk.st_ino) == (mine.st_dev, mine.st_ino)


def _unwritable(path: Path, error: OSError, rows: int) -> JournalError:
    reason = (error.strerror or str(error)).lower()
    kept = f"; the {rows} rows graded so far are kept in it" if rows else ""
    return JournalError(
        f"cannot write the journal {path}: {reason}{kept}",
        None,
        "free disk space (or raise the file-size limit), then rerun with --resume",
    )
