"""The whole benchmark table in one run: edsconv against eds-pie 1.2.0 on every file shape.

    python benchmarks/run_all.py [--quick] [--repeat N] [--steps read,check,...] [--corpus DIR] [--json PATH]

Throughput of each step (read, check, lint, show text, show json, eds2xml,
xml2eds) on the real corpus, the EZ-EDS shape and the dense shapes; peak memory
per shape in fresh processes; start-up of small commands; then issue 13's goals
with the measured ratio. ``--quick``: one run per figure and smaller generated
files (about a quarter of the size), for a look in a minute or two.
"""

from __future__ import annotations

import argparse
import importlib.metadata
import json
import os
import platform
import time
from pathlib import Path

from common import CORPUS, Shape, best_of, shapes
from generate import generate
from processes import MEMORY_STEPS, peak_memory, startup
from steps import STEPS, Step, eds_pie_text

MB = 1e6


def measure(step: Step, shape: Shape, repeat: int) -> dict:
    """Best-of seconds per file, summed over the shape; eds-pie's files it raises on are left out of its ratio."""
    row = {"step": step.name, "input": shape.name, "kind": shape.kind, "bytes": shape.size, "edsconv_s": 0.0,
           "floor_s": None, "eds_pie_s": None, "eds_pie_bytes": 0, "edsconv_on_eds_pie_files_s": 0.0,
           "eds_pie_failures": []}
    for path in shape.files:
        data = path.read_bytes()
        seconds = best_of(repeat, step.edsconv, step.argument(path, data))[0]
        row["edsconv_s"] += seconds
        if step.floor:
            row["floor_s"] = (row["floor_s"] or 0.0) + best_of(repeat, step.floor, data)[0]
        if step.eds_pie is None:
            continue
        try:
            pie_seconds = best_of(repeat, step.eds_pie, eds_pie_text(data))[0]
        except Exception as error:  # noqa: BLE001 - eds-pie raises plain Exception (and worse) on files it cannot read
            row["eds_pie_failures"].append(f"{path.name}: {type(error).__name__}: {str(error)[:70]}")
            continue
        row["eds_pie_s"] = (row["eds_pie_s"] or 0.0) + pie_seconds
        row["eds_pie_bytes"] += len(data)
        row["edsconv_on_eds_pie_files_s"] += seconds
    return row


def ratio(row: dict) -> float | None:
    """edsconv's throughput over eds-pie's, on the files eds-pie reads."""
    return row["eds_pie_s"] / row["edsconv_on_eds_pie_files_s"] if row["eds_pie_s"] else None


def throughput_table(rows: list[dict]) -> list[str]:
    lines = ["| step | input | MB | edsconv s | MB/s | eds-pie s | eds-pie MB/s | edsconv / eds-pie | time / floor |",
             "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for row in rows:
        pie = (f"{row['eds_pie_s']:.3f} | {row['eds_pie_bytes'] / MB / row['eds_pie_s']:.2f} | {ratio(row):.2f}x"
               if row["eds_pie_s"] else "- | - | -")
        floor = f"{row['edsconv_s'] / row['floor_s']:.1f}x" if row["floor_s"] else "-"
        lines.append(f"| {row['step']} | {row['input']} | {row['bytes'] / MB:.2f} | {row['edsconv_s']:.3f} | "
                     f"{row['bytes'] / MB / row['edsconv_s']:.2f} | {pie} | {floor} |")
    failures = next((row for row in rows if row["eds_pie_failures"]), None)
    if failures:
        lines.append(f"\neds-pie raised on {len(failures['eds_pie_failures'])} of the files of "
                     f"{failures['input']}; they are left out of its columns and of the ratio:")
        lines += [f"- {failure}" for failure in failures["eds_pie_failures"]]
    return lines


def memory_table(rows: list[dict]) -> list[str]:
    lines = ["| step | file | MB | baseline MiB | peak above baseline MiB | bytes per input byte | s |",
             "| --- | --- | ---: | ---: | ---: | ---: | ---: |"]
    for row in rows:
        figure = "raised" if row["failed"] else f"{row['bytes_per_byte']:.1f}"
        lines.append(f"| {row['step']} | {row['file']} | {row['bytes'] / MB:.2f} | {row['baseline_mib']:.0f} | "
                     f"{row['above_mib']:.0f} | {figure} | {row['seconds']:.2f} |")
    return lines


def goal(lines: list[str], name: str, where: str, measured: float, target: str, met: bool) -> None:
    lines.append(f"| {name} | {where} | {measured:.2f} | {target} | {'yes' if met else '**no**'} |")


def goals_table(rows: list[dict], memory: list[dict], starts: list[dict]) -> list[str]:
    """Issue 13's goals, each with the figure of this run."""
    lines = ["| goal | input | measured | target | met |", "| --- | --- | ---: | --- | --- |"]
    by = {(row["step"], row["input"]): row for row in rows}
    for row in rows:
        if row["step"] in ("read", "check") and ratio(row):
            target = 5 if row["step"] == "read" else 4
            goal(lines, f"{row['step']}: x eds-pie", row["input"], ratio(row), f">= {target}", ratio(row) >= target)
        if row["step"] == "read" and row["kind"] == "real":
            slower = row["edsconv_s"] / row["floor_s"]
            goal(lines, "read: time / regex floor", row["input"], slower, "<= 4", slower <= 4)
        check = by.get(("check", row["input"]))
        if row["step"] == "eds2xml" and row["kind"] == "real" and check:
            share = check["edsconv_s"] / row["edsconv_s"]
            goal(lines, "eds2xml: throughput / check's", row["input"], share, ">= 0.5", share >= 0.5)
        lint = by.get(("lint", row["input"]))
        if row["step"].startswith("show") and lint:
            share = row["edsconv_s"] / lint["edsconv_s"]
            goal(lines, f"{row['step']}: time / lint's", row["input"], share, "<= 1.5", share <= 1.5)
    for row in memory:
        limit = {"dense": 25, "ez": 10}.get(row["kind"])
        if row["step"] == "read" and limit and not row["failed"]:
            goal(lines, "read: peak RSS / input byte", row["file"], row["bytes_per_byte"], f"<= {limit}",
                 row["bytes_per_byte"] <= limit)
    for row in starts:
        limit = 0.3 if "validate" in row["command"] else 0.25
        if row["command"].split()[1:2] in (["parse"], ["validate"]) or (
                row["command"].startswith("edsconv lint") and "corpus" not in row["command"]):
            goal(lines, "start-up (s, warm)", row["command"], row["seconds"], f"< {limit}", row["seconds"] < limit)
    return lines


def environment() -> str:
    versions = ", ".join(f"{name} {importlib.metadata.version(name)}"
                         for name in ("lark", "lxml", "xmlschema", "eds-pie"))
    return (f"{time.strftime('%Y-%m-%d %H:%M')}, Python {platform.python_version()}, {versions}, "
            f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")


def arguments() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one run per figure, smaller generated files")
    parser.add_argument("--repeat", type=int, default=3, help="runs per figure, the best counts (default 3)")
    parser.add_argument("--steps", default="", help="only these steps (comma-separated), e.g. read,check; "
                        "memory and start-up are the steps 'memory' and 'startup'")
    parser.add_argument("--corpus", type=Path, default=CORPUS, help=f"real EDS files (default {CORPUS})")
    parser.add_argument("--json", type=Path, help="also write every figure to this JSON file")
    return parser.parse_args()


def memory_rows(inputs: list[Shape], quick: bool) -> list[dict]:
    rows = []
    for shape in inputs:
        for step in MEMORY_STEPS:
            rows.append({**peak_memory(step, shape.memory_file), "kind": shape.kind})
    if not quick:
        rows.append({**peak_memory("read", generate("params-50mb.eds")), "kind": "ez"})
    return rows


def main() -> None:
    options = arguments()
    repeat = 1 if options.quick else options.repeat
    wanted = set(filter(None, options.steps.split(",")))
    inputs = shapes(options.corpus, options.quick)
    print(f"# edsconv benchmarks\n\n{environment()}; best of {repeat}; MB = 10^6 bytes\n")
    rows = [measure(step, shape, repeat) for step in STEPS if not wanted or step.name in wanted
            for shape in inputs]
    memory = memory_rows(inputs, options.quick) if not wanted or "memory" in wanted else []
    starts = startup(options.corpus, 3 if options.quick else 10) if not wanted or "startup" in wanted else []
    sections = [("Throughput", throughput_table(rows) if rows else []),
                ("Peak memory (a fresh process per figure)", memory_table(memory) if memory else []),
                ("Start-up and whole commands (wall, warm caches)",
                 ["| command | s |", "| --- | ---: |"] + [f"| {r['command']} | {r['seconds']:.3f} |" for r in starts]
                 if starts else []),
                ("Goals of issue 13", goals_table(rows, memory, starts))]
    for title, lines in sections:
        if lines:
            print(f"## {title}\n\n" + "\n".join(lines) + "\n")
    print(f"load average at the end: {os.getloadavg()[0]:.2f}")
    if options.json:
        options.json.write_text(json.dumps({"environment": environment(), "repeat": repeat, "throughput": rows,
                                            "memory": memory, "startup": starts}, indent=2) + "\n")


if __name__ == "__main__":
    main()
