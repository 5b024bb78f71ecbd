"""Peak memory of edsconv parsing the generated 2 MB and 50 MB files.

    python benchmarks/bench_memory.py

Each parse runs in a fresh subprocess, which reports its peak RSS
(resource.getrusage ru_maxrss, Linux: KiB) and the parse time; a subprocess that
only imports edsconv and loads the grammar gives the baseline. MiB = 2**20 bytes.
"""

from __future__ import annotations

import json
import subprocess
import sys

from generate import SIZES, generate

CHILD = """
import json, resource, sys, time
import edsconv
edsconv.parse(b"[File]\\n")
seconds = 0.0
if len(sys.argv) > 1:
    start = time.perf_counter()
    eds = edsconv.parse(open(sys.argv[1], "rb").read())
    seconds = time.perf_counter() - start
print(json.dumps({"rss_kib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, "seconds": seconds}))
"""


def child(*args: str) -> dict:
    result = subprocess.run([sys.executable, "-c", CHILD, *args], capture_output=True, text=True, check=True)
    return json.loads(result.stdout)


def main() -> None:
    baseline = child()["rss_kib"] / 1024
    print(f"baseline (import edsconv, grammar loaded): {baseline:.0f} MiB peak RSS\n")
    print(f"{'input':<18}{'MiB':>7}{'peak RSS MiB':>14}{'above baseline':>16}{'above / input':>15}{'seconds':>9}")
    for name in SIZES:
        path = generate(name)
        size = path.stat().st_size / 2**20
        run = child(str(path))
        peak = run["rss_kib"] / 1024
        print(f"{name:<18}{size:>7.1f}{peak:>14.0f}{peak - baseline:>16.0f}{(peak - baseline) / size:>14.1f}x"
              f"{run['seconds']:>9.2f}")


if __name__ == "__main__":
    main()
