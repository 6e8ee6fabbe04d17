"""Where an export is written: never over a non-empty file or folder without ``force``,
never outside the path given, every file written atomically. A folder is created with
its missing parents.

>>> import pathlib, tempfile
>>> folder = pathlib.Path(tempfile.mkdtemp()) / "questions" / "q"
>>> write_folder(folder, {"info.json": "{}", "clientFilesQuestion/a.txt": "a"}, force=False)
>>> sorted(p.name for p in folder.rglob("*"))
['a.txt', 'clientFilesQuestion', 'info.json']
>>> try:
...     write_folder(folder, {"info.json": "{}"}, force=False)
... except ExportError as error:
...     print(error.message.split(":")[1].strip())
it is not empty
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path, PurePosixPath

from dynsolve.errors import DynsolveError
from dynsolve.files import check_writable, write_text


class ExportError(DynsolveError, ValueError):
    """An export cannot be made: bad input, or a target that must not be written."""


def write_file(path: Path, text: str | bytes, force: bool) -> None:
    """Write one file; refuse to replace a non-empty file unless ``force``."""
    check_file(path, force)
    write_text(path, text)


def check_file(path: Path, force: bool) -> None:
    """Refuse a file target that is a folder, or a non-empty file without ``force``."""
    if path.is_dir():
        raise ExportError(f"refusing to write {path}: it is a folder", hint="give a file name")
    if path.exists() and path.stat().st_size and not force:
        raise ExportError(
            f"refusing to write {path}: it exists and is not empty",
            hint="choose another -o path, or pass --force to replace it",
        )
    check_writable(path)


def check_folder(folder: Path, force: bool) -> None:
    """Refuse a folder target that is a file, or a non-empty folder without ``force``."""
    if folder.exists() and not folder.is_dir():
        raise ExportError(f"refusing to write into {folder}: it is a file", hint="give a folder")
    if folder.is_dir() and any(folder.iterdir()) and not force:
        raise ExportError(
            f"refusing to write into {folder}: it is not empty",
            hint="choose a new folder, or pass --force to replace the files dynsolve writes",
        )
    ancestor = folder.parent  # missing parents are created (pl/questions/x in a new course)
    while not ancestor.exists() and ancestor != ancestor.parent:
        ancestor = ancestor.parent
    if not ancestor.is_dir():
        raise ExportError(
            f"cannot create {folder}: {ancestor} is a file, not a folder", hint="give a folder"
        )


def write_folder(folder: Path, files: Mapping[str, str | bytes], force: bool) -> None:
    """Create ``folder`` and write ``files`` (relative POSIX name → content) into it.

    A name that is absolute or climbs out (``..``), or whose target resolves outside the
    folder (a symbolic link already there), is refused before anything is written."""
    check_folder(folder, force)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        reason = error.strerror or str(error)
        raise ExportError(
            f"cannot create {folder}: {reason}", hint="give a writable folder"
        ) from None
    root = Path(os.path.realpath(folder))
    targets = []
    for name, content in files.items():
        relative = PurePosixPath(name)
        if relative.is_absolute() or ".." in relative.parts or not relative.parts:
            raise ExportError(f"refusing to write {name!r}: not a name inside {folder}")
        target = folder.joinpath(*relative.parts)
        real = Path(os.path.realpath(target))
        if root not in real.parents:
            raise ExportError(
                f"refusing to write {target}: it resolves to {real}, outside {folder}",
                hint="remove the symbolic link, or choose a new folder",
            )
        targets.append((target, content))
    for target, content in targets:
        target.parent.mkdir(parents=True, exist_ok=True)
        check_writable(target)
        write_text(target, content)
