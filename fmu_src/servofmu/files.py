"""The files servofmu reads and writes: inputs read whole within a size cap, results whole or
not at all, and scratch folders that the next run cleans when a run was killed.

- :func:`read_input` reads a user's input file (a catalogue, a margin input, measured data, a
  signal table) with a size cap and checks that it is UTF-8 text; every
  refusal names the file (:class:`InputFileError`, a ValueError: bad input).
- :func:`written` is the one way a result (CSV, Parquet, PNG, JSON, text, FMU, SSP) reaches
  its final name: it is written to a temporary name in the same folder, flushed to disk and
  renamed into place, so a file under its final name is always whole. SIGINT and SIGTERM
  wait while a result is written (it is short) and act once it is in place. A file that
  cannot be written (a full disk, a folder that cannot be written) raises
  :class:`OutputError` naming the path, and no partial file stays under either name.
  Results get the mode that the umask gives new files.
- A temporary name carries the writing process's id: a run killed with SIGKILL leaves it
  behind, and the next run that writes into that folder removes it once that process is gone
  (:func:`remove_stale_parts`). Scratch folders (unpacked archives, staged builds) live in
  one folder per user in the system's temporary folder (:func:`scratch_root`), each locked by
  its process while it lives: :func:`scratch_folder` removes the folders of processes that
  are gone.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import re
import shutil
import stat
import tempfile
import time
import weakref
from collections.abc import Iterator
from pathlib import Path

#: Largest input file read [bytes] (a catalogue, a margin input, a measured-data table).
MAX_INPUT_BYTES = 256 * 1024**2
#: The exit status of the command line when a result cannot be written (sysexits' EX_IOERR).
EXIT_OUTPUT = 74
#: Marks the temporary name of a result being written: ``.NAME.PID.XXXXXXXX.part.SUFFIX``
#: (the final suffix kept last: writers that choose a format by it, e.g. matplotlib, see it).
PART_SUFFIX = ".part"
_PART = re.compile(r"\..+\.(\d+)\.[^.]+\.part(\.[^.]*)?")
#: A scratch folder without a lock is left alone this long [s] (its process may be creating
#: the lock right now).
STALE_AFTER = 60.0


class InputFileError(ValueError):
    """An input file that cannot be read as text (too large, not UTF-8, unreadable); the
    message names the file (bad input: the command line exits 2)."""


class OutputError(OSError):
    """A result that could not be written (a full disk, a folder that cannot be written); the
    message names the path. No partial file stays under its final name (the command line
    exits :data:`EXIT_OUTPUT`)."""

    def __init__(self, path, exc: OSError):
        super().__init__(exc.errno, f"cannot write {path}: {exc.strerror or exc}")
        self.path = Path(path)

    def __str__(self):
        return self.strerror


# ----------------------------------------------------------------------------- reading
def read_input(path, what: str = "input file", max_bytes: int | None = None) -> str:
    """The text of input file ``path``: at most ``max_bytes`` read, UTF-8 (a UTF-8 byte-order
    mark is dropped); :class:`InputFileError` naming the file otherwise.

    Parameters
    ----------
    path : str or pathlib.Path
        The file.
    what : str
        What it is, for messages ("catalogue", "margin input", …).
    max_bytes : int, optional
        Largest size read [bytes] (default :data:`MAX_INPUT_BYTES`).

    Returns
    -------
    str
        Its text.

    Raises
    ------
    InputFileError
        For a file that cannot be read, is larger than ``max_bytes`` (``/dev/zero`` too), is
        UTF-16 or UTF-32 (a byte-order mark), holds NUL bytes or is not UTF-8.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = Path(tmp) / "mine.toml"
    ...     _ = path.write_text("x = 1", encoding="utf-16")
    ...     try:
    ...         read_input(path, "catalogue")
    ...     except InputFileError as exc:
    ...         print(str(exc).replace(str(path), "mine.toml"))
    mine.toml: catalogue is UTF-16 text (a byte-order mark): save it as UTF-8
    >>> try:
    ...     read_input("/dev/zero", "catalogue", max_bytes=1024)
    ... except InputFileError as exc:
    ...     print(exc)
    /dev/zero: catalogue is larger than 1024 bytes: not read
    """
    path = Path(path)
    data = read_input_bytes(path, what, max_bytes)
    for bom, name in (
        (b"\xff\xfe\x00\x00", "UTF-32"),
        (b"\x00\x00\xfe\xff", "UTF-32"),
        (b"\xff\xfe", "UTF-16"),
        (b"\xfe\xff", "UTF-16"),
    ):
        if data.startswith(bom):
            raise InputFileError(
                f"{path}: {what} is {name} text (a byte-order mark): save it as UTF-8"
            )
    if b"\x00" in data:
        at = data.index(b"\x00")
        raise InputFileError(
            f"{path}: {what} holds a NUL byte (at byte {at}): not a text file (UTF-16 without "
            "a byte-order mark, or binary data); save it as UTF-8 text"
        )
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputFileError(
            f"{path}: {what} is not UTF-8 text (byte {data[exc.start]:#04x} at offset "
            f"{exc.start}); save it as UTF-8"
        ) from None
    return text.removeprefix("\ufeff")


def read_input_bytes(path, what: str = "input file", max_bytes: int | None = None) -> bytes:
    """The bytes of input file ``path``, at most ``max_bytes`` (default
    :data:`MAX_INPUT_BYTES`) read; :class:`InputFileError` naming the file otherwise (an XML
    file declares its own encoding: its parser checks it).

    Returns
    -------
    bytes

    Examples
    --------
    >>> try:
    ...     read_input_bytes("/dev/zero", "parameter set", max_bytes=8)
    ... except InputFileError as exc:
    ...     print(exc)
    /dev/zero: parameter set is larger than 8 bytes: not read
    """
    path = Path(path)
    max_bytes = MAX_INPUT_BYTES if max_bytes is None else max_bytes
    try:
        with open(path, "rb") as fh:
            data = fh.read(max_bytes + 1)
    except OSError as exc:
        raise InputFileError(f"{path}: cannot be read ({exc.strerror or exc})") from None
    if len(data) > max_bytes:
        raise InputFileError(f"{path}: {what} is larger than {max_bytes} bytes: not read")
    return data


# ----------------------------------------------------------------------------- writing
def file_mode() -> int:
    """The mode the umask gives a new regular file (0o666 less the umask).

    Returns
    -------
    int

    Examples
    --------
    >>> file_mode() & 0o600 == 0o600  # the owner reads and writes it
    True
    """
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return 0o666 & ~int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return 0o666 & ~mask


_CLEANED: set[Path] = set()  # folders whose stale temporary files this process removed


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process
        return True
    return True


def remove_stale_parts(folder) -> list[Path]:
    """Remove the temporary files that runs killed while writing left in ``folder``
    (``.NAME.PID.XXXXXXXX.part.SUFFIX`` of a process that is gone); returns them.

    Parameters
    ----------
    folder : str or pathlib.Path

    Returns
    -------
    list of pathlib.Path
        The files removed.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     stale = Path(tmp) / ".results.csv.999999999.x1y2.part.csv"  # no such process
    ...     _ = stale.write_text("half a table")
    ...     [p.name for p in remove_stale_parts(tmp)]
    ['.results.csv.999999999.x1y2.part.csv']
    """
    removed = []
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return removed
    for e in entries:
        match = _PART.fullmatch(e.name)
        if match is None or _alive(int(match.group(1))):
            continue
        with contextlib.suppress(OSError):
            (Path(folder) / e.name).unlink()
            removed.append(Path(folder) / e.name)
    return removed


def output_folder(folder) -> Path:
    """Create the results folder ``folder`` (and its parents); :class:`OutputError` naming it
    when it cannot be created.

    Returns
    -------
    pathlib.Path

    Examples
    --------
    >>> try:
    ...     output_folder("/proc/no_results_here")
    ... except OutputError as exc:
    ...     print(str(exc).split(":")[0])
    cannot write /proc/no_results_here
    """
    folder = Path(folder)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(folder, exc) from None
    return folder


@contextlib.contextmanager
def written(path) -> Iterator[Path]:
    """Write a result under ``path`` whole or not at all: yields a temporary path in the same
    folder to write to (its name ends in ``path``'s suffix); when the block ends normally that
    file is flushed to disk, given the umask's mode and renamed to ``path``. SIGINT and
    SIGTERM wait until then (:func:`~servofmu.harness.interrupt.protected`) and act once the
    file is in place. On an exception the temporary file is removed and nothing changes under
    ``path``;
    an OSError (a full disk, a folder that cannot be written) is raised as
    :class:`OutputError` naming ``path``.

    Parameters
    ----------
    path : str or pathlib.Path
        The final name.

    Returns
    -------
    contextmanager yielding pathlib.Path
        The temporary name to write to.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     target = Path(tmp) / "table.csv"
    ...     with written(target) as part:
    ...         _ = part.write_text("time [s]\\n0\\n")
    ...     try:
    ...         with written(target) as part:
    ...             _ = part.write_text("half")
    ...             raise KeyboardInterrupt
    ...     except KeyboardInterrupt:
    ...         pass
    ...     print(target.read_text().splitlines(), sorted(p.name for p in Path(tmp).iterdir()))
    ['time [s]', '0'] ['table.csv']
    """
    from servofmu.harness.interrupt import protected

    path = Path(path)
    folder = output_folder(path.parent)
    if folder.resolve() not in _CLEANED:
        remove_stale_parts(folder)
        _CLEANED.add(folder.resolve())
    try:
        fd, name = tempfile.mkstemp(
            dir=folder, prefix=f".{path.name}.{os.getpid()}.", suffix=PART_SUFFIX + path.suffix
        )
        os.close(fd)
    except OSError as exc:
        raise OutputError(path, exc) from None
    part = Path(name)
    try:
        with protected():  # a signal waits until the file is whole under its name
            yield part
            _flush(part)
            os.chmod(part, file_mode())
            os.replace(part, path)
    except OSError as exc:
        with contextlib.suppress(OSError):
            part.unlink()
        if isinstance(exc, OutputError):
            raise
        raise OutputError(path, exc) from None
    except BaseException:
        with contextlib.suppress(OSError):
            part.unlink()
        raise


def _flush(path: Path) -> None:
    """Flush the file's data to disk (a rename after a crash then never shows a hollow file)."""
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def write_text(path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all (:func:`written`).

    Returns
    -------
    pathlib.Path
        ``path``.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     write_text(Path(tmp) / "report.txt", "ok\\n").read_text()
    'ok\\n'
    """
    with written(path) as part:
        part.write_text(text, encoding="utf-8")
    return Path(path)


def save_figure(fig, path, **kwargs) -> Path:
    """Save matplotlib figure ``fig`` to ``path`` (its format from the suffix; ``kwargs`` as
    ``savefig``'s) whole or not at all (:func:`written`).

    Returns
    -------
    pathlib.Path
        ``path``.

    Examples
    --------
    >>> import tempfile
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig = plt.figure(figsize=(1, 1))
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     save_figure(fig, Path(tmp) / "f.png", dpi=20).read_bytes()[:4]
    b'\x89PNG'
    >>> plt.close(fig)
    """
    with written(path) as part:
        fig.savefig(part, **kwargs)
    return Path(path)


# ----------------------------------------------------------------------------- scratch
def scratch_root() -> Path:
    """The folder of this user's scratch folders: ``servofmu-UID`` in the system's temporary
    folder, created with mode 0700 and refused when another user owns it.

    Returns
    -------
    pathlib.Path

    Examples
    --------
    >>> scratch_root().name.startswith("servofmu-")
    True
    """
    uid = os.getuid() if hasattr(os, "getuid") else 0
    root = Path(tempfile.gettempdir()) / f"servofmu-{uid}"
    try:
        root.mkdir(mode=0o700, exist_ok=True)
        info = os.lstat(root)
    except OSError as exc:
        raise OutputError(root, exc) from None
    if not stat.S_ISDIR(info.st_mode) or (hasattr(os, "getuid") and info.st_uid != uid):
        raise OutputError(
            root, OSError(0, "not a folder of this user: remove it, or set TMPDIR elsewhere")
        )
    return root


class ScratchFolder:
    """A temporary folder under :func:`scratch_root`, locked by this process while it exists
    (like :class:`tempfile.TemporaryDirectory`: ``name``, :meth:`cleanup`)."""

    def __init__(self, prefix: str):
        root = scratch_root()
        if root not in _CLEANED:
            remove_stale_scratch(root)
            _CLEANED.add(root)
        try:
            self.name = tempfile.mkdtemp(prefix=f"{prefix}{os.getpid()}-", dir=root)
            lock = os.open(Path(self.name) / ".lock", os.O_CREAT | os.O_RDWR, 0o600)
        except OSError as exc:
            raise OutputError(root, exc) from None
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        # removed when cleaned up, collected, or at the interpreter's exit (as TemporaryDirectory)
        self._finalizer = weakref.finalize(self, _remove_scratch, self.name, lock)

    def cleanup(self) -> None:
        self._finalizer()

    def __enter__(self) -> str:
        return self.name

    def __exit__(self, *exc) -> None:
        self.cleanup()


def _remove_scratch(name: str, lock: int) -> None:
    shutil.rmtree(name, ignore_errors=True)
    os.close(lock)  # releases the lock


def scratch_folder(prefix: str) -> ScratchFolder:
    """A new scratch folder (:class:`ScratchFolder`) named ``PREFIX<pid>-…``; the first in a
    process removes the folders of processes that are gone (:func:`remove_stale_scratch`).

    Returns
    -------
    ScratchFolder

    Examples
    --------
    >>> with scratch_folder("demo_") as name:
    ...     Path(name).parent == scratch_root()
    True
    """
    return ScratchFolder(prefix)


def remove_stale_scratch(root=None) -> list[str]:
    """Remove the scratch folders under ``root`` (default :func:`scratch_root`) whose process
    is gone (its lock is free), and those without a lock; returns their names.

    Returns
    -------
    list of str

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     old = Path(tmp) / "servofmu_fmus_1-abc"  # a killed run's, no lock held
    ...     old.mkdir()
    ...     os.utime(old, (0, 0))
    ...     remove_stale_scratch(tmp)
    ['servofmu_fmus_1-abc']
    """
    root = Path(root) if root is not None else scratch_root()
    removed = []
    try:
        entries = [e for e in os.scandir(root) if e.is_dir(follow_symlinks=False)]
    except OSError:
        return removed
    for e in entries:
        lock = Path(root) / e.name / ".lock"
        try:
            fd = os.open(lock, os.O_RDWR)
        except FileNotFoundError:  # not yet locked, or left without a lock: only an old one
            fd = None
            with contextlib.suppress(OSError):
                if time.time() - e.stat(follow_symlinks=False).st_mtime < STALE_AFTER:
                    continue
        except OSError:
            continue
        try:
            if fd is not None:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:  # held: its process lives
            os.close(fd)
            continue
        shutil.rmtree(Path(root) / e.name, ignore_errors=True)
        if fd is not None:
            os.close(fd)
        removed.append(e.name)
    return removed
