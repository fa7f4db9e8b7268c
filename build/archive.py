"""Safe unpacking of .ssp and .fmu archives (zip), for the build's validation and the harness.

Refused: entries with absolute paths, drive letters, backslashes or ``..`` components, links
(symbolic links stored in the zip), two entries of one name (a reader would take either),
more than ``max_entries`` entries, or more than ``max_bytes`` unpacked in total — the sizes
the headers declare are checked before anything is written (a zip bomb is refused at once),
and the bytes are counted again while unpacking (a header may lie). An archive and the
archives in it (an .ssp and its FMUs) share one :class:`Budget`."""

from __future__ import annotations

import shutil
import stat
import zipfile
from pathlib import Path, PurePosixPath

MAX_ENTRIES = 10_000
MAX_BYTES = 2 * 1024**3  # 2 GiB unpacked
_CHUNK = 1 << 20


class ArchiveError(ValueError):
    """An archive was refused (the message says which entry and why)."""


class Budget:
    """One budget of unpacked bytes and entries shared by an archive and every archive
    unpacked from it (an .ssp and its FMUs): a per-archive cap would let N bomb FMUs through
    as N times the cap. :meth:`reserve` charges an archive's declared sizes and entry count
    before anything of it is written; :func:`safe_extract` then unpacks it within what was
    reserved for it, counting the bytes again as they come.

    Parameters
    ----------
    max_bytes : int, optional
        Unpacked bytes for everything together (default :data:`MAX_BYTES`, read at creation).
    max_entries : int, optional
        Entries for everything together (default :data:`MAX_ENTRIES`).

    Examples
    --------
    >>> import tempfile, zipfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     fmu = Path(tmp) / "a.fmu"
    ...     with zipfile.ZipFile(fmu, "w") as zf:
    ...         zf.writestr("modelDescription.xml", b"x" * 600)
    ...     budget = Budget(max_bytes=1000)
    ...     print(budget.reserve(fmu), budget.reserve(fmu))  # charged once: (bytes, entries)
    ...     try:
    ...         budget.reserve(fmu.rename(Path(tmp) / "b.fmu"))  # a second 600 bytes
    ...     except ArchiveError as exc:
    ...         print(exc)  # doctest: +ELLIPSIS
    (600, 1) (600, 1)
    b.fmu: its entries declare 600 bytes unpacked, more than the 400 left of one budget ...
    """

    def __init__(self, max_bytes: int | None = None, max_entries: int | None = None):
        self.max_bytes = MAX_BYTES if max_bytes is None else max_bytes
        self.max_entries = MAX_ENTRIES if max_entries is None else max_entries
        self.bytes = 0
        self.entries = 0
        self.reserved: dict[Path, tuple[int, int]] = {}  # archive → (bytes, entries)

    def reserve(self, archive) -> tuple[int, int]:
        """Charge ``archive``'s declared unpacked bytes and its entries (once per archive);
        ArchiveError, nothing charged, when they exceed what is left. Returns (bytes,
        entries) reserved for it."""
        archive = Path(archive)
        key = archive.resolve()
        if key in self.reserved:
            return self.reserved[key]
        try:
            with zipfile.ZipFile(archive) as zf:
                infos = zf.infolist()
        except (zipfile.BadZipFile, OSError) as exc:
            raise ArchiveError(f"{archive}: not a readable zip archive ({exc})") from None
        left_entries = self.max_entries - self.entries
        if len(infos) > left_entries:
            raise ArchiveError(
                f"{archive.name}: {len(infos)} entries, more than the {left_entries} left of "
                f"one budget of {self.max_entries} for the archive and the archives in it"
            )
        left = self.max_bytes - self.bytes
        try:
            check_members(infos, archive, left)
        except ArchiveError as exc:
            if "declare" not in str(exc):
                raise
            declared = sum(i.file_size for i in infos)
            raise ArchiveError(
                f"{archive.name}: its entries declare {declared} bytes unpacked, more than "
                f"the {left} left of one budget of {self.max_bytes} bytes for the archive and "
                "the archives in it; refusing a possible zip bomb (nothing unpacked)"
            ) from None
        charged = (sum(i.file_size for i in infos), len(infos))
        self.bytes += charged[0]
        self.entries += charged[1]
        self.reserved[key] = charged
        return charged


def check_member(info: zipfile.ZipInfo, archive: Path) -> PurePosixPath:
    """The safe relative path of one zip entry, or ArchiveError.

    Parameters
    ----------
    info : zipfile.ZipInfo
        The entry (its name and, for links, its Unix mode in ``external_attr``).
    archive : pathlib.Path
        The archive it belongs to (for messages only).

    Returns
    -------
    pathlib.PurePosixPath
        The entry's path relative to the folder it unpacks into.

    Raises
    ------
    ArchiveError
        For an absolute path, a drive letter, a backslash, a ``..`` component or a symbolic
        link.

    Examples
    --------
    >>> import zipfile
    >>> from pathlib import Path
    >>> check_member(zipfile.ZipInfo("resources/model.py"), Path("demo.fmu"))
    PurePosixPath('resources/model.py')
    >>> try:
    ...     check_member(zipfile.ZipInfo("../evil.py"), Path("demo.fmu"))
    ... except ArchiveError as exc:
    ...     print(exc)
    demo.fmu: entry '../evil.py' leaves the archive folder ('..')
    """
    name = info.filename
    where = f"{archive.name}: entry {name!r}"
    if "\\" in name:
        raise ArchiveError(f"{where} contains a backslash")
    path = PurePosixPath(name)
    if path.is_absolute() or (path.parts and ":" in path.parts[0]):
        raise ArchiveError(f"{where} is an absolute path")
    if ".." in path.parts:
        raise ArchiveError(f"{where} leaves the archive folder ('..')")
    mode = info.external_attr >> 16
    if stat.S_ISLNK(mode):
        raise ArchiveError(f"{where} is a symbolic link")
    return path


def check_members(infos, archive: Path, max_bytes: int) -> list[PurePosixPath]:
    """The safe relative paths of all entries (:func:`check_member`), or ArchiveError for the
    first unsafe entry, a name that occurs twice (also after normalisation: ``a//b``,
    ``./a/b``), or declared uncompressed sizes above ``max_bytes`` in total.

    Parameters
    ----------
    infos : list of zipfile.ZipInfo
        The entries of the archive (``ZipFile.infolist()``).
    archive : pathlib.Path
        The archive (for messages only).
    max_bytes : int
        Largest total of the declared uncompressed sizes [bytes].

    Returns
    -------
    list of pathlib.PurePosixPath
        The entries' relative paths, in the order of ``infos``.

    Raises
    ------
    ArchiveError
        For the first unsafe entry, a repeated name, or too many bytes declared.

    Examples
    --------
    >>> import zipfile
    >>> from pathlib import Path
    >>> a, b = zipfile.ZipInfo("a/b.txt"), zipfile.ZipInfo("./a/b.txt")
    >>> check_members([a], Path("demo.ssp"), max_bytes=1024)
    [PurePosixPath('a/b.txt')]
    >>> try:
    ...     check_members([a, b], Path("demo.ssp"), max_bytes=1024)
    ... except ArchiveError as exc:
    ...     print(exc)
    demo.ssp: entry './a/b.txt' occurs twice (also as 'a/b.txt'): a reader would take either
    >>> a.file_size = 2048  # what the header declares [bytes]
    >>> try:
    ...     check_members([a], Path("demo.ssp"), max_bytes=1024)
    ... except ArchiveError as exc:
    ...     print(exc)  # doctest: +ELLIPSIS
    demo.ssp: its entries declare 2048 bytes unpacked, more than 1024; refusing a possible ...
    """
    paths, seen = [], {}
    for info in infos:
        path = check_member(info, archive)
        key = path.as_posix().rstrip("/")
        if key in seen:
            raise ArchiveError(
                f"{archive.name}: entry {info.filename!r} occurs twice (also as "
                f"{seen[key]!r}): a reader would take either"
            )
        seen[key] = info.filename
        paths.append(path)
    declared = sum(info.file_size for info in infos)
    if declared > max_bytes:
        raise ArchiveError(
            f"{archive.name}: its entries declare {declared} bytes unpacked, more than "
            f"{max_bytes}; refusing a possible zip bomb (nothing unpacked)"
        )
    return paths


def safe_extract(
    archive, dest, max_entries: int | None = None, max_bytes: int | None = None, budget=None
):
    """Unpack ``archive`` into ``dest`` (created) after checking every entry; returns dest.
    Limits default to :data:`MAX_ENTRIES` and :data:`MAX_BYTES` (read at call time); with a
    :class:`Budget`, the archive is charged to it (once) and unpacked within what it declared.
    On a refusal midway, what this call wrote is removed again.

    Parameters
    ----------
    archive : str or pathlib.Path
        The zip archive (.fmu, .ssp).
    dest : str or pathlib.Path
        The folder to unpack into (created with its parents if missing).
    max_entries : int, optional
        Largest number of entries [-]; default :data:`MAX_ENTRIES`.
    max_bytes : int, optional
        Largest total unpacked size [bytes], declared and counted; default
        :data:`MAX_BYTES`.
    budget : Budget, optional
        A budget shared with other archives (an .ssp and its FMUs); it replaces the limits.

    Returns
    -------
    pathlib.Path
        ``dest``.

    Raises
    ------
    ArchiveError
        For an unreadable archive, an unsafe or repeated entry, or too many entries or
        bytes; nothing this call wrote stays.

    Examples
    --------
    A two-entry archive made on the spot, unpacked; then unpacked with a limit below its
    22 + 5 bytes:

    >>> import tempfile, zipfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     fmu = Path(tmp) / "demo.fmu"
    ...     with zipfile.ZipFile(fmu, "w") as zf:
    ...         zf.writestr("modelDescription.xml", "<fmiModelDescription/>")
    ...         zf.writestr("resources/model.py", "x = 1")
    ...     out = safe_extract(fmu, Path(tmp) / "unpacked")
    ...     print(sorted(p.relative_to(out).as_posix() for p in out.rglob("*")))
    ...     try:
    ...         safe_extract(fmu, Path(tmp) / "small", max_bytes=10)
    ...     except ArchiveError as exc:
    ...         print(exc)  # doctest: +ELLIPSIS
    ...     print((Path(tmp) / "small").exists())  # nothing left behind
    ['modelDescription.xml', 'resources', 'resources/model.py']
    demo.fmu: its entries declare 27 bytes unpacked, more than 10; refusing a possible zip ...
    False
    """
    archive, dest = Path(archive), Path(dest)
    if budget is not None:
        max_bytes, max_entries = budget.reserve(archive)
    max_entries = MAX_ENTRIES if max_entries is None else max_entries
    max_bytes = MAX_BYTES if max_bytes is None else max_bytes
    try:
        zf = zipfile.ZipFile(archive)
    except (zipfile.BadZipFile, OSError) as exc:
        raise ArchiveError(f"{archive}: not a readable zip archive ({exc})") from None
    with zf:
        infos = zf.infolist()
        if len(infos) > max_entries:
            raise ArchiveError(f"{archive.name}: {len(infos)} entries, more than {max_entries}")
        members = list(zip(infos, check_members(infos, archive, max_bytes), strict=True))
        created = not dest.exists()
        dest.mkdir(parents=True, exist_ok=True)
        root = dest.resolve()
        written: list[Path] = []
        total = 0
        try:
            for info, rel in members:
                target = root.joinpath(*rel.parts)
                if not target.resolve().is_relative_to(root):
                    raise ArchiveError(f"{archive.name}: entry {info.filename!r} leaves the folder")
                if info.is_dir():
                    target.mkdir(parents=True, exist_ok=True)
                    continue
                target.parent.mkdir(parents=True, exist_ok=True)
                written.append(target)
                with zf.open(info) as src, open(target, "wb") as out:
                    while chunk := src.read(_CHUNK):
                        total += len(chunk)
                        if total > max_bytes:
                            raise ArchiveError(
                                f"{archive.name}: unpacks to more than {max_bytes} bytes "
                                f"(stopped at entry {info.filename!r}); refusing a possible "
                                "zip bomb"
                            )
                        out.write(chunk)
        except (ArchiveError, zipfile.BadZipFile, OSError, EOFError) as exc:
            if created:
                shutil.rmtree(dest, ignore_errors=True)
            else:  # a folder that was there: remove only what this call wrote
                for f in written:
                    f.unlink(missing_ok=True)
            if isinstance(exc, ArchiveError):
                raise
            raise ArchiveError(f"{archive.name}: cannot be unpacked ({exc})") from None
    return dest


def read_member(archive, name: str, max_bytes: int = 64 * 1024**2) -> bytes:
    """One entry of a zip (e.g. modelDescription.xml) after the same checks, size-bounded.

    Parameters
    ----------
    archive : str or pathlib.Path
        The zip archive.
    name : str
        The entry's name in the archive.
    max_bytes : int, default 64 MiB
        Largest size of the entry [bytes], declared and counted.

    Returns
    -------
    bytes
        The entry's content.

    Raises
    ------
    ArchiveError
        For an unreadable archive, an unsafe or repeated entry (:func:`check_members`), a
        missing entry, or one larger than ``max_bytes``.

    Examples
    --------
    >>> import tempfile, zipfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     fmu = Path(tmp) / "demo.fmu"
    ...     with zipfile.ZipFile(fmu, "w") as zf:
    ...         zf.writestr("modelDescription.xml", "<fmiModelDescription/>")
    ...     print(read_member(fmu, "modelDescription.xml"))
    ...     try:
    ...         read_member(fmu, "modelDescription.xml", max_bytes=8)
    ...     except ArchiveError as exc:
    ...         print(exc)
    b'<fmiModelDescription/>'
    demo.fmu: entry 'modelDescription.xml' declares 22 bytes, more than 8
    """
    archive = Path(archive)
    try:
        with zipfile.ZipFile(archive) as zf:
            infos = zf.infolist()
            check_members(infos, archive, MAX_BYTES)  # one entry of each name, sizes declared
            matches = [i for i in infos if i.filename == name]
            if not matches:
                raise ArchiveError(f"{archive.name}: no {name}")
            info = matches[0]
            if info.file_size > max_bytes:
                raise ArchiveError(
                    f"{archive.name}: entry {name!r} declares {info.file_size} bytes, more "
                    f"than {max_bytes}"
                )
            data = bytearray()
            with zf.open(info) as src:
                while chunk := src.read(_CHUNK):
                    data += chunk
                    if len(data) > max_bytes:
                        raise ArchiveError(
                            f"{archive.name}: entry {name!r} is larger than {max_bytes} bytes"
                        )
    except (zipfile.BadZipFile, OSError, EOFError) as exc:
        raise ArchiveError(f"{archive}: not a readable zip archive ({exc})") from None
    return bytes(data)


def check_archive(archive) -> list[str]:
    """Every entry of ``archive`` that :func:`safe_extract` would refuse (empty: fine), without
    unpacking anything.

    Parameters
    ----------
    archive : str or pathlib.Path
        The zip archive.

    Returns
    -------
    list of str
        One message per refused entry (or for an unreadable archive); empty when the
        archive is safe to unpack.

    Examples
    --------
    >>> import tempfile, zipfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     ssp = Path(tmp) / "demo.ssp"
    ...     with zipfile.ZipFile(ssp, "w") as zf:
    ...         zf.writestr("SystemStructure.ssd", "<ssd/>")
    ...     print(check_archive(ssp))
    ...     with zipfile.ZipFile(ssp, "a") as zf:
    ...         zf.writestr("../outside.txt", "x")
    ...     print(check_archive(ssp))
    []
    ["demo.ssp: entry '../outside.txt' leaves the archive folder ('..')"]
    """
    archive = Path(archive)
    try:
        with zipfile.ZipFile(archive) as zf:
            infos = zf.infolist()
    except (zipfile.BadZipFile, OSError) as exc:
        return [f"{archive}: not a readable zip archive ({exc})"]
    problems = []
    if len(infos) > MAX_ENTRIES:
        problems.append(f"{archive.name}: {len(infos)} entries, more than {MAX_ENTRIES}")
    for info in infos:
        try:
            check_member(info, archive)
        except ArchiveError as exc:
            problems.append(str(exc))
    if not problems:
        try:
            check_members(infos, archive, MAX_BYTES)
        except ArchiveError as exc:
            problems.append(str(exc))
    return problems
