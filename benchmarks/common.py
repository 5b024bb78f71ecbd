"""What the benchmark modules share: the inputs (real corpus and generated shapes) and best-of timing."""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

from generate import generate

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus" / "real"


def corpus_files(corpus: Path) -> list[Path]:
    return sorted(corpus.glob("*.[eE][dD][sS]"))


@dataclass
class Shape:
    """One row group of the table: a file shape and the files that stand for it."""

    name: str
    #: "real", "ez" (EZ-EDS: a comment on every line) or "dense" (one short entry per line, no comment)
    kind: str
    files: list[Path]
    #: the file whose peak memory is measured (the largest)
    memory_file: Path = field(init=False)

    def __post_init__(self) -> None:
        self.memory_file = max(self.files, key=lambda path: path.stat().st_size)

    @property
    def size(self) -> int:
        return sum(path.stat().st_size for path in self.files)


def shapes(corpus: Path, quick: bool) -> list[Shape]:
    """The inputs of a run: the real corpus when present, and generated files of both shapes."""
    found = corpus_files(corpus)
    real = [Shape(f"real corpus ({len(found)} files)", "real", found)] if found else []
    names = (["params-0.5mb.eds", "dense-params-10k.eds", "dense-mixed-0.4mb.eds", "vendor-sections-20k.eds"]
             if quick else ["params-2mb.eds", "dense-params-40k.eds", "dense-mixed-1.7mb.eds",
                            "vendor-sections-200k.eds"])
    kinds = ["ez", "dense", "dense", "dense"]
    return real + [Shape(name.removesuffix(".eds"), kind, [generate(name)])
                   for name, kind in zip(names, kinds, strict=True)]


def best_of(repeat: int, function, *arguments, budget: float = 10.0) -> tuple[float, object]:
    """The shortest of up to ``repeat`` runs, in seconds, and the last result.

    Repeats stop once the runs together took ``budget`` seconds: one run of a
    slow step is already a stable figure, and a full run must end in minutes.
    """
    times, result = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        result = function(*arguments)
        times.append(time.perf_counter() - start)
        if sum(times) > budget:
            break
    return min(times), result
