"""The steps measured, each by edsconv and, where it has an equivalent, by eds-pie 1.2.0.

Every contender of a step reads the same file; its argument is prepared outside
the timing (bytes for edsconv, text for eds-pie, profiles for xml2eds).
"""

from __future__ import annotations

import contextlib
import io
import logging
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

logging.basicConfig(level=logging.CRITICAL)  # before eds_pie, which logs every token at DEBUG
from eds_pie.eds_pie import CIP_EDS, Parser  # noqa: E402
from lxml import etree  # noqa: E402

import edsconv  # noqa: E402
from edsconv.cli import cli  # noqa: E402
from edsconv.eds.from_model import device_to_eds  # noqa: E402
from edsconv.eds.source import decode  # noqa: E402
from edsconv.eds.writer import write  # noqa: E402
from edsconv.model import Device  # noqa: E402
from edsconv.xml.commnet import read_commnet_profile  # noqa: E402
from edsconv.xml.common import Header  # noqa: E402
from edsconv.xml.convert import profile_documents  # noqa: E402
from edsconv.xml.device_read import read_device_profile  # noqa: E402

# Strings, comments, numbers and words, punctuation: the tokens of an EDS, white space skipped.
FLOOR = re.compile(rb'L?"(?:[^"\\\n]|\\.)*"|\$[^\n]*|[A-Za-z0-9_.:+-]+|[^ \t\r\n\f\v]')


def floor_scan(data: bytes) -> None:
    """The floor of reading: find every token with one C regex, build nothing."""
    for _ in FLOOR.finditer(data):
        pass


def check(data: bytes) -> None:
    """What lint does per file: read, semantic model, every rule."""
    edsconv.analyse(edsconv.parse(data))


def eds2xml(data: bytes) -> list:
    """As `edsconv eds2xml`: read, analyse, both profiles, each validated before it would be written."""
    device, _ = edsconv.analyse(edsconv.parse(data))
    return profile_documents(device, Header.derive(device), "bench")


def xml2eds(documents: list) -> str:
    """As `edsconv xml2eds`: both profiles back into a model, written as canonical EDS text."""
    device = Device()
    read_device_profile(etree.fromstring(documents[0].data), device)
    read_commnet_profile(etree.fromstring(documents[1].data), device)
    return write(device_to_eds(device))


def command(*arguments: str) -> Callable[[Path], None]:
    """The edsconv command ``arguments FILE``, run in this process, its output discarded."""
    def run(path: Path) -> None:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            cli.main([*arguments, str(path)], standalone_mode=False)
    return run


def eds_pie_show_text(text: str) -> str:
    """eds-pie's nearest to `show`: parse, validate, and its listing of the model (``str``)."""
    return str(CIP_EDS(text))


def eds_pie_show_json(text: str) -> str:
    return CIP_EDS(text).to_json()


@dataclass(frozen=True)
class Step:
    name: str
    edsconv: Callable
    #: what edsconv's function takes, from (path, bytes)
    argument: Callable[[Path, bytes], object] = lambda path, data: data
    eds_pie: Callable[[str], object] | None = None
    floor: Callable[[bytes], None] | None = None


STEPS = (
    Step("read", edsconv.parse, eds_pie=lambda text: Parser(text).parse(), floor=floor_scan),
    Step("check", check, eds_pie=CIP_EDS),
    Step("lint", command("lint", "-j", "1"), argument=lambda path, data: path),
    Step("show text", command("show"), argument=lambda path, data: path, eds_pie=eds_pie_show_text),
    Step("show json", command("show", "--format", "json"), argument=lambda path, data: path,
         eds_pie=eds_pie_show_json),
    Step("eds2xml", eds2xml),
    Step("xml2eds", xml2eds, argument=lambda path, data: eds2xml(data)),
)


def eds_pie_text(data: bytes) -> str:
    """The text eds-pie reads: edsconv's decoding of the bytes (eds-pie takes str)."""
    return decode(data).text
