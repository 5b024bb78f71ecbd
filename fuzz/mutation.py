"""A bounded mutation run without atheris: for CI (tests/test_fuzz.py) and machines where atheris
does not build. Not coverage-guided: it mutates the seeds at random (bytes, ranges, tokens of both
languages, splices, long repetitions) for a fixed time and checks every input as fuzz/fuzz.py does.

    python fuzz/mutation.py TARGET SECONDS [--seed N] [--real] [--generated]

A failing input is written to build/fuzz/TARGET/ and its path is in the error.
"""

from __future__ import annotations

import hashlib
import random
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import fuzz_targets as targets

#: Pieces of EDS and XML syntax the mutations insert.
TOKENS = (b"[", b"]", b"=", b";", b",", b"{", b"}", b'"', b"$", b"\n", b"\r\n", b"\\", b"L\"", b"0x", b"-",
          b"Param1", b"Assem1", b"[Params]", b"[Device]", b"VendCode = ", b"\x00", b"\xff\xfe", b"\xef\xbb\xbf",
          b"<", b">", b"</", b"/>", b"&amp;", b"&#0;", b"<![CDATA[", b"]]>", b"<!--", b"-->", b"<?xml", b"xmlns=",
          b"<!DOCTYPE x [", b"99999999999999999999", b"1e308", b"ProfileTechnology", b"edsconv:")
#: Mutated inputs are cut to this size, so that a run stays short.
MAX_SIZE = 65536


@dataclass
class Outcome:
    target: str
    executions: int
    seconds: float


def mutate(data: bytes, rng: random.Random, donors: list[bytes]) -> bytes:
    """One to four random edits of ``data``."""
    out = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        at = rng.randint(0, len(out))
        end = min(len(out), at + rng.randint(1, 64))
        choice = rng.randrange(7)
        if choice == 0 and out:
            out[min(at, len(out) - 1)] ^= 1 << rng.randrange(8)
        elif choice == 1:
            out[at:at] = rng.choice(TOKENS)
        elif choice == 2:
            del out[at:end]
        elif choice == 3:
            out[at:at] = out[at:end] * rng.randint(2, 200)  # repetition: the time must stay linear
        elif choice == 4:
            donor = rng.choice(donors)
            start = rng.randint(0, len(donor))
            out[at:end] = donor[start:start + rng.randint(1, 512)]
        elif choice == 5:
            out[at:at] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
        else:
            out[at:end] = out[at:end].upper() if rng.random() < 0.5 else out[at:end].lower()
    return bytes(out[:MAX_SIZE])


def run(name: str, seconds: float, seed: int = 0, real: bool = False, sample: int = 40,
        generated: bool = False) -> Outcome:
    """Mutate ``sample`` of the target's seeds for ``seconds``; raise AssertionError naming the saved
    input on the first one that breaks the invariant. ``generated``: the XML targets also mutate the
    profiles eds2xml makes of corpus/ (:func:`fuzz_targets.generated_profiles`)."""
    target = targets.TARGETS[name]
    rng = random.Random(seed)
    paths = targets.seed_files(target, real)
    if generated and ".xml" in target.suffixes:
        paths += targets.generated_profiles(targets.REPO / "build" / "fuzz" / name / "generated")
    seeds = [p.read_bytes() for p in sorted(rng.sample(paths, min(sample, len(paths))))]
    timed = targets.Timed(target, targets.seconds_per_byte(target, seeds))
    start, executions = time.monotonic(), 0
    while time.monotonic() - start < seconds:
        data = mutate(rng.choice(seeds), rng, seeds)
        executions += 1
        try:
            timed(data)
        except Exception as error:  # noqa: BLE001 - any exception breaks the invariant; keep the input
            saved = save(name, data)
            raise AssertionError(f"{name} failed on {saved}: {type(error).__name__}: {error}") from error
    return Outcome(name, executions, time.monotonic() - start)


def save(name: str, data: bytes) -> Path:
    """Keep a failing input under build/fuzz/NAME/ (move it to tests/fuzz_regressions/NAME/ with the fix)."""
    directory = targets.REPO / "build" / "fuzz" / name
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / f"mutation-{hashlib.sha1(data).hexdigest()[:16]}"
    path.write_bytes(data)
    return path


def main(argv: list[str]) -> None:
    if len(argv) < 3 or argv[1] not in targets.TARGETS:
        sys.exit(f"usage: python fuzz/mutation.py {{{','.join(targets.TARGETS)}}} SECONDS [--seed N] [--real] "
                 "[--generated]")
    seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 0
    outcome = run(argv[1], float(argv[2]), seed, real="--real" in argv, generated="--generated" in argv)
    print(f"{outcome.target}: {outcome.executions} executions in {outcome.seconds:.0f} s, no failure")


if __name__ == "__main__":
    main(sys.argv)
