"""edsconv verify when the device cannot be asked: one line and exit 2 for an unreachable host, a
refused connection, a device that does not answer in time and one that does not speak EtherNet/IP;
the extra stays out of lint. Every socket here is on 127.0.0.1, except the unreachable address
224.0.0.1, which the kernel refuses for TCP before a packet leaves (ENETUNREACH)."""

from __future__ import annotations

import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv.cli import cli

EDS = REPO / "corpus" / "device" / "loopback_adapter.eds"
needs_extra = pytest.mark.skipif(not all(__import__("importlib").util.find_spec(m) for m in ("cpppo", "pycomm3")),
                                 reason="edsconv[device] is not installed")


def verify(device: str, *arguments: str):
    return CliRunner().invoke(cli, ["verify", str(EDS), "--device", device, *arguments])


@contextmanager
def tcp_server(answer: bytes | None) -> Iterator[int]:
    """A TCP server on 127.0.0.1 that answers ``answer`` to the first bytes it gets (None: stays silent)."""
    listener = socket.create_server(("127.0.0.1", 0))
    stop = threading.Event()

    def serve() -> None:
        connection, _ = listener.accept()
        with connection:
            connection.recv(1024)
            if answer is not None:
                connection.sendall(answer)
            stop.wait(10)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        yield listener.getsockname()[1]
    finally:
        stop.set()
        listener.close()


def one_line(result) -> str:
    assert result.exit_code == 2
    assert result.stdout == ""
    (line,) = result.stderr.splitlines()
    return line


@needs_extra
def test_a_refused_connection():
    with socket.create_server(("127.0.0.1", 0)) as probe:
        port = probe.getsockname()[1]  # free once closed: nothing listens there
    assert one_line(verify(f"127.0.0.1:{port}")) == f"127.0.0.1:{port}: connection refused (nothing listens on " \
        f"port {port})"


@needs_extra
def test_an_unreachable_host():
    assert one_line(verify("224.0.0.1")) == "224.0.0.1:44818: host unreachable (Network is unreachable)"


@needs_extra
def test_a_device_that_does_not_answer_in_time():
    with tcp_server(None) as port:
        begun = time.monotonic()
        line = one_line(verify(f"127.0.0.1:{port}", "--timeout", "0.3"))
        assert time.monotonic() - begun < 3
    assert line == f"127.0.0.1:{port}: no answer within 0.3 s (timed out waiting for the device)"


@needs_extra
def test_a_device_that_is_not_ethernet_ip():
    with tcp_server(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n") as port:
        line = one_line(verify(f"127.0.0.1:{port}"))
    assert line == f"127.0.0.1:{port}: does not answer as an EtherNet/IP device (no EtherNet/IP reply to " \
        "Register Session)"


def test_a_device_address_without_a_port_number():
    result = verify("127.0.0.1:http")
    assert result.exit_code == 2
    assert "127.0.0.1:http: not HOST or HOST:PORT with a port from 1 to 65535" in result.stderr


def test_without_the_extra_verify_says_how_to_install_it(monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setitem(sys.modules, "cpppo.server.enip", None)  # import fails as if not installed
    monkeypatch.setitem(sys.modules, "cpppo", None)
    with socket.create_server(("127.0.0.1", 0)) as listening:
        line = one_line(verify(f"127.0.0.1:{listening.getsockname()[1]}"))
    assert line.startswith("edsconv verify needs the device extra (")
    assert line.endswith("): pip install 'edsconv[device]'")


def test_lint_and_the_rules_do_not_import_the_extra():
    program = ("import sys; from edsconv.cli import main; sys.argv = ['edsconv', 'lint', sys.argv[1]];\n"
               "try: main()\nexcept SystemExit: pass\n"
               "from edsconv.diagnostics import load_rules; assert 'EDS601' in load_rules().rules\n"
               "print(sorted(m for m in sys.modules if m.split('.')[0] in ('cpppo', 'pycomm3')))")
    result = subprocess.run([sys.executable, "-c", program, str(EDS)], capture_output=True, text=True, timeout=60)
    assert result.stdout.splitlines()[-1] == "[]"


@pytest.mark.parametrize(("device", "host", "port"), [
    ("192.168.1.20", "192.168.1.20", 44818), ("plc.local:2222", "plc.local", 2222),
    ("[::1]:44818", "::1", 44818), ("::1", "::1", 44818), ("[fe80::1]", "fe80::1", 44818)])
def test_the_device_address(device: str, host: str, port: int):
    from edsconv.verify import Target

    assert Target.parse(device, 1.0) == Target(host, port, 1.0)


def test_help_names_its_documentation():
    result = CliRunner().invoke(cli, ["verify", "--help"])
    assert result.exit_code == 0
    assert "pip install 'edsconv[device]'" in result.stdout
    assert result.stdout.split("Documentation:")[1].split()[0].endswith("verify.md")
