"""The C.4.1.5.3 merge: corpus/modular's adapter and modules, and edsconv merge."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from tests.conftest import REPO

import edsconv
from edsconv.cli import cli
from edsconv.merge import matching_racks, merge, rack_keys

MODULAR = REPO / "corpus" / "modular"
ADAPTER = MODULAR / "adapter.eds"
MODULE = MODULAR / "module.eds"
OTHER = MODULAR / "module_other_chassis.eds"

ADAPTER_MODULAR = """[Modular]
Width = 1;
Rack1 = 65535, 101, 1, 1, 1,,,, 0;
"""
MODULE_MODULAR = """[Modular]
Width = 1;
Rack3 = 0xFFFF, 101, 1, 1, 1,,,, 1, 2;
"""


def load(path: Path) -> edsconv.EdsFile:
    eds = edsconv.load(path)
    assert not eds.has_errors, [d.format() for d in eds.diagnostics]
    return eds


def raws(entry) -> list[str | None]:
    return [item.raw for item in entry.fields]


@pytest.fixture(scope="module")
def merged():
    result = merge(load(ADAPTER), [load(MODULE)])
    assert result.diagnostics == [], [d.format() for d in result.diagnostics]
    (module_merge,) = result.merges
    return {entry.keyword: entry for section in module_merge.sections for entry in section.entries}


def codes(result) -> list[str]:
    return [d.code for d in result.diagnostics]


def test_racks_match_by_electronic_key():
    adapter, module = load(ADAPTER), load(MODULE)
    assert rack_keys(adapter) == {"Rack1": (65535, 101, 1, 1, 1), "Rack2": (65535, 101, 2, 1, 1)}
    assert matching_racks(adapter, module) == [("Rack1", "Rack1"), ("Rack2", "Rack2")]
    assert matching_racks(adapter, load(OTHER)) == []


def test_rack_numbers_and_spelling_do_not_matter():
    adapter, module = edsconv.parse(ADAPTER_MODULAR), edsconv.parse(MODULE_MODULAR)
    assert matching_racks(adapter, module) == [("Rack1", "Rack3")]


def test_racks_do_not_match_by_minor_revision():
    # C.4.1.4.3: changes in minor revisions shall not be used to match a device with an EDS
    adapter = edsconv.parse(ADAPTER_MODULAR)
    assert matching_racks(adapter, edsconv.parse(MODULE_MODULAR.replace("1, 1,,,,", "1, 7,,,,"))) == [
        ("Rack1", "Rack3")]
    assert matching_racks(adapter, edsconv.parse(MODULE_MODULAR.replace("1, 1,,,,", "2, 1,,,,"))) == []


def test_output_sections_and_keywords(merged):
    assert list(merged) == ["Param1", "Enum1", "Param2", "Enum2", "Assem1", "Assem2", "Connection1"]
    result = merge(load(ADAPTER), [load(MODULE)])
    assert [s.name for s in result.merges[0].sections] == ["Params", "Assembly", "Connection Manager"]


def test_param_module_fields_come_from_the_proxied_entry_plus_the_size_adder(merged):
    param = raws(merged["Param1"])
    assert len(param) == 21
    # ProxyParam1's own fields, spelled as written
    assert param[:9] == ["0", None, None, "0x0000", "2", "2", '"input size"', '""', '""']
    # Module, Module, Module -> ProxiedParam1's 0, 2, 2, plus ProxyParamSizeAdder1 = 4, 4, 4
    assert param[9:12] == ["4", "6", "6"]
    assert param[12:] == ["0", "0", "0", "0", None, None, None, None, "0"]


def test_param_without_size_adder_takes_the_proxied_value_as_is(merged):
    param = raws(merged["Param2"])
    assert param[3:5] == ["0x0002", "0xC6"]
    assert param[9:12] == ["0", "2", "1"]  # min, max from ProxyParam2; default Module -> ProxiedParam2's 1


def test_enums_follow_their_params(merged):
    # Param1: only the module has an enumeration; Param2: the adapter's wins
    assert raws(merged["Enum1"]) == ["0", '"no data"', "2", '"two channels"']
    assert raws(merged["Enum2"]) == ["0", '"hold"', "1", '"clear"', "2", '"fault value"']


def test_module_member_list_is_expanded(merged):
    assert raws(merged["Assem1"]) == ['"real time input format"', '"20 7D 24 SLOT 30 0A"', None, None, None, None,
                                      "16", None, "16", None]
    assert raws(merged["Assem2"]) == ['"real time status format"', '"20 7D 24 SLOT 30 0B"', None, None, None, None,
                                      "16", None]


def test_connection_module_field_and_proxy_fields(merged):
    connection = raws(merged["Connection1"])
    assert connection[:4] == ["0x04010002", "0x44244401", "2", "0"]  # field 4 Module -> ProxiedConnect1's 0
    # field 7: ProxiedConnect1 documents "" there, but the ProxyConnect's value is used
    assert connection[6:8] == ["ProxyParam1", "Assem1"]
    assert connection[12:] == ['"Listen Only"', '""', '"01 SLOT_MINUS_ONE 20 04 24 03 2C 04 2C 02"']


def test_leading_comments_name_the_sources(merged):
    comment = merged["Param1"].leading_comments[0].text
    assert "ProxyParam1" in comment and "ProxiedParam1" in comment


def test_text_reads_back_as_the_same_entries(merged):
    text = merge(load(ADAPTER), [load(MODULE)]).text()
    back = edsconv.parse(text)
    assert back.diagnostics == []
    entries = {e.keyword: e for s in back.sections for e in s.entries}
    assert {k: raws(e) for k, e in entries.items()} == {k: raws(e) for k, e in merged.items()}


def test_no_matching_rack_is_an_error():
    result = merge(load(ADAPTER), [load(OTHER)])
    assert codes(result) == ["EDS401"]
    assert result.has_errors and result.merges == [] and result.text() == ""
    assert result.diagnostics[0].path == str(OTHER)


def test_only_matching_modules_are_merged():
    result = merge(load(ADAPTER), [load(OTHER), load(MODULE)])
    assert codes(result) == ["EDS401"]
    assert [m.module.path for m in result.merges] == [str(MODULE)]


def test_adapter_without_rack_entries():
    result = merge(edsconv.parse("[Params]\nProxyParam1 = 0,,,0,2,2,\"a\",\"\",\"\",0,1,0;\n"), [load(MODULE)])
    assert codes(result) == ["EDS401"]


#: the parameters ProxyAssem members name: a merge refuses an entry naming undefined ones (EDS301)
PARAMS_1_2 = '[Params]\nParam1 = 0,,,0,0xC6,1,"p","","",0,255,0;\nParam2 = 0,,,0,0xC6,1,"q","","",0,255,0;\n'


def _merge(adapter_body: str, module_body: str):
    adapter = edsconv.parse(adapter_body + ADAPTER_MODULAR, "adapter.eds")
    module = edsconv.parse(module_body + MODULE_MODULAR, "module.eds")
    assert not adapter.has_errors and not module.has_errors
    return merge(adapter, [module])


def test_module_without_proxied_entry_is_an_error():
    result = _merge('[Params]\nProxyParam1 = 0,,,0,2,2,"a","","",Module,1,0;\n', "")
    assert codes(result) == ["EDS402"]
    assert result.diagnostics[0].line == 2
    assert result.merges[0].sections == []


def test_module_beyond_the_proxied_fields_is_an_error():
    result = _merge('[Params]\nProxyParam1 = 0,,,0,2,2,"a","","",0,1,Module;\n',
                    '[Params]\nProxiedParam1 = ,,,,,,"a";\n')
    assert codes(result) == ["EDS402"]


def test_module_member_list_without_proxied_assem_is_an_error():
    result = _merge('[Assembly]\nProxyAssem1 = "a",,,,,,,ModuleMemberList;\n', "")
    assert codes(result) == ["EDS402"]


def test_proxy_entry_without_module_needs_no_proxied_entry():
    result = _merge('[Params]\nProxyParam1 = 0,,,0,2,2,"a","","",0,1,0;\n', "")
    assert result.diagnostics == []
    (entry,) = result.merges[0].sections[0].entries
    assert entry.keyword == "Param1" and raws(entry)[9:] == ["0", "1", "0"]


@pytest.mark.parametrize("members", ["Module,Param1", "16,Module"])
def test_module_in_a_member_field_is_an_error(members):
    result = _merge(f'[Assembly]\nProxyAssem1 = "a",,,,,,{members};\n',
                    '[Assembly]\nProxiedAssem1 = "a",,,,,,16,;\n')
    # EDS403 was merge's own code for it; EDS331, the code lint gives, replaces it (EDS403 is an alias now)
    assert codes(result) == ["EDS331"]


@pytest.mark.parametrize("members", ["16,ModuleMemberList", "ModuleMemberList,Param1"])
def test_module_member_list_must_replace_a_whole_pair(members):
    result = _merge(f'[Assembly]\nProxyAssem1 = "a",,,,,,{members};\n',
                    '[Assembly]\nProxiedAssem1 = "a",,,,,,16,;\n')
    assert codes(result) == ["EDS406"]


def test_module_member_list_in_place_of_the_pair_is_no_eds406():
    # docs/rules.md's example: "16,ModuleMemberList" is EDS406, ",ModuleMemberList" is the whole pair
    module = '[Assembly]\nProxiedAssem1 = "a",,,,,,16,;\n'
    assert codes(_merge('[Assembly]\nProxyAssem1 = "a",,,,,,16,ModuleMemberList;\n', module)) == ["EDS406"]
    assert codes(_merge('[Assembly]\nProxyAssem1 = "a",,,,,,,ModuleMemberList;\n', module)) == []


def test_module_member_list_alone_and_between_members():
    result = _merge(PARAMS_1_2 + '[Assembly]\nProxyAssem1 = "a",,,,,,8,Param1,,ModuleMemberList,8,Param2;\n'
                    'ProxyAssem2 = "b",,,,,,ModuleMemberList;\n',
                    '[Assembly]\nProxiedAssem1 = "x",,,,,,16,,32,"20 04";\nProxiedAssem2 = "y",,,,,,8;\n')
    assert result.diagnostics == []
    first, second = result.merges[0].sections[0].entries
    assert raws(first)[6:] == ["8", "Param1", "16", None, "32", '"20 04"', "8", "Param2"]
    assert raws(second)[6:] == ["8", None]


def test_merge_refuses_what_lint_calls_an_error_in_the_combined_entry():
    """Issue 20 item 10: the adapter's own fault, the module's in a field the adapter defers, and a fault of
    the pair (minimum above maximum once combined) each keep the entry out, with exit 1."""
    module = '[Params]\nProxiedParam1 = ,,,,,,"a","","",9,,;\n'
    own = _merge('[Params]\nProxyParam1 = 0,,,0,0xC6,1,"a","","",5,2,2;\n', module)
    deferred = _merge('[Params]\nProxyParam1 = 0,,,0,0xC6,1,"a","","",Module,20,9;\n',
                      '[Params]\nProxiedParam1 = ,,,,,,"a","","",0x1FF,,;\n')
    pair = _merge('[Params]\nProxyParam1 = 0,,,0,0xC6,1,"a","","",Module,2,2;\n', module)
    for result, code in ((own, "EDS315"), (deferred, "EDS102"), (pair, "EDS315")):
        assert codes(result) == [code] and result.has_errors
        assert result.merges[0].sections == [] and result.diagnostics[0].line == 2  # the ProxyParam1 line
    documented = _merge('[Params]\nProxyParam1 = 0,,,0,0xC6,1,"a","","",0,20,9;\n', module)
    assert codes(documented) == [] and len(documented.merges[0].sections[0].entries) == 1


def test_size_adder_without_proxy_param_is_a_warning():
    result = _merge('[Params]\nProxyParamSizeAdder3 = 1,1,1;\n', "")
    assert codes(result) == ["EDS404"] and not result.has_errors


def test_size_adder_with_its_proxy_param_is_no_eds404():
    result = _merge('[Params]\nProxyParam3 = 0,,,0,0xC6,1,"a","","",0,100,0;\nProxyParamSizeAdder3 = 1,1,1;\n', "")
    assert codes(result) == []
    (entry,) = result.merges[0].sections[0].entries
    assert raws(entry)[9:12] == ["1", "101", "1"]


def test_eds405_only_when_the_sum_leaves_the_type():
    # docs/rules.md's example: a module maximum of 250 in a USINT takes 4 more, not 10
    adapter = '[Params]\nProxyParam1 = 0,,,0,0xC6,1,"a","","",0,Module,0;\nProxyParamSizeAdder1 = 0,{add},0;\n'
    module = '[Params]\nProxiedParam1 = ,,,,,,"a","","",,250,;\n'
    assert codes(_merge(adapter.format(add=10), module)) == ["EDS405"]
    assert codes(_merge(adapter.format(add=4), module)) == []


def test_size_adder_on_an_empty_value_or_out_of_range():
    result = _merge('[Params]\nProxyParam1 = 0,,,0,0xC6,1,"a","","",,Module,Module;\n'
                    'ProxyParamSizeAdder1 = 1,1,0x10;\n',
                    '[Params]\nProxiedParam1 = ,,,,,,"a","","",,250,0xF0;\n')
    # min is empty: nothing to add to; max 250 + 1 = 251; default 0xF0 + 0x10 = 256 is beyond USINT
    assert codes(result) == ["EDS405", "EDS405"] and not result.has_errors
    (entry,) = result.merges[0].sections[0].entries
    assert raws(entry)[9:12] == [None, "251", "0xF0"]


def test_size_adder_keeps_hex_and_reals():
    result = _merge('[Params]\nProxyParam1 = 0,,,0,0xC7,2,"a","","",0x0001,Module,0x0020;\n'
                    'ProxyParam2 = 0,,,0,0xCA,4,"b","","",0.5,1.5,1;\n'
                    'ProxyParamSizeAdder1 = 0x0010,4,4;\nProxyParamSizeAdder2 = 1,1.25,1;\n',
                    '[Params]\nProxiedParam1 = ,,,,,,"a","","",,100,;\n')
    assert result.diagnostics == []
    first, second = result.merges[0].sections[0].entries
    assert raws(first)[9:12] == ["0x0011", "104", "0x0024"]
    assert raws(second)[9:12] == ["1.5", "2.75", "2.0"]


def test_module_connection_name_is_an_error():
    result = _merge('[Connection Manager]\nProxyConnect1 = 0x04010002,0x44244401,,,,,,,,,,,Module,"",'
                    '"20 04";\n', '[Connection Manager]\nProxiedConnect1 = ,,,,,,,,,,,,"x","","";\n')
    # EDS407 was merge's own code for it; EDS313, the code lint gives, replaces it (EDS407 is an alias now)
    assert codes(result) == ["EDS313"]


# --- command line ------------------------------------------------------------------


def run(*args: str):
    return CliRunner().invoke(cli, list(args), catch_exceptions=False)


def test_cli_prints_the_combined_entries():
    result = run("merge", str(ADAPTER), str(MODULE))
    assert result.exit_code == 0, result.output
    assert "    Param1 = 0,,, 0x0000, 2, 2, \"input size\", \"\", \"\", 4, 6, 6," in result.stdout
    assert "[Connection Manager]" in result.stdout and "Connection1 =" in result.stdout
    assert result.stderr == ""


def test_cli_no_match_exits_1_with_the_diagnostic():
    result = run("merge", str(ADAPTER), str(OTHER))
    assert result.exit_code == 1
    assert result.stdout == ""
    assert "EDS401" in result.stderr


def test_cli_missing_file_exits_2(tmp_path):
    result = run("merge", str(ADAPTER), str(tmp_path / "missing.eds"))
    assert result.exit_code == 2


def test_cli_needs_a_module():
    result = run("merge", str(ADAPTER))
    assert result.exit_code == 2


def test_cli_output_file(tmp_path):
    target = tmp_path / "merged.eds"
    target.write_text("old")
    refused = run("merge", str(ADAPTER), str(MODULE), "-o", str(target))  # issue 18 item 5: not without --force
    assert (refused.exit_code, target.read_text()) == (2, "old")
    result = run("merge", str(ADAPTER), str(MODULE), "-o", str(target), "--force")
    assert result.exit_code == 0 and result.stdout == ""
    assert target.read_text() == merge(load(ADAPTER), [load(MODULE)]).text()
    assert [p.name for p in tmp_path.iterdir()] == ["merged.eds"]  # no temporary file left


def test_cli_in_the_command_list():
    assert "merge" in run("--help").output
