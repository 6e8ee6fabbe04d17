"""Reading spec files and writing output files safely: byte caps, regular files only, atomic writes.

Inputs are opened without blocking (a FIFO never hangs), checked to be regular
files *after* opening (``fstat``, so a symlink swapped in between cannot fool the
check), and read up to ``cap + 1`` bytes, so ``/dev/zero`` or a file that grows
cannot exhaust memory whatever ``stat`` says. Outputs are written to a temporary
file beside the target and renamed over it, and only when the target is absent
or a regular file: the rename never replaces a device, FIFO, socket or a file of
``/proc`` or ``/sys``.

>>> import pathlib, tempfile
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> write_text(folder / "out.txt", "hello")
>>> read_capped(folder / "out.txt", cap=100)
b'hello'
"""

from __future__ import annotations

import errno
import os
import stat
import tempfile
from pathlib import Path

from dynsolve.errors import DynsolveError

# files under these folders are kernel interfaces, not data, even when stat calls them regular
SPECIAL_FOLDERS = (Path("/proc"), Path("/sys"), Path("/dev"))
_NO_BLOCK = getattr(os, "O_NONBLOCK", 0)
_BINARY = getattr(os, "O_BINARY", 0)  # Windows: no newline translation


class FileAccessError(DynsolveError, OSError):
    """A file cannot be read or written: missing, unreadable, too big or not a regular file."""


def read_capped(path: str | Path, cap: int) -> bytes:
    """The bytes of the regular file at ``path``, at most ``cap + 1`` of them: a result
    longer than ``cap`` means the file is over the cap (the caller says so, with its limit).

    >>> try:
    ...     read_capped("/dev/zero", cap=10)
    ... except FileAccessError as error:
    ...     print(error.message)
    cannot read /dev/zero: it is a character device, not a regular file
    """
    shown = str(path)
    try:
        descriptor = os.open(path, os.O_RDONLY | _NO_BLOCK | _BINARY)
    except OSError as error:
        raise FileAccessError(
            f"cannot read {shown}: {_reason(error)}", hint=_read_hint(error)
        ) from None
    try:
        kind = _kind(os.fstat(descriptor).st_mode)
        if kind != "regular file":
            raise FileAccessError(
                f"cannot read {shown}: it is a {kind}, not a regular file",
                hint="give the path of a .dyn text file",
            )
        chunks: list[bytes] = []
        size = 0
        while size <= cap:
            chunk = os.read(descriptor, min(cap + 1 - size, 1 << 16))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    except FileAccessError:
        raise
    except OSError as error:
        raise FileAccessError(f"cannot read {shown}: {_reason(error)}") from None
    finally:
        os.close(descriptor)
    return b"".join(chunks)


def check_writable(path: Path) -> None:
    """Refuse an output path that is not (or would not become) an ordinary regular file.

    >>> try:
    ...     check_writable(Path("/dev/null"))
    ... except FileAccessError as error:
    ...     print(error.message)
    refusing to write /dev/null: it is a character device, not a regular file
    """
    hint = "give the path of an ordinary file, e.g. -o out.tex"
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        mode = None
    except OSError as error:
        raise FileAccessError(f"cannot write {path}: {_reason(error)}", hint=hint) from None
    if mode is not None and not stat.S_ISREG(mode):
        kind = _kind(mode)
        raise FileAccessError(
            f"refusing to write {path}: it is a {kind}, not a regular file", hint=hint
        )
    real = Path(os.path.realpath(path))
    for folder in SPECIAL_FOLDERS:  # as written (/dev/stdout) and as resolved (/proc/self/...)
        if any(p == folder or folder in p.parents for p in (Path(path).absolute(), real)):
            raise FileAccessError(
                f"refusing to write {path}: {folder} holds system interfaces, not files", hint=hint
            )
    if not real.parent.is_dir():
        raise FileAccessError(
            f"cannot write {path}: folder {real.parent} does not exist", hint="create it first"
        )


def write_text(path: Path, text: str | bytes) -> None:
    """Write ``text`` (or bytes) to the regular file ``path`` atomically; on any failure the
    old file stays.

    Raises FileAccessError for a special target or a write error (no space, no
    permission, read-only file system).
    """
    check_writable(path)
    real = Path(os.path.realpath(path))
    try:
        handle, temporary = tempfile.mkstemp(
            dir=real.parent, prefix=f".{real.name}.", suffix=".tmp"
        )
    except OSError as error:
        raise _write_error(path, error) from None
    try:
        data = text.encode("utf-8") if isinstance(text, str) else text
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temporary, _file_mode(real))
        check_writable(path)  # still a regular file (or absent) right before the rename
        os.replace(temporary, real)
    except FileAccessError:
        Path(temporary).unlink(missing_ok=True)
        raise
    except OSError as error:
        Path(temporary).unlink(missing_ok=True)
        raise _write_error(path, error) from None
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def _file_mode(path: Path) -> int:
    """The mode an ordinary new file gets (or the existing file's), not mkstemp's 0600."""
    if path.exists():
        return path.stat().st_mode & 0o777
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


def _kind(mode: int) -> str:
    """What a file is, in words.

    >>> _kind(stat.S_IFIFO), _kind(stat.S_IFDIR)
    ('FIFO (named pipe)', 'folder')
    """
    kinds = (
        (stat.S_ISREG, "regular file"),
        (stat.S_ISDIR, "folder"),
        (stat.S_ISCHR, "character device"),
        (stat.S_ISBLK, "block device"),
        (stat.S_ISFIFO, "FIFO (named pipe)"),
        (stat.S_ISSOCK, "socket"),
    )
    return next((name for test, name in kinds if test(mode)), "special file")


def _reason(error: OSError) -> str:
    if error.errno == errno.ELOOP:
        return "too many levels of symbolic links (a symlink loop?)"
    if error.errno == errno.EISDIR:
        return "it is a folder"
    return (error.strerror or str(error)).lower()


def _read_hint(error: OSError) -> str:
    if error.errno == errno.EACCES:
        return "check the file's permissions"
    return "check the path"


def _write_error(path: Path, error: OSError) -> FileAccessError:
    hints = {
        errno.ENOSPC: "free some disk space; the previous file was left as it was",
        errno.EACCES: "check the folder's permissions; the previous file was left as it was",
        errno.EROFS: "write to a folder on a writable file system",
    }
    hint = hints.get(error.errno or 0, "the previous file was left as it was")
    return FileAccessError(f"cannot write {path}: {_reason(error)}", hint=hint)
