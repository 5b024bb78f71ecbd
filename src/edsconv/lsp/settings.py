"""What the server asks before it reports a diagnostic: the settings of the document's project.

The same configuration ``edsconv lint`` reads (:mod:`edsconv.config`: ``[tool.edsconv]``
in pyproject.toml or ``edsconv.toml``, found by walking up from the file; for an
unsaved document, from its workspace folder), and the inline suppressions of the
document (:mod:`edsconv.suppress`: ``$ edsconv: ignore[EDS301]``). :func:`settings_for`
is the one function the server calls, once per analysed document version.
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from edsconv.config import ConfigError, FileRules, Resolver
from edsconv.diagnostics import Diagnostic, Severity
from edsconv.eds.syntax import EdsFile
from edsconv.suppress import Directives, apply_suppressions


@dataclass(frozen=True, slots=True)
class Settings:
    """The rules reported for one document, as ``edsconv lint`` reports them for the file."""

    rules: FileRules = FileRules()
    #: the configuration file in force (None: defaults)
    source: str | None = None
    #: why the configuration could not be read (then the defaults apply)
    error: str | None = None

    def reports(self, diagnostic: Diagnostic) -> bool:
        return self.rules.reports(diagnostic.code)

    def kept(self, eds: EdsFile, diagnostics: Iterable[Diagnostic], directives: Directives | None = None) \
            -> list[Diagnostic]:
        """The diagnostics to show: selected, not suppressed, warnings promoted when so configured (as copies:
        the analysis keeps its own). ``directives``: the file's suppression comments, when found already."""
        shown = apply_suppressions(eds, self.rules.kept(diagnostics), self.rules.reports, directives)
        if self.rules.warnings_as_errors:
            shown = [dataclasses.replace(d, severity=Severity.ERROR) if d.severity is Severity.WARNING else d
                     for d in shown]
        return shown


def settings_for(path: str | None, workspace_folders: Sequence[str]) -> Settings:
    """The settings for the file at ``path`` (None for an unsaved document) in one of the
    ``workspace_folders`` (paths): the configuration found walking up from the file, or from the
    first workspace folder for an unsaved document; the defaults when there is none or it is bad."""
    if path is None:
        folder = next((f for f in workspace_folders if f), None)
        if folder is None:
            return Settings()
        path = os.path.join(folder, "untitled.eds")
    try:
        settings = Resolver().settings_for(path)
    except ConfigError as error:
        return Settings(error=str(error))
    return Settings(settings.for_file(path), settings.source)
