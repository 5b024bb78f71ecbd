"""Locate the data files (grammar, schemas, docs) shipped with edsconv.

In a wheel they are inside the package (see pyproject's force-include); in a
source checkout or editable install they stand at the top of the repository.
"""

from __future__ import annotations

from pathlib import Path

_PACKAGE_DIR = Path(__file__).resolve().parent
_REPO_DIR = _PACKAGE_DIR.parent.parent


def data_dir(name: str) -> Path:
    """Return the directory ``grammar``, ``schemas`` or ``docs``, wherever it was installed."""
    for candidate in (_PACKAGE_DIR / name, _REPO_DIR / name):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"edsconv data directory {name!r} is missing from the installation")
