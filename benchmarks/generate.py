"""Write the generated benchmark inputs: Params-heavy EDS files in the EZ-EDS style.

    python benchmarks/generate.py [--out DIR]

writes params-2mb.eds and params-50mb.eds to DIR (default: <tempdir>/edsconv-bench).
The output is deterministic; it is never committed.
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

DEFAULT_DIR = Path(tempfile.gettempdir()) / "edsconv-bench"
SIZES = {"params-2mb.eds": 2 * 1024 * 1024, "params-50mb.eds": 50 * 1024 * 1024}

HEADER = """\
$ EZ-EDS Version 3.23.1.20171205 Generated Electronic Data Sheet

[File]
        DescText = "Generated Params-heavy EDS for edsconv benchmarks";
        CreateDate = 11-03-2009;
        CreateTime = 13:15:23;
        ModDate = 02-06-2018;
        ModTime = 14:05:38;
        Revision = 2.3;

[Device]
        VendCode = 1;
        VendName = "Benchmark Vendor";
        ProdType = 12;
        ProdTypeStr = "Communications Adapter";
        ProdCode = 65001;
        MajRev = 2;
        MinRev = 3;
        ProdName = "Benchmark Device";
        Catalog = "BENCH-1";

[Device Classification]
        Class1 = EtherNetIP;

[Params]
"""

# (data type, size in bytes, minimum, maximum) cycled over the parameters.
TYPES = [("0xC1", 1, 0, 1), ("0xC2", 1, -128, 127), ("0xC3", 2, -32768, 32767),
         ("0xC6", 1, 0, 255), ("0xC7", 2, 0, 65535), ("0xC8", 4, 0, 4294967295), ("0xCA", 4, "-1.5e3", "1.5e3")]


def param(n: int) -> str:
    data_type, size, low, high = TYPES[n % len(TYPES)]
    return f"""\
        Param{n} =
                0,                      $ reserved, shall equal 0
                6,"20 04 24 {n % 256:02X} 30 03", $ Link Path Size, Link Path
                0x{n % 0x10000:04X},                 $ Descriptor
                {data_type},                   $ Data Type
                {size},                      $ Data Size in bytes
                "Parameter {n}",        $ name
                "ms",                   $ units
                "Help for parameter {n}", $ help string
                {low},{high},{n % 100},           $ min, max, default data values
                1,1,1,0,                $ mult, div, base, offset scaling
                ,,,,                    $ mult, div, base, offset links
                {n % 4};                       $ decimal places
"""


def generate(name: str, directory: Path = DEFAULT_DIR) -> Path:
    """Write the input ``name`` (a key of SIZES) to ``directory``: EZ-EDS Params until the size is reached."""
    path = directory / name
    directory.mkdir(parents=True, exist_ok=True)
    with path.open("w", encoding="ascii", newline="\n") as out:
        written = out.write(HEADER)
        n = 0
        while written < SIZES[name]:
            n += 1
            written += out.write(param(n))
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_DIR, help="output directory")
    directory = parser.parse_args().out
    for name in SIZES:
        path = generate(name, directory)
        print(f"{path}: {path.stat().st_size} bytes")


if __name__ == "__main__":
    main()
