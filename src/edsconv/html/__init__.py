"""``show --format html`` and ``diff --format html``: a device as one self-contained HTML page.

The page is made from the same :func:`~edsconv.describe.describe` document the text and JSON of
``show`` print, so all three say the same thing; the markup lives in Jinja2 templates
(``templates/``, autoescaped), the few computed parts (the geometry of the drawings, the links of
the lint findings, the marks of a comparison) in :mod:`edsconv.html.view` and
:mod:`edsconv.html.drawing`. Styles, the small script (sorting and filtering the parameters) and
the icon are inside the page: it opens from a file, needs no network, and its content reads with
JavaScript off.
"""

from __future__ import annotations

from collections.abc import Iterable
from functools import cache
from typing import TYPE_CHECKING

from edsconv.html import drawing, text, view

if TYPE_CHECKING:
    import jinja2
    import markupsafe

    from edsconv.diagnostics import Diagnostic
    from edsconv.eds.syntax import EdsFile


@cache
def environment() -> jinja2.Environment:
    """The templates, autoescaped; blocks trimmed so the page carries no blank lines of template logic."""
    import jinja2

    env = jinja2.Environment(loader=jinja2.PackageLoader("edsconv.html", "templates"), autoescape=True,
                             trim_blocks=True, lstrip_blocks=True, undefined=jinja2.StrictUndefined)
    env.filters.update(cell=text.cell, type_text=text.type_text, member_text=text.member_text,
                       endpoint_text=text.endpoint_text, path_text=text.path_text, reference_text=text.reference_text)
    env.globals.update(value_range=text.value_range, parameter_value=text.parameter_value,
                       bits_text=text.bits_text, mark=view.mark, style=_inline(env, "page.css"),
                       script=_inline(env, "page.js"))
    return env


def _inline(env: jinja2.Environment, name: str) -> markupsafe.Markup:
    """The style sheet or script ``name`` as the page holds it: without its comments and indentation,
    which every page would carry (a small device's page is mostly these)."""
    import re

    import markupsafe

    source = env.loader.get_source(env, name)[0] if env.loader else ""
    source = re.sub(r"/\*.*?\*/\n?", "", source, flags=re.S)  # CSS comments (the script has none of this form)
    lines = (line.strip() for line in source.splitlines())
    return markupsafe.Markup("\n".join(line for line in lines if line and not line.startswith("//")))


def show_page(document: dict, title: str, diagnostics: Iterable[Diagnostic] = (), eds: EdsFile | None = None,
              icon: bytes | None = None) -> str:
    """The page of one device: the ``show`` document, the lint verdict on ``eds`` and its icon."""
    device = view.device_view(document, "", {})
    return environment().get_template("show.html.j2").render(
        title=title, device=device, verdict=view.verdict(diagnostics, eds, device["anchors"]),
        icon=view.icon_uri(icon), rulers=drawing.rulers(device["maps"].values()))


def diff_page(old: dict, new: dict, changes: list[dict], old_title: str, new_title: str) -> str:
    """The review page of two devices side by side, each change marked on both sides."""
    old_marks, new_marks = view.marks(changes, "old"), view.marks(changes, "new")
    old_view, new_view = view.device_view(old, "a-", old_marks), view.device_view(new, "b-", new_marks)
    rows = view.change_rows(changes, old_view["anchors"], new_view["anchors"])
    return environment().get_template("diff.html.j2").render(
        old_title=old_title, new_title=new_title, old=old_view, new=new_view, changes=rows,
        rulers=drawing.rulers([*old_view["maps"].values(), *new_view["maps"].values()]))
