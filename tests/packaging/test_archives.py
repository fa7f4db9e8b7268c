"""Crafted archives and XML against the harness and `servofmu validate`: entries
with absolute paths, `..`, backslashes, drive letters or links, too many entries, a zip bomb,
billion laughs, external entities; each refused with a clear message, nothing written
outside the target folder, no entity expanded or external file read."""

from __future__ import annotations

import shutil
import stat
import zipfile

import pytest

from servofmu.build import archive as archive_module
from servofmu.build.archive import ArchiveError, check_archive, safe_extract
from servofmu.build.ssp import SSP_DIR
from servofmu.harness import HarnessError, SystemError_, load_system, run

SECRET = "top-secret-3141592653"


@pytest.fixture(scope="module")
def out(fmus):
    return fmus["BearingFriction"].parent


def _zip(path, entries, link=None):
    """A zip with {name: bytes} entries (and a symbolic-link entry ``link`` = (name, target))."""
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
        for name, data in entries.items():
            zf.writestr(name, data)
        if link:
            info = zipfile.ZipInfo(link[0])
            info.external_attr = (stat.S_IFLNK | 0o777) << 16
            zf.writestr(info, link[1])
    return path


def _system_entries(name="seeker_gimbal"):
    return {
        f.relative_to(SSP_DIR / name).as_posix(): f.read_bytes()
        for f in (SSP_DIR / name).rglob("*")
        if f.is_file() and f.suffix in (".ssd", ".ssv")
    }


@pytest.mark.parametrize(
    "entry, message",
    [
        ("/tmp/servofmu_evil.txt", "absolute path"),
        ("../servofmu_evil.txt", "leaves the archive"),
        ("resources/../../servofmu_evil.txt", "leaves the archive"),
        ("..\\servofmu_evil.txt", "backslash"),
        ("C:servofmu_evil.txt", "absolute path"),
    ],
)
def test_path_traversal_entries_are_refused(tmp_path, entry, message):
    bad = _zip(tmp_path / "evil.ssp", {**_system_entries(), entry: b"pwned"})
    target = tmp_path / "deep" / "target"
    with pytest.raises(ArchiveError, match=message):
        safe_extract(bad, target)
    with pytest.raises(ArchiveError, match=message):
        load_system(bad)
    assert not list(tmp_path.rglob("servofmu_evil.txt"))
    assert not target.exists()  # nothing half-unpacked is left
    assert check_archive(bad)  # `servofmu validate` sees it without unpacking


def test_symbolic_link_entry_is_refused(tmp_path):
    bad = _zip(tmp_path / "link.ssp", _system_entries(), link=("resources/x", "/etc/passwd"))
    with pytest.raises(ArchiveError, match="symbolic link"):
        load_system(bad)


def test_zip_bomb_and_entry_count_are_bounded(tmp_path, monkeypatch):
    bomb = _zip(tmp_path / "bomb.ssp", {**_system_entries(), "resources/zeros": bytes(8 << 20)})
    assert bomb.stat().st_size < 100_000  # 8 MiB of zeros packs small
    monkeypatch.setattr(archive_module, "MAX_BYTES", 1 << 20)
    with pytest.raises(ArchiveError, match="zip bomb"):
        load_system(bomb)
    many = _zip(tmp_path / "many.ssp", {f"f{i}": b"" for i in range(50)})
    monkeypatch.setattr(archive_module, "MAX_ENTRIES", 20)
    with pytest.raises(ArchiveError, match="50 entries, more than 20"):
        safe_extract(many, tmp_path / "m")
    existing = tmp_path / "existing"
    existing.mkdir()
    (existing / "keep.txt").write_text("mine")
    monkeypatch.setattr(archive_module, "MAX_ENTRIES", 10_000)
    with pytest.raises(ArchiveError):
        safe_extract(bomb, existing)
    assert (existing / "keep.txt").read_text() == "mine"  # a refused unpack removes only its own


def test_not_a_zip(tmp_path):
    junk = tmp_path / "junk.ssp"
    junk.write_bytes(b"PK\x03\x04 not really")
    with pytest.raises(ArchiveError, match="not a readable zip"):
        load_system(junk)


BILLION_LAUGHS = b"""<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
 <!ENTITY lol9 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
]>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
  version="1.0" name="&lol9;"><ssd:System name="s"/></ssd:SystemStructureDescription>
"""


def _external_entity(secret_file) -> bytes:
    return f"""<?xml version="1.0"?>
<!DOCTYPE x [ <!ENTITY xxe SYSTEM "file://{secret_file}"> ]>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
  version="1.0" name="&xxe;"><ssd:System name="s"/></ssd:SystemStructureDescription>
""".encode()


@pytest.mark.parametrize("kind", ["billion_laughs", "external_entity"])
def test_entity_attacks_in_the_ssd_are_refused(tmp_path, kind):
    secret = tmp_path / "secret.txt"
    secret.write_text(SECRET)
    xml = BILLION_LAUGHS if kind == "billion_laughs" else _external_entity(secret)
    bad = _zip(tmp_path / "x.ssp", {**_system_entries(), "SystemStructure.ssd": xml})
    with pytest.raises(SystemError_, match="DOCTYPE/DTD is not allowed") as info:
        load_system(bad)
    assert SECRET not in str(info.value) and "lollol" not in str(info.value)


@pytest.mark.slow
def test_external_entity_in_a_parameter_set_is_refused(tmp_path, out):
    secret = tmp_path / "secret.txt"
    secret.write_text(SECRET)
    folder = tmp_path / "seeker_gimbal"
    shutil.copytree(SSP_DIR / "seeker_gimbal", folder)
    ssv = folder / "bearing.ssv"
    text = ssv.read_text().replace(
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<?xml version="1.0" encoding="UTF-8"?>\n<!DOCTYPE x [ <!ENTITY e SYSTEM '
        f'"file://{secret}"> ]>',
    )
    ssv.write_text(text.replace('description="grease"', 'description="&e;"'))
    with pytest.raises(SystemError_, match=r"bearing\.ssv: a DOCTYPE/DTD") as info:
        run(folder, fmu_dir=out, stop=0.01)
    assert SECRET not in str(info.value)


def _fmu_with_model_description(tmp_path, source_fmu, xml: bytes):
    target = tmp_path / source_fmu.name
    with zipfile.ZipFile(source_fmu) as src, zipfile.ZipFile(target, "w") as dst:
        for item in src.infolist():
            data = xml if item.filename == "modelDescription.xml" else src.read(item)
            dst.writestr(item, data)
    return target


def test_fmu_with_an_entity_attack_is_refused_by_the_harness_and_validate(tmp_path, out, capsys):
    from servofmu.cli import main

    secret = tmp_path / "secret.txt"
    secret.write_text(SECRET)
    md = (
        f'<?xml version="1.0"?>\n<!DOCTYPE f [ <!ENTITY e SYSTEM "file://{secret}"> ]>\n'
        '<fmiModelDescription fmiVersion="2.0" modelName="&e;" guid="x"/>'
    ).encode()
    fmu_dir = tmp_path / "fmus"
    fmu_dir.mkdir()
    for f in out.glob("*.fmu"):
        shutil.copy(f, fmu_dir)
    evil = _fmu_with_model_description(fmu_dir, out / "BearingFriction.fmu", md)
    with pytest.raises(SystemError_, match="DOCTYPE/DTD is not allowed"):
        load_system(SSP_DIR / "seeker_gimbal", fmu_dir=fmu_dir)
    assert main(["validate", str(evil)]) == 1
    printed = capsys.readouterr().out
    assert "DOCTYPE/DTD is not allowed" in printed and SECRET not in printed


def test_fmu_with_a_traversal_entry_is_refused_before_instantiation(tmp_path, out):
    fmu_dir = tmp_path / "fmus"
    fmu_dir.mkdir()
    for f in out.glob("*.fmu"):
        shutil.copy(f, fmu_dir)
    target = fmu_dir / "DCMotor.fmu"
    with zipfile.ZipFile(target, "a") as zf:
        zf.writestr("resources/../../../servofmu_evil.txt", b"pwned")
    # reading the FMU's modelDescription checks every entry of the FMU first
    with pytest.raises(SystemError_, match=r"DCMotor\.fmu: entry .* leaves the archive"):
        load_system(SSP_DIR / "seeker_gimbal", fmu_dir=fmu_dir)
    assert not list(tmp_path.rglob("servofmu_evil.txt"))


def test_duplicate_entries_are_refused(tmp_path):
    import warnings

    entries = _system_entries()
    bad = tmp_path / "twice.ssp"
    with warnings.catch_warnings():  # zipfile warns "Duplicate name" and writes it anyway
        warnings.simplefilter("ignore")
        with zipfile.ZipFile(bad, "w") as zf:
            for name, data in entries.items():
                zf.writestr(name, data)
            zf.writestr("SystemStructure.ssd", b"<the second one/>")
    with pytest.raises(ArchiveError, match=r"'SystemStructure\.ssd' occurs twice"):
        load_system(bad)
    with pytest.raises(ArchiveError, match="occurs twice"):
        safe_extract(bad, tmp_path / "t")
    assert not (tmp_path / "t").exists()
    assert any("occurs twice" in p for p in check_archive(bad))
    spelled = _zip(tmp_path / "spelled.ssp", {**entries, "./SystemStructure.ssd": b"<x/>"})
    with pytest.raises(ArchiveError, match="occurs twice"):
        safe_extract(spelled, tmp_path / "t")


def _declare_size(path, size):
    """Rewrite the uncompressed size every central-directory header of ``path`` declares (a
    bomb's headers need not be written by zipfile's honest sizes)."""
    data = bytearray(path.read_bytes())
    start = 0
    while (i := data.find(b"PK\x01\x02", start)) >= 0:
        data[i + 24 : i + 28] = size.to_bytes(4, "little")
        start = i + 4
    path.write_bytes(bytes(data))
    return path


def test_declared_sizes_refuse_a_bomb_before_anything_is_written(tmp_path):
    import time

    # one entry whose header declares 2.2 GiB (more than the 2 GiB limit): refused from the
    # headers alone, nothing unpacked, no time spent inflating
    bomb = _declare_size(_zip(tmp_path / "bomb.ssp", {"zeros": b"0" * 1000}), int(2.2 * 2**30))
    target = tmp_path / "target"
    t0 = time.perf_counter()
    with pytest.raises(ArchiveError, match=r"declare 2362232012 bytes unpacked.*zip bomb"):
        safe_extract(bomb, target)
    assert time.perf_counter() - t0 < 5.0  # not a speed test: minutes would mean inflating
    assert not target.exists()
    assert any("zip bomb" in p for p in check_archive(bomb))
    with pytest.raises(HarnessError, match="zip bomb"):
        load_system(bomb)


@pytest.mark.parametrize(
    "source, message",
    [
        ("../../x.fmu", "leaves the system folder"),
        ("../x.fmu", "leaves the system folder"),
        ("{tmp}/x.fmu", "is an absolute path"),
        ("file:///{tmp}/x.fmu", "is an absolute path or URI"),
        ("resources/link.fmu", "resolves outside the system folder"),
    ],
)
def test_component_source_must_lie_inside_the_system(tmp_path, out, source, message):
    outside = tmp_path / "x.fmu"  # a real FMU outside the system: never to be loaded
    shutil.copy(out / "DCMotor.fmu", outside)
    folder = tmp_path / "a" / "b" / "seeker_gimbal"
    shutil.copytree(SSP_DIR / "seeker_gimbal", folder)
    (folder / "resources").mkdir(exist_ok=True)
    (folder / "resources" / "link.fmu").symlink_to(outside)
    shutil.copy(outside, tmp_path / "a" / "x.fmu")
    ssd = folder / "SystemStructure.ssd"
    ssd.write_text(
        ssd.read_text().replace(
            'source="resources/DCMotor.fmu"', f'source="{source.format(tmp=tmp_path)}"'
        )
    )
    with pytest.raises(SystemError_, match=message) as info:
        load_system(folder, fmu_dir=out)
    assert "component 'motor'" in str(info.value)
    # a parameter set from outside is refused the same way
    ssd.write_text(
        ssd.read_text()
        .replace(f'source="{source.format(tmp=tmp_path)}"', 'source="resources/DCMotor.fmu"')
        .replace('source="motor.ssv"', 'source="../motor.ssv"')
    )
    shutil.copy(folder / "motor.ssv", folder.parent / "motor.ssv")
    with pytest.raises(SystemError_, match=r"parameter set '\.\./motor\.ssv' leaves"):
        load_system(folder, fmu_dir=out)


def test_component_source_outside_an_archive_is_refused_on_the_command_line(tmp_path, out, capsys):
    from servofmu.cli import main

    entries = _system_entries()
    entries["SystemStructure.ssd"] = entries["SystemStructure.ssd"].replace(
        b'source="resources/DCMotor.fmu"', b'source="../../x.fmu"'
    )
    for f in ("ServoController", "BearingFriction"):
        entries[f"resources/{f}.fmu"] = (out / f"{f}.fmu").read_bytes()
    shutil.copy(out / "DCMotor.fmu", tmp_path / "x.fmu")
    (tmp_path / "deep" / "er").mkdir(parents=True)
    bad = _zip(tmp_path / "deep" / "er" / "evil.ssp", entries)
    assert main(["run", str(bad), "--stop", "0.01", "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "'../../x.fmu' leaves the system folder" in err and len(err.splitlines()) == 1
    assert not (tmp_path / "o").exists()


def test_one_budget_covers_an_ssp_and_the_fmus_in_it(tmp_path, monkeypatch):
    """Three FMUs, each within the per-archive limit, together over it: refused from their
    headers before any FMU is unpacked (a per-archive cap let N bombs through as N × it)."""
    monkeypatch.setattr(archive_module, "MAX_BYTES", 4 << 20)
    bomb = _zip(tmp_path / "bomb.fmu", {"modelDescription.xml": b"<x/>", "zeros": bytes(3 << 20)})
    entries = _system_entries()
    for name in ("ServoController", "DCMotor", "BearingFriction"):
        entries[f"resources/{name}.fmu"] = bomb.read_bytes()
    ssp = _zip(tmp_path / "bombs.ssp", entries)
    assert ssp.stat().st_size < 100_000
    unpacked = []
    real = archive_module.safe_extract
    monkeypatch.setattr(
        "servofmu.harness.system.safe_extract",
        lambda a, *args, **kw: unpacked.append(a.name) or real(a, *args, **kw),
    )
    with pytest.raises(SystemError_, match=r"left of one budget of 4194304 bytes") as info:
        load_system(ssp)
    assert unpacked == ["bombs.ssp"]  # no FMU was unpacked
    assert len(info.value.problems) == 2  # the first FMU fits, the next two do not
