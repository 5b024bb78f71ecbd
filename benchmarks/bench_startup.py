"""Start-up time of `edsconv parse` on a small file, with a warm and a cold Lark grammar cache.

    python benchmarks/bench_startup.py [--repeat N] [FILE]

FILE defaults to a small real EDS of the corpus, else to a small file of the
repository's corpus/. Warm: best of N runs of `python -m edsconv parse FILE` and
of the `edsconv` console script. Cold: one run of each after deleting Lark's
cache files (<tempdir>/.lark_cache_*), so that the grammar is compiled again.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SMALL_FILES = [REPO.parent / "shared/corpus/real/EIPStackGroup__OpENer__opener_sample_app.eds",
               *sorted((REPO / "corpus").rglob("*.eds"))]


def wall(command: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def clear_lark_cache() -> None:
    for cache in Path(tempfile.gettempdir()).glob(".lark_cache_*"):
        cache.unlink(missing_ok=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=10, help="warm runs; the best counts (default 10)")
    parser.add_argument("file", type=Path, nargs="?", help="the EDS to parse")
    args = parser.parse_args()
    path = args.file or next((p for p in SMALL_FILES if p.exists()), None)
    if path is None:
        sys.exit("no small EDS file found: pass one")
    script = shutil.which("edsconv", path=str(Path(sys.executable).parent)) or shutil.which("edsconv")
    commands = {"python -c pass (floor)": [sys.executable, "-c", "pass"],
                "python -m edsconv parse": [sys.executable, "-m", "edsconv", "parse", str(path)],
                "edsconv parse (console script)": [script, "parse", str(path)]}
    print(f"{path.name} ({path.stat().st_size} bytes); warm: best of {args.repeat}\n")
    print(f"{'command':<32}{'warm s':>8}{'cold s':>8}")
    for name, command in commands.items():
        wall(command)  # fills the cache
        warm = min(wall(command) for _ in range(args.repeat))
        clear_lark_cache()
        cold = wall(command)
        print(f"{name:<32}{warm:>8.3f}{cold:>8.3f}")


if __name__ == "__main__":
    main()
