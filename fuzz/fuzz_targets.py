"""The fuzz targets: one function per entry point, bytes in, diagnostics out.

Each target runs what the command runs, in memory where the library allows it, and checks the
invariant of issue 11: no exception escapes and the run ends in a list of diagnostics. The
drivers (``fuzz/fuzz.py`` with atheris, ``fuzz/mutation.py`` without) add the time bound:
no input may take more than :data:`SLOWDOWN_LIMIT` times the corpus's time per byte.

``xml2eds`` and ``validate`` read files (the XML reader takes a path), so their targets write
the input to one scratch file, in /dev/shm where it exists.
"""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import edsconv
from edsconv.diagnostics import Diagnostic
from edsconv.eds.from_model import device_to_eds
from edsconv.eds.writer import write
from edsconv.xml.common import Header
from edsconv.xml.convert import NotConverted, conversion_refusals, device_from_profiles, profile_documents
from edsconv.xml.validate import validate_file

REPO = Path(__file__).resolve().parents[1]
#: The real EDS files beside the repository (read in place, never copied).
SHARED_REAL = REPO.parent / "shared" / "corpus" / "real"
#: No input may take longer than this many times the seeds' average time per byte ...
SLOWDOWN_LIMIT = 50
#: ... counting at least this many bytes (a call has a fixed cost that tiny inputs do not pay back).
FLOOR_BYTES = 2048


class InvariantBroken(AssertionError):
    """A target returned something other than a list of diagnostics, or took too long."""


def parse_analyse(data: bytes) -> list[Diagnostic]:
    """``edsconv lint`` of one file: read, build the model, run every check."""
    _, diagnostics = edsconv.analyse(edsconv.parse(data, "fuzz.eds"))
    return diagnostics


def eds2xml(data: bytes) -> list[Diagnostic]:
    """``edsconv eds2xml`` without files: refuse (XML103) or build and serialise both profiles."""
    eds = edsconv.parse(data, "fuzz.eds")
    device, diagnostics = edsconv.analyse(eds)
    refusals = conversion_refusals(eds, device)
    if refusals:
        return diagnostics + refusals
    try:
        profile_documents(device, Header.derive(device, "fuzz"), "fuzz")
    except NotConverted as refused:
        return diagnostics + refused.diagnostics
    return diagnostics


def xml2eds(data: bytes) -> list[Diagnostic]:
    """``edsconv xml2eds`` of one profile: read, validate, convert and write the EDS text."""
    with _scratch_file(data) as path:
        device, diagnostics = device_from_profiles([path])
    if device is not None:
        write(device_to_eds(device))
    return diagnostics


def validate(data: bytes) -> list[Diagnostic]:
    """``edsconv validate`` of one file."""
    with _scratch_file(data) as path:
        return validate_file(path).diagnostics


@dataclass(frozen=True)
class Target:
    name: str
    run: Callable[[bytes], list[Diagnostic]]
    #: which seed files feed it
    suffixes: tuple[str, ...]


TARGETS = {target.name: target for target in (
    Target("parse_analyse", parse_analyse, (".eds",)),
    Target("eds2xml", eds2xml, (".eds",)),
    Target("xml2eds", xml2eds, (".xml",)),
    Target("validate", validate, (".xml",)),
)}


def checked(target: Target, data: bytes) -> list[Diagnostic]:
    """Run ``target`` and check that it ended in diagnostics (an exception simply propagates)."""
    diagnostics = target.run(data)
    if not isinstance(diagnostics, list) or not all(isinstance(d, Diagnostic) for d in diagnostics):
        raise InvariantBroken(f"{target.name} returned {type(diagnostics).__name__}, not a list of diagnostics")
    return diagnostics


def seed_files(target: Target, real: bool = True) -> list[Path]:
    """The seeds of ``target``: corpus/ and, when ``real`` and present, the shared real files."""
    roots = [REPO / "corpus"] + ([SHARED_REAL] if real and SHARED_REAL.is_dir() else [])
    return sorted(p for root in roots for p in root.rglob("*") if p.is_file() and p.suffix.lower() in target.suffixes)


def generated_profiles(directory: Path, limit: int = 80) -> list[Path]:
    """Profiles eds2xml makes of the EDS files of corpus/ (ours only), written to ``directory``:
    seeds for the XML targets that reach the readers of xml2eds, which need valid profiles."""
    directory.mkdir(parents=True, exist_ok=True)
    made: list[Path] = []
    for source in sorted((REPO / "corpus").rglob("*.eds"))[:limit]:
        eds = edsconv.parse(source.read_bytes(), str(source))
        device, _ = edsconv.analyse(eds)
        if conversion_refusals(eds, device):
            continue
        stem = "-".join(source.relative_to(REPO / "corpus").with_suffix("").parts)
        try:
            outputs = profile_documents(device, Header.derive(device, stem), stem)
        except NotConverted:
            continue
        for output in outputs:
            (directory / output.name).write_bytes(output.data)
            made.append(directory / output.name)
    return made


def seconds_per_byte(target: Target, seeds: list[bytes]) -> float:
    """The seeds' average time per byte under ``target`` (each counted at least :data:`FLOOR_BYTES`),
    after one warm-up run that loads the grammar and the schemas."""
    for data in seeds[:1]:
        checked(target, data)
    start = time.process_time()
    for data in seeds:
        checked(target, data)
    return (time.process_time() - start) / max(1, sum(max(len(d), FLOOR_BYTES) for d in seeds))


class Timed:
    """Runs ``target`` under the time bound: :class:`InvariantBroken` when an input is too slow.

    Time is the process's CPU time, here and in :func:`seconds_per_byte`: on a shared machine the
    wall clock also counts the other processes' work (a wall-clock run on the 2-core machine at a
    load of 7 stopped on a seed that takes 0.03 s, slowed to 0.43 s)."""

    def __init__(self, target: Target, seconds_per_byte: float) -> None:
        self.target = target
        self.seconds_per_byte = seconds_per_byte

    def __call__(self, data: bytes) -> list[Diagnostic]:
        budget = SLOWDOWN_LIMIT * self.seconds_per_byte * max(len(data), FLOOR_BYTES)
        for _ in range(2):  # a second try, so that a busy moment of the shared machine is not taken for a finding
            start = time.process_time()
            diagnostics = checked(self.target, data)
            elapsed = time.process_time() - start
            if elapsed <= budget:
                return diagnostics
        raise InvariantBroken(f"{self.target.name}: {elapsed:.3f} s for {len(data)} bytes, more than "
                              f"{SLOWDOWN_LIMIT}x the seeds' time per byte (budget {budget:.3f} s)")


_SCRATCH = Path(tempfile.mkdtemp(prefix="edsconv-fuzz-", dir="/dev/shm" if os.path.isdir("/dev/shm") else None))
atexit.register(shutil.rmtree, _SCRATCH, ignore_errors=True)


@contextmanager
def _scratch_file(data: bytes) -> Iterator[Path]:
    """``data`` in the scratch file, for the targets whose reader takes a path."""
    path = _SCRATCH / "input.xml"
    path.write_bytes(data)
    try:
        yield path
    finally:
        path.unlink(missing_ok=True)
