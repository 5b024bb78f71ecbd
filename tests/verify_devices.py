"""The devices of edsconv verify's tests: tests/enip_device.py (cpppo's EtherNet/IP server) run on
127.0.0.1 at a port the system picks, configured as corpus/device/loopback_adapter.eds describes the
device (MATCHING) or with deliberate differences; started and stopped with bounded waits."""

from __future__ import annotations

import copy
import json
import queue
import subprocess
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from conftest import REPO

EDS = REPO / "corpus" / "device" / "loopback_adapter.eds"
SERVER = REPO / "tests" / "enip_device.py"
START_TIMEOUT, STOP_TIMEOUT = 20.0, 5.0

#: the device loopback_adapter.eds describes: identity, TCP/IP Interface revision 4, assembly
#: instances 100 (8 bytes, T=>O header 2) and 150 (4 bytes, O=>T header 2 + 4), the Ethernet Link
#: object (0xF6) and the vendor object 0x64 that holds Param1 (1500 rpm)
MATCHING = {
    "identity": {"Vendor Number": 1234, "Device Type": 12, "Product Code Number": 42,
                 "Product Revision": 2 | 3 << 8, "Product Name": "edsconv loopback adapter"},
    "classes": {"245": 4, "4": 2},
    "assemblies": {"100": [8, 2], "150": [4, 6]},
    "objects": {"246": {"revision": 4, "instances": {"1": {"1": ["UDINT", 100], "10": ["SSTRING", "X1"]}}},
                "100": {"revision": 1, "instances": {"1": {"1": ["UINT", 1500], "2": ["UINT", 7]}}}},
}


def differing() -> dict:
    """MATCHING with revision 2.4 (not 2.3), assembly instance 100 of 10 bytes, no Ethernet Link object."""
    config = copy.deepcopy(MATCHING)
    config["identity"]["Product Revision"] = 2 | 4 << 8
    config["assemblies"]["100"] = [10, 2]
    del config["objects"]["246"]
    return config


def line_of(text: str, path: Path = EDS) -> int:
    """The line of ``path`` that holds ``text`` (once)."""
    (line,) = [n for n, content in enumerate(path.read_text().splitlines(), start=1) if text in content]
    return line


@contextmanager
def running(config: dict, directory: Path) -> Iterator[int]:
    """The device of ``config`` listening on 127.0.0.1; yields its port, stops it on the way out."""
    config_file = directory / "device.json"
    config_file.write_text(json.dumps(config))
    process = subprocess.Popen([sys.executable, str(SERVER), str(config_file)], stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, text=True, cwd=directory)
    try:
        yield _port(process)
    finally:
        process.terminate()
        try:
            process.wait(STOP_TIMEOUT)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(STOP_TIMEOUT)


def _port(process: subprocess.Popen) -> int:
    """The port from the server's ``Network TCP Server address = ('127.0.0.1', PORT)`` line."""
    lines: queue.Queue[str] = queue.Queue()
    threading.Thread(target=lambda: lines.put(process.stdout.readline() if process.stdout else ""),
                     daemon=True).start()
    try:
        line = lines.get(timeout=START_TIMEOUT)
    except queue.Empty as error:
        raise RuntimeError("the test device did not start listening in time") from error
    if "127.0.0.1" not in line:
        raise RuntimeError(f"the test device did not start: {line!r}")
    return int(line.rsplit(",", 1)[1].strip(" )\n"))
