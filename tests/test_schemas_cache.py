"""The on-disk cache of built schemas: written cold, read warm, equivalent, robust to damage and to schema edits.

Every test points the cache at ``tmp_path`` (``XDG_CACHE_HOME``), never at the real one.
"""

from __future__ import annotations

import os
import re
import shutil
from dataclasses import dataclass, field
from pathlib import Path

import pytest
import xmlschema

from edsconv import cache as cache_module
from edsconv.xml import schemas
from edsconv.xml.safe import read_xml

CORPUS = Path(__file__).resolve().parents[1] / "corpus" / "xml"
XSD = "CIP_Device_Profile.xsd"  # XSD 1.1, with assertions: the hardest one to round-trip
ADDRESS = re.compile(r"0x[0-9a-f]+")


@dataclass
class Cache:
    dir: Path
    #: The schemas actually built (not unpickled), in order.
    builds: list[str] = field(default_factory=list)


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """The cache directory, not yet created, under tmp_path; ``build_schema`` calls are counted."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    state = Cache(schemas.cache_dir())
    assert state.dir == tmp_path / "xdg" / "edsconv"
    real_build = schemas.build_schema

    def counting_build(xsd):
        state.builds.append(xsd)
        return real_build(xsd)

    monkeypatch.setattr(schemas, "build_schema", counting_build)
    return state


def cache_file(xsd: str = XSD) -> Path:
    path = schemas.schema_cache_file(xsd, xmlschema.__version__)
    assert path is not None
    return path


def outcome(schema: xmlschema.XMLSchemaBase, path: Path) -> list[tuple]:
    """Everything validate.py reports of each error; object addresses in messages differ between any two builds."""
    document = read_xml(path)
    return [(error.reason, ADDRESS.sub("0x", error.message), error.path,
             document.position(error.elem) if error.elem is not None else None)
            for error in schema.iter_errors(document.tree)]


def test_cold_build_writes_the_cache(cache):
    schema = schemas.load_schema_uncached(XSD)
    assert cache.builds == [XSD]
    assert isinstance(schema, xmlschema.XMLSchema11)
    assert cache_file().is_file()
    assert [p.name for p in cache.dir.iterdir()] == [cache_file().name]  # no temporary file left behind
    if hasattr(os, "getuid"):
        assert cache.dir.stat().st_mode & 0o777 == 0o700
        assert cache_file().stat().st_mode & 0o077 == 0


@pytest.mark.parametrize("xsd, instances", [
    ("CIP_Device_Profile.xsd", ["cip-device/valid-chassis.xml", "cip-device/invalid-vendcode-access.xml"]),
    ("ENet_CommNet_Profile.xsd",
     ["ethernetip-commnet/valid-complete.xml", "ethernetip-commnet/invalid-interface-type.xml"]),
    ("FL-net_Device_Profile.xsd", ["flnet-device/valid-complete.xml", "flnet-device/invalid-node-number.xml"]),
])
def test_warm_load_validates_like_a_fresh_build(cache, xsd, instances):
    schemas.load_schema_uncached(xsd)
    warm = schemas.load_schema_uncached(xsd)
    assert cache.builds == [xsd]  # the second one came from the disk
    fresh = schemas.build_schema(xsd)
    assert type(warm) is type(fresh) and warm is not fresh
    valid, invalid = (CORPUS / name for name in instances)
    assert outcome(warm, valid) == outcome(fresh, valid) == []
    assert warm.is_valid(str(valid))
    assert outcome(warm, invalid) == outcome(fresh, invalid) != []


@pytest.mark.parametrize("damage", [b"", b"not a pickle", b"\x80\x05garbage", b"\x80\x05N."],
                         ids=["empty", "text", "truncated", "not-a-schema"])
def test_a_corrupt_cache_file_falls_back_and_is_rewritten(cache, damage):
    cache.dir.mkdir(parents=True, mode=0o700)
    cache_file().write_bytes(damage)
    schema = schemas.load_schema_uncached(XSD)
    assert cache.builds == [XSD]
    assert schema.is_valid(str(CORPUS / "cip-device" / "valid-chassis.xml"))
    assert cache_file().read_bytes() != damage
    schemas.load_schema_uncached(XSD)
    assert cache.builds == [XSD]  # the rewritten file is good


def test_a_changed_schema_file_misses_the_cache(cache, tmp_path, monkeypatch):
    copy = tmp_path / "schemas"
    shutil.copytree(schemas.data_dir("schemas"), copy)
    monkeypatch.setattr(schemas, "data_dir", lambda name: copy)
    schemas.load_schema_uncached(XSD)
    before = cache_file()
    # An included file counts as much as the main one.
    included = copy / "MasterTemplateTypes.xsd"
    included.write_text(included.read_text(encoding="utf-8") + "<!-- edited -->\n", encoding="utf-8")
    after = cache_file()
    assert after != before
    schemas.load_schema_uncached(XSD)
    assert cache.builds == [XSD, XSD]
    assert before.is_file() and after.is_file()


def test_the_key_depends_on_the_xmlschema_version(cache):
    assert schemas.schema_cache_file(XSD, "1.0") != schemas.schema_cache_file(XSD, "2.0")


@pytest.mark.skipif(not hasattr(os, "getuid"), reason="no file ownership")
def test_a_cache_file_of_another_user_is_not_unpickled(cache, monkeypatch):
    schemas.load_schema_uncached(XSD)
    real_uid = os.getuid()
    assert schemas._read_cache(cache_file(), xmlschema.XMLSchema11) is not None
    monkeypatch.setattr(os, "getuid", lambda: real_uid + 1)
    # Seen as another user, the directory is refused outright...
    assert schemas._read_cache(cache_file(), xmlschema.XMLSchema11) is None
    # ...and so is the file on its own.
    monkeypatch.setattr(cache_module, "trusted_dir", lambda directory: True)
    assert schemas._read_cache(cache_file(), xmlschema.XMLSchema11) is None
    loaded = []
    monkeypatch.setattr(schemas.pickle, "loads", lambda data: loaded.append(data))
    schemas._read_cache(cache_file(), xmlschema.XMLSchema11)
    assert loaded == []  # refused before unpickling, not after


@pytest.mark.skipif(not hasattr(os, "getuid"), reason="no file ownership")
def test_a_group_writable_cache_dir_is_not_used(cache):
    cache.dir.mkdir(parents=True)
    cache.dir.chmod(0o777)
    schemas.load_schema_uncached(XSD)
    assert not cache_file().exists()
    schemas.load_schema_uncached(XSD)
    assert cache.builds == [XSD, XSD]


@pytest.mark.skipif(not hasattr(os, "O_NOFOLLOW"), reason="no O_NOFOLLOW")
def test_a_symlinked_cache_file_is_not_followed(cache, tmp_path):
    schemas.load_schema_uncached(XSD)
    elsewhere = tmp_path / "elsewhere.pickle"
    cache_file().rename(elsewhere)
    cache_file().symlink_to(elsewhere)
    assert schemas._read_cache(cache_file(), xmlschema.XMLSchema11) is None


def test_an_unwritable_cache_only_costs_time(cache, tmp_path):
    blocker = tmp_path / "xdg"
    blocker.write_text("a file where the cache directory should be")
    schema = schemas.load_schema_uncached(XSD)
    assert schema.is_valid(str(CORPUS / "cip-device" / "valid-chassis.xml"))
    assert cache.builds == [XSD]


def test_load_schema_keeps_its_in_process_cache(cache):
    schemas.load_schema.cache_clear()
    try:
        assert schemas.load_schema(XSD) is schemas.load_schema(XSD)
        assert cache.builds == [XSD]
    finally:
        schemas.load_schema.cache_clear()
