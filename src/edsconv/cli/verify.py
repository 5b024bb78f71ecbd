"""``edsconv verify``: check an EDS against the running EtherNet/IP device it describes."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from edsconv.cli.common import CannotRun, counts_line, documentation, exit_status, reading
from edsconv.report import FORMATTERS

READ_ONLY = ("verify: read-only: List Identity and Get_Attribute_Single only; nothing is written to the device")
CONNECTING = ("verify: --connect: a Forward Open per ConnectionN, each closed again at once (Forward Close); "
              "no parameter is written")


@click.command("verify", epilog=documentation("verify.md"))
@click.argument("path", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--device", "device", required=True, metavar="HOST[:PORT]",
              help="The device's address; the port defaults to 44818 (EtherNet/IP explicit messaging).")
@click.option("--connect", is_flag=True,
              help="Also open each ConnectionN of the EDS with its own RPIs, sizes, transport and trigger, and "
              "close it again at once; report the connections the device refuses.")
@click.option("--strict", is_flag=True,
              help="Also ask the device for the object classes edsconv knows and report those the EDS does not "
              "declare.")
@click.option("--timeout", type=click.FloatRange(min=0.1, max=60), default=2.0, show_default=True,
              help="Seconds to wait for each answer of the device (and for the connection to it).")
@click.option("--format", "output_format", type=click.Choice(list(FORMATTERS)), default="text", show_default=True,
              help="text, json (lint's shape), sarif (2.1.0) or github (workflow annotations).")
def verify_command(path: Path, device: str, connect: bool, strict: bool, timeout: float, output_format: str) -> int:
    """Compare the EDS at PATH with the device at HOST[:PORT]: its identity, the object classes
    the EDS declares, the sizes of the assembly instances its connections name and the values at
    its parameters' paths (and, with --connect, whether the device accepts each connection).

    Needs the device extra: pip install 'edsconv[device]'. Exit status: 0 the device matches, 1 it
    differs, 2 could not run (the file, or a device that is unreachable, refuses the connection,
    does not answer in time or does not speak EtherNet/IP).
    """
    from edsconv.verify import Target, verify
    from edsconv.verify.client import DeviceError

    try:
        target = Target.parse(device, timeout)
    except ValueError as error:
        raise click.BadParameter(str(error), param_hint="'--device'") from error
    try:
        with reading(path):
            report = verify(path, target, connect=connect, strict=strict)
    except DeviceError as error:
        raise CannotRun(str(error)) from error
    sys.stdout.write(FORMATTERS[output_format]([report]))
    sys.stdout.flush()
    if output_format == "text":
        click.echo(CONNECTING if connect else READ_ONLY, err=True)
        click.echo(counts_line(f"{path} against {target.host}:{target.port}", report.diagnostics), err=True)
    return exit_status(report.diagnostics)
