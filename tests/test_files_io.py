"""Reading specs and writing output safely: byte caps, special files, unreadable files, -o.

Through typer's CliRunner (the solve runs in a forked worker, which inherits the
test's monkeypatches) and directly on dynsolve.files. Nothing here writes to a
real device: special targets are a FIFO, a socket or a device node made in a
temporary folder, or are checked with ``check_writable``, which never writes.
"""

from __future__ import annotations

import errno
import os
import socket
import stat
from pathlib import Path

import pytest
from specs import DRUM
from typer.testing import CliRunner, Result

from dynsolve import files
from dynsolve.cli import ExitCode, app
from dynsolve.files import FileAccessError, check_writable, read_capped, write_text
from dynsolve.spec.parser import MAX_FILE_BYTES

# The symbolic key is wrong on purpose: the equation gives F = m g + k x, the key
# says m g + k h. m and g cancel in the difference, which made the equivalence test
# substitute values into the difference's symbols only and crash converting m*g.
SPRING_WRONG_FORMULA = """\
problem: weight plus a spring force, in symbols
given:
  m: kg
  g: m/s^2
  k: N/m
  x: m
  h: m
equations:
  F = m*g + k*x
find: F
answers:
  F = m*g + k*h
"""


# devices, FIFOs, sockets and symlinks as on Linux and macOS
posix = pytest.mark.skipif(os.name != "posix", reason="POSIX special files")


def run(*args: str) -> Result:
    return CliRunner().invoke(app, list(args), env={"COLUMNS": "300"})  # tables unwrapped


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def last_line(text: str) -> str:
    return text.strip().splitlines()[-1]


# ---- inputs ---------------------------------------------------------------------------------


@posix
def test_dev_zero_is_refused_not_read_forever():
    result = run("solve", "/dev/zero")
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "/dev/zero: it is a character device, not a regular file" in result.stderr


@posix
def test_a_dyn_symlink_to_dev_zero_is_refused(tmp_path: Path):
    link = tmp_path / "zero.dyn"
    link.symlink_to("/dev/zero")
    result = run("solve", str(link))
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "character device" in result.stderr


@posix
def test_a_fifo_is_refused_without_blocking(tmp_path: Path):
    fifo = tmp_path / "pipe.dyn"
    os.mkfifo(fifo)
    # no writer: a blocking open would hang; the budget bounds the test if it did
    result = run("solve", str(fifo), "--time-budget", "20")
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "FIFO (named pipe), not a regular file" in result.stderr


def test_a_folder_given_as_file_is_a_clear_error(tmp_path: Path):
    result = run("solve", str(tmp_path))
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "it is a folder" in result.stderr
    assert "Traceback" not in result.output


def test_the_byte_cap_counts_bytes_read_not_stat(tmp_path: Path):
    path = tmp_path / "big.dyn"
    path.write_bytes(b"#" * (MAX_FILE_BYTES + 1))
    assert len(read_capped(path, 10)) == 11  # cap + 1 bytes read: over the cap
    assert read_capped(path, MAX_FILE_BYTES + 1) == b"#" * (MAX_FILE_BYTES + 1)
    result = run("solve", str(path))
    assert result.exit_code == ExitCode.BAD_INPUT
    assert f"specs are limited to {MAX_FILE_BYTES} bytes" in result.stderr


@posix
def test_a_symlink_loop_is_named_as_such(tmp_path: Path):
    loop = tmp_path / "loop.dyn"
    loop.symlink_to(loop)
    with pytest.raises(FileAccessError, match="symlink loop"):
        read_capped(loop, 100)


def _make_unreadable(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """chmod 000; as root (which reads anyway) opening that path fails with EACCES instead."""
    path.chmod(0)
    if os.geteuid() != 0:
        return
    real_open = os.open

    def refusing_open(name: object, *args: object, **kwargs: object) -> int:
        if os.fspath(name) == str(path):  # type: ignore[call-overload]
            raise PermissionError(errno.EACCES, "Permission denied", str(path))
        return real_open(name, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(files.os, "open", refusing_open)


@posix
def test_check_goes_on_past_unreadable_folders_and_loops(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
):
    specs = tmp_path / "specs"
    write(specs, "a_drum.dyn", DRUM)
    write(specs, "b_secret.dyn", DRUM)
    _make_unreadable(specs / "b_secret.dyn", monkeypatch)
    (specs / "c_folder.dyn").mkdir()
    (specs / "d_loop.dyn").symlink_to(specs / "d_loop.dyn")
    write(specs, "e_spring.dyn", SPRING_WRONG_FORMULA)
    write(specs, "f_drum.dyn", DRUM)
    result = run("check", str(specs))
    out = " ".join(result.stdout.split())  # the table wraps long cells
    assert result.exit_code == ExitCode.BAD_INPUT
    assert last_line(result.stdout) == "2 passed, 1 failed, 3 malformed"
    assert "b_secret.dyn" in out and "permission denied" in out
    assert "c_folder.dyn" in out and "it is a folder" in out
    assert "d_loop.dyn" in out and "symlink loop" in out
    assert "e_spring.dyn" in out and "not equivalent" in out


def test_a_wrong_formula_key_with_symbolic_givens_is_a_failed_answer(tmp_path: Path):
    path = write(tmp_path, "spring.dyn", SPRING_WRONG_FORMULA)
    result = run("solve", str(path), "--format", "json")
    assert result.exit_code == ExitCode.FAILED
    assert '"answer F"' in result.stdout and "not equivalent" in result.stdout


def test_a_formula_key_without_a_finite_value_is_a_failed_answer(tmp_path: Path):
    path = write(tmp_path, "spring.dyn", SPRING_WRONG_FORMULA.replace("k*h\n", "k*h*x/(x - x)\n"))
    result = run("solve", str(path), "--format", "json")
    assert result.exit_code == ExitCode.FAILED
    assert "no finite value" in result.stdout


# ---- output ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "target", ["/dev/null", "/dev/full", "/dev/stdout", "/proc/self/comm", "/sys/kernel/x"]
)
def test_special_targets_are_refused_before_any_write(target: str):
    # check_writable only inspects the path: no risk to the real devices
    if not os.path.exists(target.rsplit("/", 1)[0] or "/"):
        pytest.skip(f"no {target} here")
    with pytest.raises(FileAccessError, match="refusing to write"):
        check_writable(Path(target))


def _fifo(path: Path) -> None:
    os.mkfifo(path)


def _socket(path: Path) -> None:
    server = socket.socket(socket.AF_UNIX)
    server.bind(str(path))
    server.close()


def _device(path: Path) -> None:
    try:  # a copy of /dev/null's node (1, 3) in the temporary folder
        os.mknod(path, stat.S_IFCHR | 0o600, os.makedev(1, 3))
    except (PermissionError, AttributeError):
        pytest.skip("creating a device node needs root")


@posix
@pytest.mark.parametrize("make", [_fifo, _socket, _device], ids=["fifo", "socket", "device"])
def test_o_to_a_special_file_is_refused_and_the_file_stays(tmp_path: Path, make):  # type: ignore[no-untyped-def]
    spec = write(tmp_path, "drum.dyn", DRUM)
    target = tmp_path / "out.md"
    make(target)
    before = os.lstat(target)
    result = run("solve", str(spec), "-f", "markdown", "-o", str(target))
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "refusing to write" in result.stderr and "not a regular file" in result.stderr
    after = os.lstat(target)
    assert stat.S_IFMT(after.st_mode) == stat.S_IFMT(before.st_mode)
    assert after.st_ino == before.st_ino


@posix
def test_o_into_proc_is_refused(tmp_path: Path):
    if not os.path.exists("/proc/self/comm"):
        pytest.skip("no /proc here")
    spec = write(tmp_path, "drum.dyn", DRUM)
    result = run("solve", str(spec), "-f", "markdown", "-o", "/proc/self/comm")
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "/proc holds system interfaces" in result.stderr


@pytest.mark.parametrize(
    ("code", "words"),
    [
        (errno.ENOSPC, "no space left on device"),
        (errno.EACCES, "permission denied"),
        (errno.EROFS, "read-only file system"),
    ],
)
def test_write_errors_are_clear_and_keep_the_old_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, code: int, words: str
):
    spec = write(tmp_path, "drum.dyn", DRUM)
    target = write(tmp_path, "out.md", "the user's earlier output\n")

    def failing_replace(source: object, destination: object) -> None:
        raise OSError(code, os.strerror(code))

    monkeypatch.setattr(files.os, "replace", failing_replace)
    result = run("solve", str(spec), "-f", "markdown", "-o", str(target))
    assert result.exit_code == ExitCode.BAD_INPUT
    assert f"cannot write {target}: {words}" in result.stderr
    assert "Traceback" not in result.output
    assert target.read_text(encoding="utf-8") == "the user's earlier output\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drum.dyn", "out.md"]  # no temp file


@posix
def test_write_text_through_a_symlink_keeps_the_link(tmp_path: Path):
    real = write(tmp_path, "real.md", "old")
    link = tmp_path / "link.md"
    link.symlink_to(real)
    write_text(link, "new")
    assert link.is_symlink() and real.read_text(encoding="utf-8") == "new"


@posix
def test_check_names_a_special_file_or_loop_given_on_the_command_line(tmp_path: Path):
    loop = tmp_path / "loop.dyn"
    loop.symlink_to(loop)
    spec = write(tmp_path, "drum.dyn", DRUM)
    result = run("check", "/dev/zero", str(loop), str(spec))
    assert result.exit_code == ExitCode.BAD_INPUT
    assert "character device" in result.stdout and "symlink loop" in result.stdout
    assert last_line(result.stdout) == "1 passed, 0 failed, 2 malformed"
