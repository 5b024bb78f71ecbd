"""``edsconv show``: the describe() document, its text rendering, --section and exit codes."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv.cli import cli
from edsconv.cli.show import json_text, plain_text, render
from edsconv.describe import SECTIONS, describe
from edsconv.model.epath import decode_path
from edsconv.model.values import PathItem

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
SPEC = sorted((REPO / "corpus" / "spec").glob("*.eds"))
OWN = sorted((REPO / "corpus").rglob("*.eds"))
BROKEN = sorted((REPO / "corpus" / "broken").glob("*.eds"))


def run(*args: str):
    """The command in this process; ``return_value`` is its exit code."""
    return CliRunner().invoke(cli, list(args), standalone_mode=False, catch_exceptions=False)


def document(path: Path = EXAMPLE) -> dict:
    device, _ = edsconv.analyse(edsconv.load(path))
    return describe(device)


@pytest.fixture(scope="module")
def example() -> dict:
    return document()


def by_keyword(items: list[dict], keyword: str) -> dict:
    (found,) = [item for item in items if item["keyword"] == keyword]
    return found


def path_of(text: str) -> tuple[PathItem, ...]:
    return tuple(PathItem(byte=int(byte, 16)) for byte in text.split())


# --- the document ---------------------------------------------------------------------------------


def test_identity_and_file(example: dict):
    assert example["identity"]["vendor_code"] == 65535
    assert example["identity"]["product_name"] == "Example IO Adapter 8DI/8DO"
    assert (example["identity"]["major_revision"], example["identity"]["minor_revision"]) == (1, 2)
    assert example["file"]["revision"] == "1.1"
    assert example["file"]["create_date"] == "2026-11-22"
    assert example["classifications"] == [{"number": 1, "classification": "EtherNetIP", "subclassifications": []}]


def test_parameters_with_types_enums_flags_and_engineering_values(example: dict):
    rpi = by_keyword(example["parameters"], "Param1")
    assert rpi["data_type"] == {"name": "UDINT", "code": 0xC8, "written": 0xC8}
    assert (rpi["minimum"], rpi["maximum"], rpi["default"], rpi["units"]) == (2000, 1000000, 10000, "microseconds")
    assert "engineering" not in rpi  # no scaling fields

    param2 = by_keyword(example["parameters"], "Param2")
    assert param2["flags"] == ["Read only parameter"]
    assert param2["engineering"] == {"minimum": 0, "maximum": 255, "default": 3}
    assert param2["link_path"]["summary"] == "class 0x04 (Assembly), instance 0x96, attribute 0x03"

    param3 = by_keyword(example["parameters"], "Param3")
    assert [e["text"] for e in param3["enum"]] == ["Clear", "Hold last state", "Use fault value"]
    assert [e["value"] for e in param3["enum"]] == [0, 1, 2]
    assert param3["flags"] == ["Supports enumerated strings"]

    param4 = by_keyword(example["parameters"], "Param4")
    assert param4["data_type"]["name"] == "REAL"
    assert (param4["minimum"], param4["maximum"], param4["default"]) == (-40.0, 85.0, 70.0)


def test_engineering_values_apply_the_scaling_formula():
    # Figure C.9: Read is USINT 64..95 with offset -63, shown to the user as 1..32
    read = by_keyword(document(REPO / "corpus" / "spec" / "figure_C09.eds")["parameters"], "Param1")
    assert read["scaling"]["offset"] == -63
    assert read["engineering"] == {"minimum": 1, "maximum": 32, "default": 1}


def test_scaling_fields_that_are_all_zero_mean_no_scaling():
    # Figure C.8 writes 0,0,0,0 "scaling not used"
    for parameter in document(REPO / "corpus" / "spec" / "figure_C08.eds")["parameters"]:
        assert "engineering" not in parameter


def test_groups_resolve_their_members(example: dict):
    (configuration, diagnostics) = example["groups"]
    assert configuration["name"] == "Configuration"
    assert [(m["keyword"], m["name"]) for m in configuration["members"]] == [
        ("Param2", "Input Filter"), ("Param3", "Fault Action")]
    assert [m["keyword"] for m in diagnostics["members"]] == ["Param4"]


def test_assemblies_as_bit_layouts(example: dict):
    inputs = by_keyword(example["assemblies"], "Assem100")
    assert (inputs["name"], inputs["size"], inputs["total_bits"]) == ("Inputs", 2, 16)
    assert [(m["offset"], m["bits"]) for m in inputs["members"]] == [(0, 8), (8, 8)]
    assert inputs["members"][0]["member"]["kind"] == "parameter"
    assert inputs["members"][0]["member"]["keyword"] == "Param2"
    assert inputs["members"][1]["member"] == {"kind": "pad"}
    assert inputs["path"]["summary"] == "class 0x04 (Assembly), instance 0x64, attribute 0x03"
    configuration = by_keyword(example["assemblies"], "Assem151")
    assert [m["member"]["keyword"] for m in configuration["members"]] == ["Param2", "Param3"]
    assert example["assembly_revision"] == 2


def test_member_sizes_come_from_the_referenced_entry_when_empty():
    # Figure C.15: Assem1 lists ProxyAssem1/2 without sizes; they take their members from the module
    assem1 = by_keyword(document(REPO / "corpus" / "spec" / "figure_C15.eds")["assemblies"], "Assem1")
    assert [m["member"]["keyword"] for m in assem1["members"]] == ["ProxyAssem1", "ProxyAssem2"]
    assert assem1["total_bits"] is None


def test_connection_trigger_and_transport_in_words(example: dict):
    connection = by_keyword(example["connections"], "Connection1")
    assert connection["name"] == "Exclusive Owner"
    trigger = connection["trigger_transport"]
    assert trigger["value"] == "0x04010002"
    assert trigger["classes"] == [1]
    assert trigger["triggers"] == ["cyclic"]
    assert trigger["transport"] == ["exclusive-owner"]
    assert trigger["role"] == "client"
    assert trigger["reserved_bits"] is None
    listen = by_keyword(example["connections"], "Connection2")["trigger_transport"]
    assert listen["transport"] == ["listen-only"]


def test_connection_parameters_per_direction(example: dict):
    parameters = by_keyword(example["connections"], "Connection1")["parameters"]
    assert parameters["value"] == "0x44640405"
    o_to_t, t_to_o = parameters["O=>T"], parameters["T=>O"]
    assert (o_to_t["fixed_size"], o_to_t["variable_size"]) == (True, False)
    assert o_to_t["real_time_format"] == "32-bit run/idle header"
    assert o_to_t["connection_types"] == ["POINT2POINT"]
    assert o_to_t["priorities"] == ["SCHEDULED"]
    assert t_to_o["real_time_format"] == "pure data, modeless"
    assert t_to_o["connection_types"] == ["MULTICAST", "POINT2POINT"]
    assert t_to_o["priorities"] == ["SCHEDULED"]


def test_rpi_size_and_format_are_resolved(example: dict):
    connection = by_keyword(example["connections"], "Connection1")
    o_to_t = connection["O=>T"]
    assert o_to_t["rpi"]["written"] == "Param1"
    assert o_to_t["rpi"]["value"] == 10000
    assert (o_to_t["rpi"]["reference"]["minimum"], o_to_t["rpi"]["reference"]["maximum"]) == (2000, 1000000)
    assert o_to_t["size"] == {"written": 2, "value": 2}
    assert o_to_t["format"]["keyword"] == "Assem150"
    assert (o_to_t["format"]["kind"], o_to_t["format"]["name"], o_to_t["format"]["size"]) == (
        "assembly", "Outputs", 2)
    assert connection["T=>O"]["format"]["keyword"] == "Assem100"
    assert connection["config1"] is None
    assert connection["config2"]["format"]["keyword"] == "Assem151"
    assert "rpi" not in connection["config2"]


def test_connection_path_decoded(example: dict):
    path = by_keyword(example["connections"], "Connection1")["path"]
    assert path["text"] == "20 04 24 97 2C 96 2C 64"
    assert [(s["type"], s["value"]) for s in path["segments"]] == [
        ("class", 0x04), ("instance", 0x97), ("connection point", 0x96), ("connection point", 0x64)]
    assert [s["bytes"] for s in path["segments"]] == ["20 04", "24 97", "2C 96", "2C 64"]
    assert path["segments"][0]["text"] == "class 0x04 (Assembly)"


def test_path_substitutions_and_slot_keywords():
    connection = document(REPO / "corpus" / "spec" / "figure_C09.eds")["connections"][0]
    points = [s for s in connection["path"]["segments"] if s["type"] == "connection point"]
    assert [s["parameter"] for s in points] == ["Param2", "Param1"]
    assert "'Write', default 160" in points[0]["text"]
    proxy = document(REPO / "corpus" / "spec" / "figure_C15.eds")["connections"][0]
    port = proxy["path"]["segments"][0]
    assert (port["type"], port["value"], port["link_address"]) == ("port", 1, "SLOT_MINUS_ONE")


@pytest.mark.parametrize(("text", "summary"), [
    ("21 00 04 00 25 00 65 00 31 00 03 00", "class 0x0004 (Assembly), instance 0x0065, attribute 0x0003"),
    # packed 16-bit values without the pad byte, as real files write them
    ("21 04 00 25 65 00 30 03", "class 0x0004 (Assembly), instance 0x0065, attribute 0x03"),
    ("20 F5 24 01", "class 0xF5 (TCP/IP Interface), instance 0x01"),
    ("01 00 20 02 24 01", "port 1, link address 0x00, class 0x02 (Message Router), instance 0x01"),
    ("12 0B 31 39 32 2E 31 36 38 2E 31 2E 31 00", "port 2, link address 192.168.1.1"),
    ("34 04 FF FF 0C 00 E9 03 81 02",
     "electronic key: vendor 65535, device type 12, product code 1001, revision 1.2 (compatible)"),
    ("91 03 61 62 63 00", "ANSI extended symbol 'abc'"),
    ("20 04 24", "class 0x04 (Assembly), instance segment: the value is missing"),
    ("E0 01", "0xE0 is not a segment type edsconv decodes"),
])
def test_decode_path(text: str, summary: str):
    assert decode_path(path_of(text))["summary"] == summary


def test_ports_modular_and_other_sections(example: dict):
    (port,) = example["ports"]
    assert (port["type"], port["name"], port["port_number"]) == ("TCP", "EtherNet/IP Port", 2)
    assert port["object_path"]["segments"][0]["text"] == "class 0xF5 (TCP/IP Interface)"
    assert example["modular"] is None
    chassis = document(REPO / "corpus" / "spec" / "figure_C11.eds")["modular"]
    assert (chassis["role"], chassis["define_slots_in_rack"]) == ("chassis", 5)
    module = document(REPO / "corpus" / "spec" / "figure_C13.eds")["modular"]
    assert module["role"] == "module"
    assert [r["legal_slots"] for r in module["racks"]] == [[1, 2, 3, 4], [1, 2, 3, 4, 5, 6, 7]]
    other = document(REPO / "corpus" / "spec" / "stringi_C4135.eds")["other_sections"]
    assert [s["name"] for s in other] == ["Example"]
    assert other[0]["entries"] >= 1


# --- the command ----------------------------------------------------------------------------------


def test_json_output_is_the_document(example: dict):
    result = run("show", "--format", "json", str(EXAMPLE))
    assert result.return_value == 0
    assert json.loads(result.stdout) == example


def test_text_output_spells_everything_out():
    result = run("show", str(EXAMPLE))
    assert result.return_value == 0
    out = result.stdout
    for words in ("Example IO Adapter 8DI/8DO", "Input Filter", "USINT 0xC6", "Hold last state",
                  "Read only parameter", "0-7", "8-15", "(pad)", "Exclusive Owner", "class 1: duplicate detect",
                  "cyclic", "exclusive-owner", "32-bit run/idle header", "POINT2POINT", "SCHEDULED",
                  "Assem150 'Outputs', 2 bytes", "default 10000 microseconds",
                  "class 0x04 (Assembly), instance 0x97, connection point 0x96, connection point 0x64",
                  "EtherNet/IP Port"):
        assert words in out, words
    assert "\x1b[" not in out  # no colour codes when not a terminal
    assert all(line == line.rstrip() for line in out.splitlines())


def test_text_keeps_brackets_literal():
    # rich markup would swallow "[Param2]"
    result = run("show", "--section", "connections", str(REPO / "corpus" / "spec" / "figure_C09.eds"))
    assert "2C [Param2] 2C [Param1]" in result.stdout


def test_section_filter():
    result = run("show", "--format", "json", "--section", "connections", "--section", "ports", str(EXAMPLE))
    assert set(json.loads(result.stdout)) == {"connections", "ports"}
    result = run("show", "--format", "json", "--section", "identity,assemblies", str(EXAMPLE))
    assert set(json.loads(result.stdout)) == {*SECTIONS["identity"], *SECTIONS["assemblies"]}
    text = run("show", "--section", "parameters", str(EXAMPLE)).stdout
    assert "Fault Action" in text
    assert "Exclusive Owner" not in text and "Assem100" not in text and "EtherNet/IP Port" not in text


def test_diagnostics_are_counted_on_stderr_and_do_not_fail(tmp_path: Path):
    path = tmp_path / "missing_semicolon.eds"
    path.write_bytes(EXAMPLE.read_bytes().replace(b'Catalog = "EX-8DIO";', b'Catalog = "EX-8DIO"'))
    result = run("show", str(path))
    assert result.return_value == 0
    counts = re.fullmatch(rf"{re.escape(str(path))}: (\d+) errors?, (\d+) warnings? \(see 'edsconv lint .*'\)",
                          result.stderr.strip())
    assert counts and int(counts[1]) >= 1, result.stderr
    assert "Example IO Adapter" in result.stdout
    assert run("show", str(EXAMPLE)).stderr == ""


def test_exit_codes_as_a_process(tmp_path: Path):
    def edsconv_(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, "-m", "edsconv", *args], capture_output=True, text=True,
                              timeout=120, cwd=tmp_path)

    assert edsconv_("show", str(EXAMPLE)).returncode == 0
    missing = edsconv_("show", "missing.eds")
    assert missing.returncode == 2
    assert "missing.eds" in missing.stderr
    assert edsconv_("show", "--section", "nope", str(EXAMPLE)).returncode == 2
    assert edsconv_("show", "--format", "xml", str(EXAMPLE)).returncode == 2


def test_rich_is_imported_only_by_the_text_output():
    code = ("import sys, edsconv.describe, edsconv.cli.show, edsconv.cli; "
            "assert 'rich' not in sys.modules, 'rich imported'")
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, timeout=60).returncode == 0


# --- every file -----------------------------------------------------------------------------------


@pytest.mark.parametrize("path", SPEC + BROKEN, ids=lambda p: p.name)
def test_every_spec_figure_describes_and_renders(path: Path):
    json.dumps(document(path), allow_nan=False)
    result = run("show", str(path))
    assert result.return_value == 0


@needs_real_corpus
def test_real_corpus_describes_and_renders():
    from rich.console import Console

    for path in REAL_EDS:
        described = document(path)
        json.dumps(described, allow_nan=False)
        if path.stat().st_size > 40_000:
            continue  # rich lays out large files slowly (seconds); the small ones cover the renderer
        console = Console(markup=False, highlight=False, width=120, color_system=None)
        with console.capture() as capture:
            render(described, console)
        assert described["identity"]["product_name"] is None or str(
            described["identity"]["product_name"]).strip()[:10] in capture.get(), path.name


def _words(text: str) -> list[str]:
    """The words of a text, its rules (lines of '─', as long as the table is wide) left out."""
    return [word for word in text.split() if set(word) != {"\u2500"}]


def _rich_text(described: dict) -> str:
    from rich.console import Console

    console = Console(markup=False, highlight=False, width=3000, color_system=None)  # wide: rich wraps nothing
    with console.capture() as capture:
        render(described, console)
    return capture.get()


@pytest.mark.parametrize("path", OWN + [p for p in REAL_EDS if p.stat().st_size <= 40_000],
                         ids=lambda p: p.name)
def test_piped_text_says_what_the_terminal_tables_say(path: Path):
    described = document(path)
    plain = plain_text(described)
    assert _words(plain) == _words(_rich_text(described))
    assert all(line == line.rstrip() for line in plain.splitlines())


def test_piped_text_lays_out_columns_and_rows_of_several_lines(example: dict):
    lines = plain_text(example, ("groups",)).splitlines()
    assert lines[:6] == ["Groups",
                         "Group   Name            Members",
                         "\u2500" * 48,
                         "1       Configuration   Param2 Input Filter",
                         "                        Param3 Fault Action",
                         "2       Diagnostics     Param4 Temperature Limit"]


@needs_real_corpus
def test_real_corpus_renders_as_piped_text():
    for path in REAL_EDS:
        described = document(path)
        name = described["identity"]["product_name"]
        assert name is None or str(name).strip()[:10] in plain_text(described), path.name


# --- JSON as the standard library writes it -------------------------------------------------------

json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats() | st.text(),
    lambda inner: st.lists(inner, max_size=4) | st.tuples(inner, inner)
    | st.dictionaries(st.text(max_size=5) | st.integers(), inner, max_size=4),
    max_leaves=20)


@settings(max_examples=300, deadline=None)
@given(json_values)
def test_json_text_is_what_the_standard_library_writes(value):
    assert json_text(value) == json.dumps(value, indent=2, ensure_ascii=False)


@pytest.mark.parametrize("path", OWN + REAL_EDS, ids=lambda p: p.name)
def test_show_json_of_every_file_is_the_standard_librarys(path: Path):
    described = document(path)
    assert json_text(described) == json.dumps(described, indent=2, ensure_ascii=False)


def test_show_marks_a_default_without_reading_and_an_open_range(tmp_path: Path) -> None:
    """Issue 18 item 32: a BOOL default of 255 was a blank, and ``1000 ..`` left its open end unexplained."""
    text = EXAMPLE.read_text().replace("0xC8,                   $ Data Type: UDINT", "0xC1, $ BOOL", 1)
    text = text.replace("4,                      $ Data Size in bytes", "1,", 1)
    text = text.replace("2000,1000000,10000,     $ min", "0,,255, $ min", 1)
    path = tmp_path / "bool.eds"
    path.write_text(text)
    doc = document(path)
    (param1,) = [p for p in doc["parameters"] if p["keyword"] == "Param1"]
    assert param1["default"] is None and param1["invalid"] == {"default": "255"}
    row = next(line for line in plain_text(doc, ("parameters",)).splitlines() if line.startswith("Param1 "))
    assert "0 .. (no max)" in row and "255 (invalid)" in row
    assert "invalid" not in next(p for p in document()["parameters"] if p["keyword"] == "Param1")
