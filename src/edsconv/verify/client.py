"""The EtherNet/IP side of ``edsconv verify``: cpppo's client, wrapped so that the checks see plain
data (:class:`Reply`, :class:`ListedIdentity`) and a device that cannot be asked is one
:class:`DeviceError` with a line that says why.

cpppo (and pycomm3, for the CIP status words) are the ``edsconv[device]`` extra: they are imported
when a :class:`Session` opens, never when edsconv starts, so ``lint`` stays light. Only requests that
read are sent: List Identity, Get_Attribute_Single (0x0E), and with ``--connect`` Forward Open
(0x54) followed at once by Forward Close (0x4E). Every wait is bounded by the timeout.
"""

from __future__ import annotations

import errno
import logging
import socket
from dataclasses import dataclass, field
from typing import Any

#: CIP general status codes the checks tell apart (CIP Vol 1 Appendix B; the words come from pycomm3)
SUCCESS, CONNECTION_FAILURE, PATH_UNKNOWN, SERVICE_NOT_SUPPORTED = 0x00, 0x01, 0x05, 0x08
ATTRIBUTE_NOT_SUPPORTED, OBJECT_DOES_NOT_EXIST = 0x14, 0x16
#: the Connection Manager (class 6 instance 1): where Forward Open and Forward Close go
CONNECTION_MANAGER = "@6/1"
EXTRA = "pip install 'edsconv[device]'"


class DeviceError(Exception):
    """The device cannot be asked: unreachable, refused, silent, or not EtherNet/IP. One line."""


@dataclass(frozen=True, slots=True)
class Reply:
    """A CIP reply: general status, extended status words, and the data of a successful reply."""

    status: int
    extended: tuple[int, ...] = ()
    data: bytes = b""
    #: what a successful Forward Open answered (serials and connection IDs), for its Forward Close
    established: Any = field(default=None, compare=False, repr=False)
    #: a Forward Open's: the reply to the Forward Close that followed it
    closed: Reply | None = field(default=None, compare=False, repr=False)

    @property
    def ok(self) -> bool:
        return self.status == SUCCESS

    @property
    def absent(self) -> bool:
        """The object or instance does not exist on the device."""
        return self.status in (PATH_UNKNOWN, OBJECT_DOES_NOT_EXIST)

    def words(self) -> str:
        """``general status 0x01 (Connection failure), extended status 0x0109 (Invalid connection size)``."""
        from pycomm3.cip.status_info import EXTEND_CODES, SERVICE_STATUS  # the words of CIP Vol 1 App. B

        text = f"general status 0x{self.status:02X} ({SERVICE_STATUS.get(self.status, 'unknown status')})"
        for word in self.extended:
            meaning = EXTEND_CODES.get(self.status, {}).get(word, "not in the status table")
            text += f", extended status 0x{word:04X} ({meaning})"
        return text


@dataclass(frozen=True, slots=True)
class ListedIdentity:
    """The List Identity reply's identity item."""

    vendor: int
    device_type: int
    product_code: int
    major_revision: int
    minor_revision: int
    product_name: str


@dataclass(frozen=True, slots=True)
class ForwardOpen:
    """The parameters of one Forward Open (CIP Vol 1 3-5.5.2), from a ConnectionN of the EDS."""

    connection_path: list[dict]
    transport: int
    o_to_t_rpi: int
    o_to_t_ncp: int
    t_to_o_rpi: int
    t_to_o_ncp: int
    serial: int


#: Originator identification of our Forward Opens: vendor 0xFFFF is none of the CIP vendors
ORIGINATOR_VENDOR, ORIGINATOR_SERIAL = 0xFFFF, 0x45445343  # "EDSC"


class Session:
    """One EtherNet/IP session (TCP) with the device, registered when it opens."""

    def __init__(self, host: str, port: int, timeout: float) -> None:
        self.host, self.port, self.timeout = host, port, timeout
        self._client: Any = None
        self._connection: Any = None

    def __enter__(self) -> Session:
        try:
            from cpppo.server.enip import client  # type: ignore[import-untyped]
        except ImportError as error:
            raise DeviceError(f"edsconv verify needs the device extra ({error.name} is missing): {EXTRA}") from error
        for name in ("enip", "cpppo"):  # cpppo logs failures it raises; we report them, once
            logging.getLogger(name).setLevel(logging.CRITICAL + 1)
        self._client = client
        self._connection = self._open()
        self._connection.frame.__enter__()  # cpppo's parser is used under its lock (its client's `with`)
        return self

    def __exit__(self, *exc: object) -> None:
        if self._connection is not None:
            self._connection.frame.__exit__(None, None, None)
            self._connection.close()

    @property
    def where(self) -> str:
        return f"{self.host}:{self.port}"

    def _open(self) -> Any:
        """Connect and register a session (cpppo's connector); each failure as the line that says why."""
        try:
            return self._client.connector(host=self.host, port=self.port, timeout=self.timeout)
        except OSError as error:
            raise DeviceError(self._socket_failure(error)) from error
        except Exception as error:  # cpppo asserts on a missing reply, its parser on one that is not EtherNet/IP
            raise DeviceError(self._no_answer(str(error))) from error

    def _socket_failure(self, error: OSError) -> str:
        if isinstance(error, socket.timeout | TimeoutError):
            return f"{self.where}: no answer within {self.timeout:g} s (connecting timed out)"
        if error.errno == errno.ECONNREFUSED:
            return f"{self.where}: connection refused (nothing listens on port {self.port})"
        if error.errno in (errno.EHOSTUNREACH, errno.ENETUNREACH):
            return f"{self.where}: host unreachable ({error.strerror})"
        if isinstance(error, socket.gaierror):
            return f"{self.where}: unknown host ({error.strerror})"
        return f"{self.where}: cannot connect ({error.strerror or error})"

    def _no_answer(self, reason: str) -> str:
        if "Failed to receive any response" in reason:
            return f"{self.where}: no answer within {self.timeout:g} s (timed out waiting for the device)"
        return f"{self.where}: does not answer as an EtherNet/IP device (no EtherNet/IP reply to Register Session)"

    def _exchange(self) -> Any:
        """The next reply, within the timeout; a silent or vanished device is a DeviceError."""
        try:
            response, _elapsed = self._client.await_response(self._connection, timeout=self.timeout)
        except OSError as error:
            raise DeviceError(self._socket_failure(error)) from error
        except Exception as error:
            raise DeviceError(f"{self.where}: does not answer as an EtherNet/IP device (a reply that is not "
                              "EtherNet/IP)") from error
        if response is None:
            raise DeviceError(self._no_answer("Failed to receive any response"))
        if not response or response.get("enip.status", 0) != 0:
            raise DeviceError(f"{self.where}: the device ended the session "
                              f"(encapsulation status {response.get('enip.status', 'none')})")
        return response

    def list_identity(self) -> ListedIdentity:
        self._connection.list_identity(timeout=self.timeout)
        item = self._exchange().get("enip.CIP.list_identity.CPF.item")[0].identity_object
        revision = item.product_revision
        return ListedIdentity(item.vendor_id, item.device_type, item.product_code, revision & 0xFF, revision >> 8,
                              item.product_name)

    def get_attribute(self, class_id: int, instance: int, attribute: int) -> Reply:
        """Get_Attribute_Single of class/instance/attribute; a refusal is a Reply with its status."""
        self._connection.get_attribute_single(f"@{class_id}/{instance}/{attribute}", timeout=self.timeout)
        reply = self._exchange().enip.CIP.send_data.CPF.item[1].unconnected_send.request
        return Reply(reply.status, _extended(reply), bytes(reply.get("get_attribute_single.data") or b""))

    def forward_open(self, request: ForwardOpen) -> Reply:
        """Forward Open with ``request``'s parameters; when it succeeds, Forward Close at once."""
        opened = self._connection_manager(
            self._connection.forward_open, path=CONNECTION_MANAGER, connection_path=request.connection_path,
            priority_time_tick=7, timeout_ticks=155,
            O_T={"RPI": request.o_to_t_rpi, "NCP": request.o_to_t_ncp, "connection_ID": request.serial},
            T_O={"RPI": request.t_to_o_rpi, "NCP": request.t_to_o_ncp, "connection_ID": 0xFFFFFFFF},
            O_serial=ORIGINATOR_SERIAL, O_vendor=ORIGINATOR_VENDOR, connection_serial=request.serial,
            transport_class_triggers=request.transport, connection_timeout_multiplier=0)
        if not opened.ok:
            return opened
        closed = self.forward_close(request)
        if not closed.ok:  # never seen; without data sent the device drops it after 4 RPIs (multiplier 0)
            raise DeviceError(f"{self.where}: the device refused to close a connection verify opened "
                              f"(Forward Close: {closed.words()})")
        return Reply(opened.status, opened.extended, established=opened.established, closed=closed)

    def forward_close(self, request: ForwardOpen) -> Reply:
        return self._connection_manager(
            self._connection.forward_close, path=CONNECTION_MANAGER, connection_path=request.connection_path,
            priority_time_tick=7, timeout_ticks=155, O_serial=ORIGINATOR_SERIAL, O_vendor=ORIGINATOR_VENDOR,
            connection_serial=request.serial)

    def _connection_manager(self, service: Any, **parameters: Any) -> Reply:
        """A Connection Manager service: its replies are parsed as the Connection Manager's (cpppo's way)."""
        from cpppo.server.enip import device

        saved, self._connection.dialect = self._connection.dialect, device.Connection_Manager
        try:
            service(timeout=self.timeout, **parameters)
            reply = self._exchange().enip.CIP.send_data.CPF.item[1].unconnected_send.request
        finally:
            self._connection.dialect = saved
        return Reply(reply.status, _extended(reply), established=reply)


def _extended(reply: Any) -> tuple[int, ...]:
    return tuple(reply.get("status_ext.data") or ())
