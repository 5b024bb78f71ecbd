"""Coverage-guided fuzzing of one target with atheris (libFuzzer), seeded from corpus/ and the shared
real files, read in place.

    python fuzz/fuzz.py TARGET [--no-real] [libFuzzer options ...]

TARGET is parse_analyse, eds2xml, xml2eds or validate (fuzz/fuzz_targets.py). New inputs go to
build/fuzz/TARGET/corpus, crashes to build/fuzz/TARGET/ (crash-*, slow inputs as crash-* too:
the time bound raises). docs/fuzzing.md says how to run it for long and what to do with a crash.
"""

from __future__ import annotations

import sys

import atheris

with atheris.instrument_imports(include=["edsconv", "lark", "fuzz_targets"]):
    import importlib
    import pkgutil

    import fuzz_targets as targets

    import edsconv

    # edsconv imports some modules where they are needed: instrument them all now
    for module in pkgutil.walk_packages(edsconv.__path__, "edsconv."):
        if not module.name.startswith(("edsconv.lsp", "edsconv.cli", "edsconv.__main__")):
            importlib.import_module(module.name)


def main(argv: list[str]) -> None:
    name, *options = argv[1:] or ["--help"]
    if name not in targets.TARGETS:
        sys.exit(f"usage: python fuzz/fuzz.py {{{','.join(targets.TARGETS)}}} [--no-real] [libFuzzer options]")
    target = targets.TARGETS[name]
    real = "--no-real" not in options
    options = [option for option in options if option != "--no-real"]
    work = targets.REPO / "build" / "fuzz" / name
    (work / "corpus").mkdir(parents=True, exist_ok=True)
    seeds = targets.seed_files(target, real)
    if ".xml" in target.suffixes:
        seeds += targets.generated_profiles(work / "generated")
    seed_list = work / "seeds.txt"
    seed_list.write_text(",".join(str(p) for p in seeds))
    per_byte = targets.seconds_per_byte(target, [p.read_bytes() for p in seeds])
    print(f"{name}: {len(seeds)} seeds, {per_byte * 1e6:.2f} us per byte", file=sys.stderr)
    timed = targets.Timed(target, per_byte)
    atheris.Setup([argv[0], str(work / "corpus"), f"-seed_inputs=@{seed_list}", f"-artifact_prefix={work}/",
                   "-print_final_stats=1", "-report_slow_units=86400", *options], timed)
    atheris.Fuzz()


if __name__ == "__main__":
    main(sys.argv)
