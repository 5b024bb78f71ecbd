"""Rejecting a large invalid device profile: `edsconv validate` on many schema errors.

    python benchmarks/bench_invalid_profile.py                  # 20,000 parameters, every 4th broken
    python benchmarks/bench_invalid_profile.py --params 100000 --every 20

The profile is the one eds2xml writes for the dense parameter shape (generate.py), with the
ParamDescriptor of every ``--every``-th parameter made invalid (``ZZZZ`` is no hexBinary): one
XML003 per broken parameter. It is written to ``<tempdir>/edsconv-bench``, never committed.
The time is that of :func:`edsconv.xml.validate.validate_file` (read, fast path, xmlschema, the
report); it should grow with size + errors, not with size x errors (issue 20 item 6, where a
52 MB profile with 4,900 errors took 19.5 minutes).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from lxml import etree

import edsconv
from edsconv.xml.common import Header
from edsconv.xml.convert import profile_documents
from edsconv.xml.validate import validate_file
from generate import DEFAULT_DIR, HEADER, dense_param


def invalid_profile(params: int, every: int, directory: Path = DEFAULT_DIR) -> tuple[Path, int]:
    """The device profile of ``params`` dense parameters, every ``every``-th one's ParamDescriptor
    broken; its path and the number of broken parameters."""
    text = HEADER + "[Params]\n" + "".join(dense_param(n) for n in range(1, params + 1))
    device, _ = edsconv.analyse(edsconv.parse(text.encode("ascii")))
    document = profile_documents(device, Header.derive(device), "bench")[0]
    root = etree.fromstring(document.data)
    descriptors = root.iter("ParamDescriptor")
    broken = 0
    for index, descriptor in enumerate(descriptors):
        if index % every == every - 1:
            descriptor.text = "ZZZZ"
            broken += 1
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / f"invalid-profile-{params}-every-{every}.xml"
    path.write_bytes(etree.tostring(root, xml_declaration=True, encoding="UTF-8"))
    return path, broken


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--params", type=int, default=20000, help="parameters in the profile (default 20000)")
    parser.add_argument("--every", type=int, default=4, help="break every n-th parameter (default 4)")
    options = parser.parse_args()
    path, broken = invalid_profile(options.params, options.every)
    start = time.perf_counter()
    report = validate_file(path)
    elapsed = time.perf_counter() - start
    print(f"{path.name}: {path.stat().st_size / 2**20:.1f} MiB, {broken} broken parameters, "
          f"{len(report.diagnostics)} diagnostics, validate {elapsed:.2f} s")


if __name__ == "__main__":
    main()
