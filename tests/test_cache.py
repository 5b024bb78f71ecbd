"""The per-user disk cache (edsconv.cache) and the lexicon that keeps its patterns there.

Every test points the cache at ``tmp_path`` (``XDG_CACHE_HOME``), never at the real one.
"""

from __future__ import annotations

import json
import os

import pytest

from edsconv import cache
from edsconv.eds import lexicon

needs_owners = pytest.mark.skipif(not hasattr(os, "getuid"), reason="no file ownership")


@pytest.fixture
def directory(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache.cache_dir() == tmp_path / "xdg" / "edsconv"
    return cache.cache_dir()


def test_a_relative_xdg_cache_home_is_not_used(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", "relative/dir")
    assert cache.cache_dir().is_absolute()
    assert cache.cache_dir().name.startswith("edsconv-")


def test_written_then_read(directory):
    path = directory / "thing.json"
    cache.write_file(path, b"{}")
    assert cache.read_file(path) == b"{}"
    assert [p.name for p in directory.iterdir()] == ["thing.json"]  # no temporary file left behind
    if hasattr(os, "getuid"):
        assert directory.stat().st_mode & 0o777 == 0o700
        assert path.stat().st_mode & 0o077 == 0


def test_an_absent_file_is_a_miss(directory):
    assert cache.read_file(directory / "absent") is None


@needs_owners
def test_a_file_writable_by_others_is_ignored(directory):
    path = directory / "planted.json"
    cache.write_file(path, b"planted")
    path.chmod(0o666)
    assert cache.read_file(path) is None
    path.chmod(0o620)
    assert cache.read_file(path) is None
    path.chmod(0o600)
    assert cache.read_file(path) == b"planted"


@needs_owners
def test_a_file_owned_by_someone_else_is_ignored(directory, monkeypatch):
    path = directory / "planted.json"
    cache.write_file(path, b"planted")
    if os.geteuid() == 0:  # root can plant a file of another user for real
        os.chown(path, 4242, -1)
    else:
        real_uid = os.getuid()
        monkeypatch.setattr(cache, "trusted_dir", lambda directory: True)
        monkeypatch.setattr(os, "getuid", lambda: real_uid + 1)
    assert cache.read_file(path) is None


@needs_owners
def test_a_directory_writable_by_others_is_neither_read_nor_written(directory):
    path = directory / "thing.json"
    cache.write_file(path, b"good")
    directory.chmod(0o777)
    assert cache.read_file(path) is None
    cache.write_file(directory / "other.json", b"x")
    assert not (directory / "other.json").exists()


@pytest.mark.skipif(not hasattr(os, "O_NOFOLLOW"), reason="no O_NOFOLLOW")
def test_a_symlink_is_not_followed(directory, tmp_path):
    elsewhere = tmp_path / "elsewhere.json"
    elsewhere.write_bytes(b"elsewhere")
    elsewhere.chmod(0o600)
    directory.mkdir(parents=True, mode=0o700)
    (directory / "link.json").symlink_to(elsewhere)
    assert cache.read_file(directory / "link.json") is None


def test_an_unwritable_cache_only_costs_time(tmp_path, monkeypatch):
    (tmp_path / "xdg").write_text("a file where the cache directory should be")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    cache.write_file(cache.cache_dir() / "thing.json", b"x")
    assert cache.read_file(cache.cache_dir() / "thing.json") is None


# --- the lexicon's patterns ---------------------------------------------------------------


def plant_patterns(mode: int) -> dict[str, str]:
    """A cache file of the lexicon whose patterns match nothing, with ``mode``."""
    real = lexicon.terminal_patterns()
    planted = {name: "(?!x)x" for name in real}
    path = lexicon.cache_file(lexicon.grammar_text())
    path.write_text(json.dumps(planted), encoding="utf-8")
    path.chmod(mode)
    return planted


def test_the_lexicon_is_cached_in_the_users_directory(directory):
    patterns = lexicon.terminal_patterns()
    path = lexicon.cache_file(lexicon.grammar_text())
    assert path.parent == directory
    assert json.loads(path.read_text(encoding="utf-8")) == patterns
    assert lexicon.terminal_patterns() == patterns


@needs_owners
def test_a_planted_lexicon_writable_by_others_does_not_change_tokenising(directory):
    planted = plant_patterns(0o666)
    assert lexicon.terminal_patterns() != planted
    assert lexicon.terminal_patterns()["KEYWORD"] != "(?!x)x"


def test_the_users_own_lexicon_file_is_read(directory):
    # the same planted file, private: read, so the test above can tell trusted from untrusted
    planted = plant_patterns(0o600)
    assert lexicon.terminal_patterns() == planted


def test_a_damaged_lexicon_file_is_computed_again(directory):
    patterns = lexicon.terminal_patterns()
    path = lexicon.cache_file(lexicon.grammar_text())
    for damage in ("not json", "[]", json.dumps({"STRING": 1})):
        path.write_text(damage, encoding="utf-8")
        assert lexicon.terminal_patterns() == patterns
