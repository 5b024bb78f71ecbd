"""``edsconv eds2xml`` and ``edsconv xml2eds``: EDS <-> ISO 15745-4 XML profiles.

Every document is validated before anything is written, and files are written atomically:
an invalid document is an internal error, never a file on disk.
"""

from __future__ import annotations

import datetime
import sys
from pathlib import Path
from typing import Any

import click

from edsconv.atomic import write_all_atomically, write_atomically
from edsconv.cli.common import (
    EXIT_FINDINGS,
    CannotRun,
    documentation,
    echo_diagnostics,
    exit_status,
    read_eds,
    reading,
    writing,
)
from edsconv.diagnostics import Severity
from edsconv.eds.syntax import EdsFile
from edsconv.model import Device
from edsconv.xml.common import Header, InvalidProfile
from edsconv.xml.convert import (
    WRAPPER_REFERENCES,
    NotConverted,
    Output,
    device_from_profiles,
    eds_documents,
    eds_text,
    header_for,
)


@click.command("eds2xml", epilog=documentation("mapping.md"))
@click.argument("eds_file", type=click.Path(dir_okay=False, path_type=Path))
@click.option("-o", "--output-dir", type=click.Path(file_okay=False, path_type=Path), default=Path("."),
              show_default=True, help="Directory for the profiles.")
@click.option("--wrapper", is_flag=True, help="Write the EDS wrapper profiles (C.2.2, C.3.2) instead.")
@click.option("--reference", type=click.Choice(sorted(WRAPPER_REFERENCES)), default="fileinfo", show_default=True,
              help="What a wrapper's ExternalProfileHandle names (Table C.2).")
@click.option("--force", is_flag=True, help="Overwrite existing files.")
@click.option("--strict", is_flag=True,
              help="Refuse an EDS with any error of reading (XML103), instead of keeping unreadable text as written.")
@click.option("--profile-id", "identification", help="ProfileIdentification (default: VendCode-ProdType-ProdCode).")
@click.option("--profile-revision", "revision", help="ProfileRevision (default: [File] Revision).")
@click.option("--profile-name", "name", help="ProfileName (default: [Device] ProdName).")
@click.option("--profile-source", "source", help="ProfileSource (default: [Device] VendName).")
@click.option("--profile-date", "date", type=click.DateTime(["%Y-%m-%d"]),
              help="ProfileDate YYYY-MM-DD (default: [File] ModDate, else CreateDate).")
def eds2xml_command(eds_file: Path, output_dir: Path, wrapper: bool, reference: str, force: bool, strict: bool,
                    **overrides: Any) -> int:
    """Convert an EDS into ISO 15745-4 XML profiles (device + communication network).

    \b
    Writes, in the output directory (STEM: EDS_FILE's name without its extension):
      STEM_device.xml and STEM_commnet.xml
      with --wrapper: STEM_device_wrapper.xml and STEM_commnet_wrapper.xml
    Both files or neither: nothing is written when one cannot be.

    A value that cannot be read (a date 13-11-2008, a BOOL 255, a stray word) is
    kept with its exact spelling in an edsconv:Unreadable of the device profile and
    reported (exit 1); xml2eds writes it back. An EDS whose [Device] gives no
    readable VendCode, ProdType, ProdCode, MajRev or MinRev, or with text the
    profiles cannot keep, is not converted (XML103); --strict refuses any error
    of reading.

    \b
    Exit status:
      0  converted, no errors
      1  converted but the checks found errors, or not converted (XML103)
      2  could not run: unreadable input, a file that cannot be written,
         existing files without --force, a bad option
    """
    from edsconv import analyse

    eds = read_eds(eds_file)
    device, diagnostics = analyse(eds)
    echo_diagnostics((d for d in diagnostics if d.severity is Severity.ERROR), err=True)
    if isinstance(overrides["date"], datetime.datetime):
        overrides["date"] = overrides["date"].date()
    header = header_for(device, eds_file.stem, overrides)
    try:
        outputs = _documents(eds, eds_file, device, header, strict,
                             WRAPPER_REFERENCES[reference] if wrapper else None)
    except NotConverted as refused:
        echo_diagnostics(refused.diagnostics, err=True)
        return EXIT_FINDINGS
    for target in _write_all(output_dir, outputs, force, eds_file):
        click.echo(str(target))
    return exit_status(diagnostics)


def _documents(eds: EdsFile, eds_file: Path, device: Device, header: Header, strict: bool,
               wrapper_reference: str | None) -> list[Output]:
    """The profiles (or, with a wrapper reference, the wrapper profiles) of ``device``, validated."""
    try:
        return eds_documents(eds, device, header, eds_file.stem, strict=strict, wrapper_reference=wrapper_reference)
    except InvalidProfile as error:
        raise CannotRun(f"{eds_file}: internal error, nothing written: {error}") from error


def _write_all(output_dir: Path, outputs: list[Output], force: bool, eds_file: Path) -> list[Path]:
    """Write every document or none (none when one exists and ``force`` is not given)."""
    targets = [output_dir / output.name for output in outputs]
    with writing(output_dir):  # an error names the file it is about
        write_all_atomically([(target, output.data) for target, output in zip(targets, outputs, strict=True)],
                             inputs=[eds_file], force=force)
    return targets


@click.command("xml2eds", epilog=documentation("mapping.md"))
@click.argument("profiles", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option("-o", "--output", type=click.Path(dir_okay=False, path_type=Path),
              help="EDS file to write (default: standard output).")
@click.option("--force", is_flag=True, help="Overwrite an existing output file.")
def xml2eds_command(profiles: tuple[Path, ...], output: Path | None, force: bool) -> int:
    """Convert ISO 15745-4 XML profiles (DEVICE.xml [COMMNET.xml]) into an EDS.

    \b
    The network profile must be the device's own: the same ProfileIdentification
    (without -DEV / -COMM) and ProfileDate (XML008); a network profile alone
    describes no device (XML009). A wrapper profile names the EDS next to it.

    \b
    Exit status:
      0  converted, no errors
      1  not converted: an invalid profile, profiles of two devices (XML008),
         no device profile (XML009), a wrapper without its EDS (XML101)
      2  could not run: a missing file, more than two profiles, a file that
         cannot be written, an existing output without --force
    """
    if len(profiles) > 2:
        raise click.UsageError(f"xml2eds takes a device profile and at most its network profile; "
                               f"{len(profiles)} files were given")
    missing = [str(p) for p in profiles if not p.is_file()]
    if missing:
        raise CannotRun(f"cannot read: {', '.join(missing)}")
    with reading():
        device, diagnostics = device_from_profiles(list(profiles))
    echo_diagnostics(diagnostics, err=True)
    if device is None:
        return EXIT_FINDINGS
    try:
        text = eds_text(device, "\r\n" if output else "\n", str(profiles[0]))
    except NotConverted as refused:
        echo_diagnostics(refused.diagnostics, err=True)
        return EXIT_FINDINGS
    if output is None:
        sys.stdout.write(text)
    else:
        with writing(output):
            write_atomically(output, text.encode("utf-8"), inputs=profiles, force=force)
        click.echo(str(output))
    return exit_status(diagnostics)
