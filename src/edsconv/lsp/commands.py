"""The server's commands (``workspace/executeCommand``), each the editor's way to a command line job:

- ``edsconv.showDevice`` URI: the device as ``edsconv show`` prints it (the text, and the document
  ``show --format json`` prints), for the client to open beside the file;
- ``edsconv.convertToXml`` URI [FORCE]: the two profiles ``edsconv eds2xml`` writes, beside the EDS,
  refused as eds2xml refuses (an EDS that cannot be converted faithfully, existing files without force);
- ``edsconv.fixAll`` URI: every fix ``edsconv lint --fix`` makes, as edits the server asks the
  client to apply (``workspace/applyEdit``), so they join the editor's undo history.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from edsconv import describe
from edsconv.eds.source import encode, split_lines
from edsconv.fix import Edit, fix_source
from edsconv.lsp.actions import minimal_edits
from edsconv.lsp.analysis import Analysis
from edsconv.lsp.settings import Settings

SHOW_DEVICE = "edsconv.showDevice"
CONVERT_TO_XML = "edsconv.convertToXml"
FIX_ALL = "edsconv.fixAll"
COMMANDS = (SHOW_DEVICE, CONVERT_TO_XML, FIX_ALL)

#: Renders the show document as text; given by the command line layer, which owns the text layout.
ShowRenderer = Callable[[dict], str]


class CommandRefused(ValueError):
    """A command that cannot be carried out; the message says why, in the words of the command line."""


def show_device(analysis: Analysis, render: ShowRenderer | None) -> dict:
    """``{"text": ..., "document": ...}``: what ``edsconv show`` prints for the document's text."""
    document = describe.describe(analysis.device)
    return {"text": render(document) if render is not None else None, "document": document}


def convert_to_xml(analysis: Analysis, path: str | None, force: bool) -> list[str]:
    """Write STEM_device.xml and STEM_commnet.xml beside the EDS at ``path``; the paths written."""
    from edsconv.atomic import Refused, write_all_atomically
    from edsconv.xml.common import InvalidProfile
    from edsconv.xml.convert import NotConverted, eds_documents, header_for

    if path is None:
        raise CommandRefused("save the file first: the profiles are written beside it")
    eds_path = Path(path)
    try:
        outputs = eds_documents(analysis.eds, analysis.device, header_for(analysis.device, eds_path.stem, {}),
                                eds_path.stem)
        targets = [eds_path.parent / output.name for output in outputs]
        write_all_atomically([(t, o.data) for t, o in zip(targets, outputs, strict=True)], inputs=[eds_path],
                             force=force)
    except NotConverted as refused:
        raise CommandRefused("not converted: " + "; ".join(d.message for d in refused.diagnostics[:3])) from None
    except (InvalidProfile, Refused, OSError) as error:
        raise CommandRefused(str(error)) from None
    return [str(target) for target in targets]


def fix_all(analysis: Analysis, settings: Settings) -> list[Edit]:
    """The edits that make every safe fix, round after round as ``lint --fix`` does, as few lines as change."""
    from edsconv.lint import check

    def reported(eds):  # the diagnostics the editor shows for a text: the file's own settings
        return settings.kept(eds, check(eds, settings.rules))

    outcome = fix_source(encode(analysis.text, "utf-8"), analysis.eds.path, reported)
    return minimal_edits(analysis.lines, split_lines(outcome.data.decode("utf-8")), 1)
