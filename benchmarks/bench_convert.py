"""Conversion throughput: eds2xml and xml2eds, in MB of EDS per second.

    python benchmarks/bench_convert.py [--repeat N] [--corpus DIR] [--json PATH]

eds2xml: read the EDS, build the model, produce and validate both profiles.
xml2eds: read both profiles back into a model and write canonical EDS text.
Inputs: the real corpus and the generated 2 MB Params-heavy file; each file is
timed best of N and a row sums its files' best times. MB = 10**6 bytes of EDS.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from lxml import etree

import edsconv
from common import best_of, corpus_files, options
from edsconv.eds.from_model import device_to_eds
from edsconv.eds.writer import write
from edsconv.model import Device
from edsconv.xml.commnet import read_commnet_profile
from edsconv.xml.common import Header
from edsconv.xml.convert import profile_documents
from edsconv.xml.device_read import read_device_profile
from generate import generate


def eds2xml(data: bytes) -> list:
    device = edsconv.build(edsconv.parse(data))
    return profile_documents(device, Header.derive(device), "bench")


def xml2eds(documents: list) -> str:
    device = Device()
    read_device_profile(etree.fromstring(documents[0].data), device)
    read_commnet_profile(etree.fromstring(documents[1].data), device)
    return write(device_to_eds(device))


def measure(name: str, files: list[Path], repeat: int) -> dict:
    row = {"input": name, "files": len(files), "bytes": 0, "eds2xml_s": 0.0, "xml2eds_s": 0.0}
    for path in files:
        data = path.read_bytes()
        seconds, documents = best_of(repeat, eds2xml, data)
        row["bytes"] += len(data)
        row["eds2xml_s"] += seconds
        row["xml2eds_s"] += best_of(repeat, xml2eds, documents)[0]
    megabytes = row["bytes"] / 1e6
    print(f"{name}: {row['files']} files, {megabytes:.2f} MB; eds2xml {row['eds2xml_s']:.2f} s "
          f"({megabytes / row['eds2xml_s']:.2f} MB/s), xml2eds {row['xml2eds_s']:.2f} s "
          f"({megabytes / row['xml2eds_s']:.2f} MB/s)")
    return row


def main() -> None:
    arguments = options(__doc__, 3)
    rows = []
    files = corpus_files(arguments.corpus)
    if files:
        rows.append(measure("real corpus", files, arguments.repeat))
    else:
        print(f"no corpus at {arguments.corpus}; skipped", file=sys.stderr)
    rows.append(measure("generated 2 MB Params", [generate("params-2mb.eds")], arguments.repeat))
    if arguments.json:
        arguments.json.write_text(json.dumps(rows, indent=2))


if __name__ == "__main__":
    main()
