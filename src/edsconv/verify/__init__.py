"""``edsconv verify``: check an EDS against the running EtherNet/IP device it describes.

:func:`verify` reads the EDS into the typed model, opens one EtherNet/IP session with the device
(:mod:`edsconv.verify.client`, cpppo's client: the ``edsconv[device]`` extra, imported only here) and
runs the comparisons of :mod:`edsconv.verify.checks` and :mod:`edsconv.verify.io`. It returns the
same :class:`~edsconv.report.FileReport` as lint, so every output format of lint renders it.
Read-only: only List Identity and Get_Attribute_Single are sent, and with ``connect`` a Forward Open
per ConnectionN, each closed again at once.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from edsconv.checks import Context
from edsconv.diagnostics import Diagnostic
from edsconv.eds.reader import load
from edsconv.model.build import build
from edsconv.report import FileReport

#: EtherNet/IP's registered TCP port for explicit messaging
DEFAULT_PORT = 44818


@dataclass(frozen=True, slots=True)
class Target:
    """Where the device is and how long to wait for each answer."""

    host: str
    port: int = DEFAULT_PORT
    timeout: float = 2.0

    @classmethod
    def parse(cls, device: str, timeout: float) -> Target:
        """``HOST`` or ``HOST:PORT`` (an IPv6 address in brackets: ``[::1]:44818``)."""
        if device.startswith("["):
            host, _, rest = device[1:].partition("]")
            port = rest.removeprefix(":") if rest else str(DEFAULT_PORT)
        elif device.count(":") == 1:
            host, _, port = device.partition(":")
        else:  # a name, an IPv4 address or a bare IPv6 address
            host, port = device, str(DEFAULT_PORT)
        if not host or not port.isdigit() or not 0 < int(port) < 65536:
            raise ValueError(f"{device}: not HOST or HOST:PORT with a port from 1 to 65535")
        return cls(host, int(port), timeout)


def verify(path: Path, target: Target, connect: bool = False, strict: bool = False) -> FileReport:
    """Every comparison of the EDS at ``path`` with the device at ``target``.

    Raises :class:`~edsconv.verify.client.DeviceError` when the device cannot be asked, OSError when
    the file cannot be read."""
    from edsconv.verify import checks, io
    from edsconv.verify.client import Session

    eds = load(path)
    device = build(eds)
    diagnostics: list[Diagnostic] = []
    with Session(target.host, target.port, target.timeout) as session:
        probe = checks.Probe(session, device, Context(eds, device))
        for compare in (checks.identity, checks.object_classes, checks.ethernet_interfaces, io.assembly_sizes,
                        io.parameter_values):
            diagnostics.extend(compare(probe))
        if strict:
            diagnostics.extend(checks.undeclared_objects(probe))
        if connect:
            diagnostics.extend(io.connections(probe))
    diagnostics.sort(key=lambda d: (d.line, d.column, d.code))
    return FileReport(str(path), diagnostics)
