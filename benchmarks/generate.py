"""Write the generated benchmark inputs, in two file shapes.

    python benchmarks/generate.py [--out DIR]

EZ-EDS shape (``params-*.eds``): [Params] entries of 12 lines, a comment on every
line, as EZ-EDS writes them. Dense shape (``dense-*.eds``): one short entry per
line and no comment, as generators and hand editors write them: ``dense-params``
holds only ``ParamN = 0,,,0x0000,0xC8,4,"P1","","",0,100,1,,,,,,,,,;`` lines (the
file of issue 13), ``dense-mixed`` parameters, assemblies that use them and
connections that use both, so that the semantic model, the checks and ``show``
have cross-references to resolve. Vendor shape (``vendor-sections-*.eds``): the
header, then only empty vendor-specific sections ``[65535_S1]`` ``[65535_S2]`` ...,
the file of issue 18 item 9 (the placement check was quadratic in them). Every file goes to DIR (default:
<tempdir>/edsconv-bench); the output is deterministic and never committed.
"""

from __future__ import annotations

import argparse
import itertools
import tempfile
from collections.abc import Iterator
from pathlib import Path

DEFAULT_DIR = Path(tempfile.gettempdir()) / "edsconv-bench"
MIB = 1024 * 1024

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


def dense_param(n: int) -> str:
    return f'        Param{n} = 0,,,0x0000,0xC8,4,"P1","","",0,100,1,,,,,,,,,;\n'


def dense_assembly(n: int, params: int) -> str:
    """Four of the ``params`` parameters, of 4 bytes each, by reference."""
    members = ",".join(f"32,Param{(4 * n + k) % params + 1}" for k in range(4))
    return f'        Assem{n} = "Assembly {n}","20 04 24 {n % 256:02X} 30 03",16,0x0000,,,{members};\n'


def dense_connection(n: int, assemblies: int) -> str:
    """An exclusive owner: parameter RPIs, three of the ``assemblies`` for both directions and configuration."""
    output, data_in, config = ((3 * n + k) % assemblies + 1 for k in range(3))
    return (f"        Connection{n} = 0x04010002,0x44640405,Param1,16,Assem{output},Param1,16,Assem{data_in},,,"
            f'16,Assem{config},"Connection {n}","","20 04 24 {n % 256:02X} 2C 96 2C 64";\n')


def dense_mixed(scale: int = 1) -> Iterator[str]:
    """[Params] with 20,000 entries, [Assembly] with 10,000, [Connection Manager] with 6,000, divided by ``scale``."""
    yield "[Params]\n"
    yield from (dense_param(n) for n in range(1, 20000 // scale + 1))
    yield "\n[Assembly]\n"
    yield from (dense_assembly(n, 20000 // scale) for n in range(1, 10000 // scale + 1))
    yield "\n[Connection Manager]\n"
    yield from (dense_connection(n, 10000 // scale) for n in range(1, 6000 // scale + 1))


def vendor_section(n: int) -> str:
    return f"[65535_S{n}]\n"


def repeated(entry, first: str = "[Params]\n") -> Iterator[str]:
    """``first``, then ``entry(1)``, ``entry(2)`` ... for ever: the caller stops at its size."""
    yield first
    yield from map(entry, itertools.count(1))


#: name -> (the text after the header, in pieces; how much of it: bytes for the EZ-EDS shape, entries for the
#: dense parameters and the vendor sections, None for all)
SHAPES: dict[str, tuple] = {
    "params-2mb.eds": (lambda: repeated(param), 2 * MIB),
    "params-0.5mb.eds": (lambda: repeated(param), MIB // 2),
    "params-50mb.eds": (lambda: repeated(param), 50 * MIB),
    "dense-params-40k.eds": (lambda: repeated(dense_param), 40000),
    "dense-params-10k.eds": (lambda: repeated(dense_param), 10000),
    "dense-mixed-1.7mb.eds": (lambda: dense_mixed(2), None),
    "dense-mixed-0.4mb.eds": (lambda: dense_mixed(8), None),
    "dense-mixed-3mb.eds": (lambda: dense_mixed(1), None),
    "vendor-sections-200k.eds": (lambda: repeated(vendor_section, first=""), 200000),
    "vendor-sections-20k.eds": (lambda: repeated(vendor_section, first=""), 20000),
}
#: the shapes whose size counts entries (or sections), not bytes
COUNTED = ("dense", "vendor")


def generate(name: str, directory: Path = DEFAULT_DIR) -> Path:
    """Write the input ``name`` (a key of SHAPES) to ``directory``."""
    path = directory / name
    directory.mkdir(parents=True, exist_ok=True)
    body, size = SHAPES[name]
    temporary = path.with_suffix(".tmp")
    with temporary.open("w", encoding="ascii", newline="\n") as out:
        written = out.write(HEADER)
        for count, text in enumerate(body()):
            if size is not None and (count > size if name.startswith(COUNTED) else written >= size):
                break
            written += out.write(text)
    temporary.replace(path)
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_DIR, help="output directory")
    directory = parser.parse_args().out
    for name in SHAPES:
        path = generate(name, directory)
        print(f"{path}: {path.stat().st_size} bytes")


if __name__ == "__main__":
    main()
