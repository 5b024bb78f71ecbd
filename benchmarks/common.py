"""What the benchmark scripts share: options, the real corpus, best-of timing."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "real"


def options(doc: str, repeat: int) -> argparse.Namespace:
    """--repeat, --corpus and --json, as every benchmark takes them."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=repeat, help=f"timings per input; the best counts "
                        f"(default {repeat})")
    parser.add_argument("--corpus", type=Path, default=CORPUS, help=f"real EDS files (default {CORPUS})")
    parser.add_argument("--json", type=Path, help="also write the numbers to this JSON file")
    return parser.parse_args()


def corpus_files(corpus: Path) -> list[Path]:
    return sorted(corpus.glob("*.[eE][dD][sS]"))


def best_of(repeat: int, function, *arguments) -> tuple[float, object]:
    """The shortest of ``repeat`` runs, in seconds, and the last result."""
    times, result = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        result = function(*arguments)
        times.append(time.perf_counter() - start)
    return min(times), result
