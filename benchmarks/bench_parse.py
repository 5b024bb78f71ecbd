"""Parse throughput: edsconv against eds-pie 1.2.0 and a bare regex token scan (the floor).

    python benchmarks/bench_parse.py [--repeat N] [--corpus DIR] [--json PATH]

Every contender reads the same inputs: the real corpus and the generated 2 MB
Params-heavy file. Each file is timed best of N; a row's seconds are the sum of
its files' best times. MB = 10**6 bytes.
"""

from __future__ import annotations

import argparse
import json
import logging
import re
import time
from pathlib import Path

logging.basicConfig(level=logging.CRITICAL)  # before eds_pie, which would log every token at DEBUG
from eds_pie.eds_pie import Parser  # noqa: E402

import edsconv  # noqa: E402
from edsconv.eds.source import decode  # noqa: E402
from generate import generate  # noqa: E402

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "real"

# Strings, comments, numbers and words, punctuation: the tokens of an EDS, white space skipped.
FLOOR = re.compile(rb'L?"(?:[^"\\\n]|\\.)*"|\$[^\n]*|[A-Za-z0-9_.:+-]+|[^ \t\r\n\f\v]')


def floor_scan(data: bytes) -> None:
    for _ in FLOOR.finditer(data):
        pass


def best(function, argument, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function(argument)
        times.append(time.perf_counter() - start)
    return min(times)


def eds_pie_parse(text: str) -> None:
    Parser(text).parse()


def measure(name: str, files: list[Path], repeat: int) -> dict:
    """Best-of-``repeat`` seconds per contender over ``files``; eds-pie skips the files it raises on."""
    row = {"input": name, "files": len(files), "bytes": 0, "edsconv_s": 0.0, "floor_s": 0.0,
           "eds_pie_s": 0.0, "eds_pie_bytes": 0, "eds_pie_edsconv_s": 0.0, "eds_pie_failures": []}
    for path in files:
        data = path.read_bytes()
        text = decode(data).text
        edsconv_s = best(edsconv.parse, data, repeat)
        row["bytes"] += len(data)
        row["edsconv_s"] += edsconv_s
        row["floor_s"] += best(floor_scan, data, repeat)
        try:
            eds_pie_parse(text)
        except Exception as error:  # eds-pie raises plain Exception on files it cannot read
            row["eds_pie_failures"].append(f"{path.name}: {type(error).__name__}: {str(error)[:80]}")
            continue
        row["eds_pie_s"] += best(eds_pie_parse, text, repeat)
        row["eds_pie_bytes"] += len(data)
        row["eds_pie_edsconv_s"] += edsconv_s
    mb = row["bytes"] / 1e6
    row["edsconv_mb_s"] = mb / row["edsconv_s"]
    row["floor_mb_s"] = mb / row["floor_s"]
    row["eds_pie_mb_s"] = row["eds_pie_bytes"] / 1e6 / row["eds_pie_s"] if row["eds_pie_s"] else None
    # Both ratios compare throughputs; edsconv/eds-pie only over the files eds-pie could read.
    row["edsconv_over_eds_pie"] = row["eds_pie_s"] / row["eds_pie_edsconv_s"] if row["eds_pie_s"] else None
    row["edsconv_over_floor"] = row["floor_s"] / row["edsconv_s"]
    return row


def print_table(rows: list[dict]) -> None:
    print(f"{'input':<24}{'bytes':>11}{'edsconv s':>11}{'MB/s':>7}{'eds-pie s':>11}{'MB/s':>7}"
          f"{'floor s':>9}{'MB/s':>7}{'vs eds-pie':>12}{'vs floor':>10}")
    for row in rows:
        pie = row["eds_pie_mb_s"]
        print(f"{row['input']:<24}{row['bytes']:>11}{row['edsconv_s']:>11.3f}{row['edsconv_mb_s']:>7.2f}"
              f"{row['eds_pie_s']:>11.3f}{pie or 0:>7.2f}{row['floor_s']:>9.3f}{row['floor_mb_s']:>7.1f}"
              f"{row['edsconv_over_eds_pie'] or 0:>11.2f}x{row['edsconv_over_floor']:>9.3f}x")
    for row in rows:
        if row["eds_pie_failures"]:
            print(f"\n{row['input']}: eds-pie raised on {len(row['eds_pie_failures'])} of {row['files']} files "
                  f"({row['bytes'] - row['eds_pie_bytes']} bytes), left out of its total and of the ratio:")
            print("\n".join(f"  {failure}" for failure in row["eds_pie_failures"]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="timings per file; the best counts (default 5)")
    parser.add_argument("--corpus", type=Path, default=CORPUS, help=f"real EDS files (default {CORPUS})")
    parser.add_argument("--json", type=Path, help="also write the numbers to this JSON file")
    args = parser.parse_args()
    edsconv.parse(b"[File]\n")  # compile (or load) the grammar outside the timings
    rows = []
    corpus = sorted(args.corpus.glob("*.[eE][dD][sS]"))
    if corpus:
        rows.append(measure(f"real corpus ({len(corpus)} files)", corpus, args.repeat))
    else:
        print(f"no real corpus at {args.corpus}: skipping it")
    rows.append(measure("generated 2 MB Params", [generate("params-2mb.eds")], args.repeat))
    print(f"best of {args.repeat} per file; MB = 10**6 bytes; ratios are throughput edsconv / other\n")
    print_table(rows)
    if args.json:
        args.json.write_text(json.dumps({"repeat": args.repeat, "rows": rows}, indent=2) + "\n")


if __name__ == "__main__":
    main()
