"""Output files (edsconv.atomic): all of a set or none, the umask's mode for new files, a replaced
file's mode kept, signals held back during the renames, nothing left behind on failure."""

from __future__ import annotations

import os
import signal
import stat
import threading
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv import atomic
from edsconv.atomic import write_all_atomically, write_atomically
from edsconv.cli import cli
from edsconv.signals import Interrupted

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
MESSY = "[Device]\nVendCode = 1;\n[File]\nDescText = \"x\";\n"


def mode(path: Path) -> int:
    return stat.S_IMODE(path.stat().st_mode)


@pytest.fixture
def umask_027():
    previous = os.umask(0o027)
    yield
    os.umask(previous)


def test_a_new_file_gets_the_mode_the_umask_gives(tmp_path: Path, umask_027: None) -> None:
    write_atomically(tmp_path / "a.xml", b"x", inputs=())
    assert mode(tmp_path / "a.xml") == 0o640
    os.umask(0o022)
    write_atomically(tmp_path / "b.xml", b"x", inputs=())
    assert mode(tmp_path / "b.xml") == 0o644


def test_a_replaced_file_keeps_its_mode(tmp_path: Path, umask_027: None) -> None:
    target = tmp_path / "a.xml"
    target.write_bytes(b"old")
    os.chmod(target, 0o664)
    write_atomically(target, b"new", inputs=(), force=True)
    assert (target.read_bytes(), mode(target)) == (b"new", 0o664)


@pytest.mark.parametrize("command", [
    ["eds2xml", str(EXAMPLE), "-o", "{dir}", "--force"],
    ["xml2eds", str(REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"), "-o", "{dir}/out.eds", "--force"],
    ["merge", str(REPO / "corpus" / "modular" / "adapter.eds"), str(REPO / "corpus" / "modular" / "module.eds"),
     "-o", "{dir}/out.eds", "--force"],
])
def test_every_writer_gives_the_umask_mode_and_keeps_a_replaced_mode(tmp_path: Path, umask_027: None,
                                                                    command: list[str]) -> None:
    args = [part.replace("{dir}", str(tmp_path)) for part in command]
    assert CliRunner().invoke(cli, args).exit_code in (0, 1)
    written = sorted(tmp_path.iterdir())
    assert written and all(mode(p) == 0o640 for p in written)
    for path in written:
        os.chmod(path, 0o604)
    assert CliRunner().invoke(cli, args).exit_code in (0, 1)
    assert all(mode(p) == 0o604 for p in written)
    assert sorted(tmp_path.iterdir()) == written  # no temporary file left


def test_fmt_keeps_the_mode_and_writes_through_a_symbolic_link(tmp_path: Path) -> None:
    real = tmp_path / "real.eds"
    real.write_text(MESSY)
    os.chmod(real, 0o600)
    link = tmp_path / "link.eds"
    link.symlink_to(real)
    assert CliRunner().invoke(cli, ["fmt", str(link)]).exit_code == 0
    assert link.is_symlink() and real.read_text().startswith("[File]")
    assert mode(real) == 0o600


def test_nothing_is_written_when_one_file_of_the_set_fails(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    calls = []

    def failing_fsync(descriptor: int) -> None:
        calls.append(descriptor)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")

    monkeypatch.setattr(atomic.os, "fsync", failing_fsync)
    with pytest.raises(OSError) as raised:
        write_all_atomically([(tmp_path / "a.xml", b"a"), (tmp_path / "b.xml", b"b")], inputs=())
    assert raised.value.filename == str(tmp_path / "b.xml")  # the file asked for, not the temporary one
    assert list(tmp_path.iterdir()) == []


def _raise_interrupted(signal_number: int, frame: object) -> None:
    raise Interrupted(signal_number)


@pytest.fixture
def sigterm_raises():
    previous = signal.signal(signal.SIGTERM, _raise_interrupted)
    yield
    signal.signal(signal.SIGTERM, previous)


def test_a_signal_while_writing_leaves_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                               sigterm_raises: None) -> None:
    real_fsync = os.fsync

    def fsync_then_signal(descriptor: int) -> None:
        real_fsync(descriptor)
        os.kill(os.getpid(), signal.SIGTERM)

    monkeypatch.setattr(atomic.os, "fsync", fsync_then_signal)
    with pytest.raises(Interrupted):
        write_all_atomically([(tmp_path / "a.xml", b"a"), (tmp_path / "b.xml", b"b")], inputs=())
    assert list(tmp_path.iterdir()) == []


def test_a_second_signal_while_cleaning_up_leaves_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                          sigterm_raises: None) -> None:
    # a pool ending its workers: our SIGTERM, then concurrent.futures' own when the first worker exits
    # (CI found a temporary file left by `fmt -j 2` after a SIGHUP)
    real_fsync, real_unlink = os.fsync, Path.unlink

    def fsync_then_signal(descriptor: int) -> None:
        real_fsync(descriptor)
        signal.pthread_kill(threading.get_ident(), signal.SIGTERM)

    def signal_then_unlink(path: Path, missing_ok: bool = False) -> None:
        signal.pthread_kill(threading.get_ident(), signal.SIGTERM)
        real_unlink(path, missing_ok=missing_ok)

    monkeypatch.setattr(atomic.os, "fsync", fsync_then_signal)
    monkeypatch.setattr(Path, "unlink", signal_then_unlink)
    with pytest.raises(Interrupted):
        write_all_atomically([(tmp_path / "a.xml", b"a"), (tmp_path / "b.xml", b"b")], inputs=())
    assert list(tmp_path.iterdir()) == []


def test_a_signal_between_the_renames_waits_until_both_are_done(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                sigterm_raises: None) -> None:
    real_replace = os.replace

    def replace_then_signal(source: str, target: Path) -> None:
        real_replace(source, target)
        # to this thread: the mask is per thread, and a process-directed signal may go to another
        # thread of the test runner (pytest-xdist's); the command line runs in one thread
        signal.pthread_kill(threading.get_ident(), signal.SIGTERM)

    monkeypatch.setattr(atomic.os, "replace", replace_then_signal)
    with pytest.raises(Interrupted):
        write_all_atomically([(tmp_path / "a.xml", b"a"), (tmp_path / "b.xml", b"b")], inputs=())
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.xml", "b.xml"]


def test_a_directory_or_a_file_in_the_way_is_an_error_before_anything_is_written(tmp_path: Path) -> None:
    (tmp_path / "b.xml").mkdir()
    with pytest.raises(IsADirectoryError):
        write_all_atomically([(tmp_path / "a.xml", b"a"), (tmp_path / "b.xml", b"b")], inputs=())
    assert [p.name for p in tmp_path.iterdir()] == ["b.xml"]
    (tmp_path / "file").write_text("")
    with pytest.raises(NotADirectoryError, match="is not a directory"):
        write_atomically(tmp_path / "file" / "sub" / "x.eds", b"x", inputs=())


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
def test_a_device_is_written_to_not_replaced(tmp_path: Path) -> None:
    device = Path("/dev/full")
    kind = stat.S_IFMT(device.stat().st_mode)
    with pytest.raises(OSError, match="No space left on device") as raised:
        write_atomically(device, b"x", inputs=())  # no --force needed: a device is not a file to overwrite
    assert raised.value.filename == "/dev/full"
    assert stat.S_ISCHR(kind) and stat.S_IFMT(device.stat().st_mode) == kind
    assert not list(Path("/dev").glob(".full.*.tmp"))


def test_a_named_pipe_is_written_to_not_replaced(tmp_path: Path) -> None:
    pipe = tmp_path / "pipe"
    os.mkfifo(pipe)
    received: list[bytes] = []
    reader = threading.Thread(target=lambda: received.append(pipe.read_bytes()))
    reader.start()
    write_atomically(pipe, b"profile", inputs=())
    reader.join(10)
    assert received == [b"profile"]
    assert stat.S_ISFIFO(pipe.stat().st_mode) and list(tmp_path.iterdir()) == [pipe]
