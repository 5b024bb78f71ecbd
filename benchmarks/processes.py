"""What is measured in fresh processes: peak memory per step and shape, start-up of small commands.

Memory: a child process imports what the step needs, warms it on a one-line
file, reads the input bytes, runs the step once and reports its peak RSS
(``VmHWM`` of /proc/self/status: ``ru_maxrss`` would also count the memory of
the parent it was forked from, which Linux keeps across exec). The same child
on a one-line file is the baseline; the figure is the peak above it, per input
byte.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from common import best_of

REPO = Path(__file__).resolve().parents[1]

CHILD = r"""
import json, logging, resource, sys, time
step, path = sys.argv[1], sys.argv[2]
logging.basicConfig(level=logging.CRITICAL)
import edsconv
from edsconv.eds.source import decode
if step.startswith("eds-pie"):
    from eds_pie.eds_pie import CIP_EDS, Parser
    run = (lambda data: Parser(decode(data).text).parse()) if step == "eds-pie read" else (
        lambda data: CIP_EDS(decode(data).text))
else:
    run = edsconv.parse if step == "read" else (lambda data: edsconv.analyse(edsconv.parse(data)))
try:
    run(b"[File]\n        DescText = \"warm\";\n")
except Exception:
    pass
data = open(path, "rb").read()
start = time.perf_counter()
try:
    kept = run(data)
    failed = False
except Exception:
    failed = True
seconds = time.perf_counter() - start
try:
    status = open("/proc/self/status").read()
    peak = int(status.split("VmHWM:")[1].split()[0])
except (OSError, IndexError):
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print(json.dumps({"rss_kib": peak, "seconds": seconds, "failed": failed}))
"""

MEMORY_STEPS = ("read", "check", "eds-pie read", "eds-pie check")


def child(step: str, path: Path) -> dict:
    result = subprocess.run([sys.executable, "-c", CHILD, step, str(path)], capture_output=True, text=True,
                            check=True)
    return json.loads(result.stdout)


def peak_memory(step: str, path: Path) -> dict:
    """Peak RSS above the baseline of the same step on a one-line file, in MiB and in bytes per input byte."""
    with tempfile.NamedTemporaryFile("wb", suffix=".eds", delete=False) as tiny:
        tiny.write(b"[File]\n")
    try:
        baseline = child(step, Path(tiny.name))["rss_kib"] * 1024
    finally:
        Path(tiny.name).unlink()
    run = child(step, path)
    above = run["rss_kib"] * 1024 - baseline
    return {"step": step, "file": path.name, "bytes": path.stat().st_size, "baseline_mib": baseline / 2**20,
            "above_mib": above / 2**20, "bytes_per_byte": above / path.stat().st_size, "seconds": run["seconds"],
            "failed": run["failed"]}


#: the environment of the timed commands: bytecode caches written and used, as an installed package has them
#: (pip compiles them when it installs; with PYTHONDONTWRITEBYTECODE every run compiles every module again)
_WARM_ENVIRONMENT = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}


def wall(command: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False, env=_WARM_ENVIRONMENT)
    return time.perf_counter() - start


def small_files(corpus: Path) -> tuple[Path, Path]:
    """A small EDS (a 17 kB real file, else the repository's example) and a small hand-written device
    profile that only xmlschema accepts (its unqualified VendorNote is the XSD 1.0 rendition's deviation)."""
    real = corpus / "EIPStackGroup__OpENer__opener_sample_app.eds"
    eds = real if real.exists() else REPO / "corpus" / "examples" / "io_adapter.eds"
    return eds, REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"


def written_profile(script: str, directory: Path) -> Path:
    """The device profile eds2xml writes for the repository's example (accepted by lxml and the rendition)."""
    subprocess.run([script, "eds2xml", str(REPO / "corpus" / "examples" / "io_adapter.eds"), "-o", str(directory),
                    "--force"], check=True, capture_output=True)
    return directory / "io_adapter_device.xml"


def startup(corpus: Path, repeat: int) -> list[dict]:
    """Warm wall time (best of ``repeat``, after one run that fills the caches, bytecode too) of small commands."""
    script = shutil.which("edsconv", path=str(Path(sys.executable).parent)) or "edsconv"
    eds, profile = small_files(corpus)
    written = written_profile(script, Path(tempfile.mkdtemp(prefix="edsconv-startup-")))
    commands = {"python -c pass (interpreter alone)": [sys.executable, "-c", "pass"],
                f"edsconv parse {eds.name}": [script, "parse", str(eds)],
                f"edsconv lint {eds.name}": [script, "lint", str(eds)],
                f"edsconv validate {written.name} (as eds2xml writes it)": [script, "validate", str(written)],
                f"edsconv validate {profile.parent.name}/{profile.name} (xmlschema)":
                    [script, "validate", str(profile)]}
    if corpus.is_dir():
        commands["edsconv lint -j1 <real corpus>"] = [script, "lint", "-j", "1", str(corpus)]
        commands["edsconv lint <real corpus> (every core)"] = [script, "lint", str(corpus)]
    rows = []
    for name, command in commands.items():
        wall(command)
        rows.append({"command": name, "seconds": best_of(repeat, wall, command, budget=15.0)[0]})
    return rows
