"""What the server asks before it reports a diagnostic: the settings of the document's project.

The seam for the configuration that ``edsconv lint`` will read (the pipelines
issue: ``[tool.edsconv]`` in pyproject.toml or ``edsconv.toml``, found by walking
up from the file, per workspace folder, and inline suppressions such as
``$ edsconv: ignore[EDS301]``). Until then every document gets the defaults:
every rule selected, none ignored, no suppression. :func:`settings_for` is the
one function the server calls, once per analysed document version.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from edsconv.diagnostics import Diagnostic, Selection


@dataclass(frozen=True, slots=True)
class Settings:
    """Rule selection as ``edsconv lint --select/--ignore`` takes it (code prefixes)."""

    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()

    def reports(self, diagnostic: Diagnostic) -> bool:
        return diagnostic.code in Selection.of(self.select, self.ignore)


def settings_for(path: str | None, workspace_folders: Sequence[str]) -> Settings:
    """The settings for the file at ``path`` (None for an unsaved document) in one of the
    ``workspace_folders`` (paths). The configuration issue fills this in; for now: the defaults."""
    return Settings()
