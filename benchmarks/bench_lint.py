"""Lint throughput: edsconv's full check against eds-pie 1.2.0's parse + validate.

    python benchmarks/bench_lint.py [--repeat N] [--corpus DIR] [--json PATH]

In one run, on the same files: edsconv in-process (read, semantic model, every
check) and eds-pie's ``CIP_EDS(text)`` (its parser plus its semantic
validation); then the whole ``edsconv lint DIR`` command, process start-up
included, on one core (``-j1``) and on all cores. Each figure is the best of N.
"""

from __future__ import annotations

import json
import logging
import os
import subprocess
import sys
from pathlib import Path

logging.basicConfig(level=logging.CRITICAL)  # before eds_pie, which logs every token at DEBUG
from eds_pie.eds_pie import CIP_EDS  # noqa: E402

import edsconv  # noqa: E402
from common import best_of, corpus_files, options  # noqa: E402
from edsconv.eds.source import decode  # noqa: E402


def edsconv_lint(data: bytes) -> None:
    edsconv.analyse(edsconv.parse(data))


def eds_pie_check(text: str) -> bool:
    """True when eds-pie read and validated the file; it raises on many real files."""
    try:
        CIP_EDS(text)
    except Exception:  # noqa: BLE001 - any failure of the contender counts as one
        return False
    return True


def in_process(files: list[Path], repeat: int) -> dict:
    row = {"files": len(files), "bytes": 0, "edsconv_s": 0.0, "eds_pie_s": 0.0, "eds_pie_files": 0,
           "eds_pie_bytes": 0, "edsconv_on_eds_pie_files_s": 0.0}
    for path in files:
        data = path.read_bytes()
        text = decode(data).text
        seconds = best_of(repeat, edsconv_lint, data)[0]
        row["bytes"] += len(data)
        row["edsconv_s"] += seconds
        if eds_pie_check(text):
            row["eds_pie_s"] += best_of(repeat, CIP_EDS, text)[0]
            row["eds_pie_files"] += 1
            row["eds_pie_bytes"] += len(data)
            row["edsconv_on_eds_pie_files_s"] += seconds
    return row


def whole_command(corpus: Path, repeat: int, jobs: str | None) -> float:
    command = [sys.executable, "-m", "edsconv", "lint", str(corpus)] + (["-j", jobs] if jobs else [])

    def run() -> None:
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)

    return best_of(repeat, run)[0]


def main() -> None:
    arguments = options(__doc__, 3)
    files = corpus_files(arguments.corpus)
    if not files:
        sys.exit(f"no corpus at {arguments.corpus}")
    row = in_process(files, arguments.repeat)
    megabytes = row["bytes"] / 1e6
    print(f"{row['files']} files, {megabytes:.2f} MB, best of {arguments.repeat}")
    print(f"edsconv read+model+checks : {row['edsconv_s']:.3f} s  {row['files'] / row['edsconv_s']:.1f} files/s  "
          f"{megabytes / row['edsconv_s']:.2f} MB/s")
    pie_mb = row["eds_pie_bytes"] / 1e6
    print(f"eds-pie parse+validate    : {row['eds_pie_s']:.3f} s on the {row['eds_pie_files']} files it reads "
          f"({pie_mb:.2f} MB): {pie_mb / row['eds_pie_s']:.2f} MB/s; edsconv on the same files "
          f"{pie_mb / row['edsconv_on_eds_pie_files_s']:.2f} MB/s, ratio "
          f"{row['eds_pie_s'] / row['edsconv_on_eds_pie_files_s']:.2f}x")
    row["command_one_core_s"] = whole_command(arguments.corpus, arguments.repeat, "1")
    row["command_all_cores_s"] = whole_command(arguments.corpus, arguments.repeat, None)
    print(f"edsconv lint DIR, -j1     : {row['command_one_core_s']:.2f} s wall")
    print(f"edsconv lint DIR, {os.cpu_count()} cores : {row['command_all_cores_s']:.2f} s wall, speed-up "
          f"{row['command_one_core_s'] / row['command_all_cores_s']:.2f}x")
    if arguments.json:
        arguments.json.write_text(json.dumps(row, indent=2))


if __name__ == "__main__":
    main()
