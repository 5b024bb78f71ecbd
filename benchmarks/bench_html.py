"""``show --format html`` against ``show``'s text: time and page size (issue 23's goals).

    python benchmarks/bench_html.py [--repeat N]

Inputs: the largest file of the real corpus (when ../shared/corpus/real is there) and two
generated dense files (generate.py): ``dense-params-40k.eds`` (2.7 MB, the dense file of the
language server's and the reader's benchmarks: 40,000 parameters) and ``dense-mixed-3mb.eds``
(20,000 parameters, 10,000 assemblies, 6,000 connections). Each command runs in this process,
as ``run_all.py``'s steps do, its output discarded (the page written to a temporary file, as
``-o`` does); each figure is the best of N runs, text and page alternating so that both see the
same load. Goals: the page under 2x the
text's time and under 3x the EDS's size. Then the size ratio over the whole real corpus (median, max).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import statistics
import tempfile
from pathlib import Path

from common import CORPUS, best_of, corpus_files
from edsconv.cli import cli
from generate import generate


def run(*arguments: str) -> None:
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        cli.main(list(arguments), standalone_mode=False)


def measure(path: Path, repeat: int, page: Path) -> tuple[float, float, int]:
    """(text seconds, html seconds, page bytes), each time the best of ``repeat`` alternating runs."""
    text_times, html_times = [], []
    for _ in range(repeat):
        text_times.append(best_of(1, run, "show", str(path))[0])
        html_times.append(best_of(1, run, "show", "--format", "html", "-o", str(page), "--force", str(path))[0])
    return min(text_times), min(html_times), page.stat().st_size


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="runs per figure (best of N)")
    options = parser.parse_args()
    real = corpus_files(CORPUS)
    inputs = ([max(real, key=lambda p: p.stat().st_size)] if real else []) + [
        generate("dense-params-40k.eds"), generate("dense-mixed-3mb.eds")]
    print("| file | EDS | show text | show html | time ratio (goal < 2) | page | size ratio (goal < 3) |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    with tempfile.TemporaryDirectory() as directory:
        for path in inputs:
            text, html, size = measure(path, options.repeat, Path(directory) / "page.html")
            eds = path.stat().st_size
            print(f"| {path.name[:60]} | {eds / 1e6:.2f} MB | {text:.2f} s | {html:.2f} s | {html / text:.2f} "
                  f"| {size / 1e6:.2f} MB | {size / eds:.2f} |")
        if real:
            print(corpus_ratios(real, Path(directory) / "page.html"))


def corpus_ratios(files: list[Path], page: Path) -> str:
    """The page's size over the EDS's for every file: their median and maximum."""
    ratios = []
    for path in files:
        run("show", "--format", "html", "-o", str(page), "--force", str(path))
        ratios.append((page.stat().st_size / path.stat().st_size, path))
    largest, worst = max(ratios)
    return (f"\nreal corpus, {len(ratios)} files: page / EDS median {statistics.median(r for r, _ in ratios):.2f}, "
            f"max {largest:.2f} ({worst.name}, {worst.stat().st_size} bytes)")


if __name__ == "__main__":
    main()
