"""The size of an assembly member (C.4.1.4.8), one answer for ``show`` and the checks.

"If a Member Size field is empty, the defined size of the corresponding Member Reference
field shall be used. The defined size of a Param entry shall be as given in its 6th field
(size). The defined size of an Assem entry shall be as given in its 3rd field (size)." And
for an AssemN the Size and the members "both specify the size of the block".
"""

from __future__ import annotations

import edsconv
from edsconv.describe import describe
from edsconv.model import Device

HEAD = "[File]\nDescText = \"t\";\nCreateDate = 01-02-2024;\nCreateTime = 10:00:00;\nRevision = 1.1;\n"
PARAM_WORD = 'Param1 = 0,,,0x0000,0xD2,2,"Word","","",0,65535,0;'


def device(params: list[str], assemblies: list[str]) -> Device:
    return edsconv.build(edsconv.parse(HEAD + "[Params]\n" + "\n".join(params) + "\n[Assembly]\n"
                                       + "\n".join(assemblies) + "\n"))


def member_bits(dev: Device, keyword: str) -> list[int | None]:
    assembly = dev.assemblies[keyword]
    return [dev.member_bits(assembly, member) for member in assembly.members]


def shown_bits(dev: Device, keyword: str) -> list[int | None]:
    (assembly,) = [a for a in describe(dev)["assemblies"] if a["keyword"] == keyword]
    return [member["bits"] for member in assembly["members"]]


def size_codes(dev: Device) -> list[str]:
    _, diagnostics = edsconv.analyse(dev.eds)
    return [d.code for d in diagnostics if d.code in ("EDS324", "EDS325")]


def test_an_empty_member_size_takes_the_parameters_data_size():
    dev = device([PARAM_WORD], ['Assem1 = "a","",2,,,,,Param1;'])
    assert member_bits(dev, "Assem1") == shown_bits(dev, "Assem1") == [16]
    assert size_codes(dev) == []


def test_a_parameter_without_a_data_size_has_no_defined_size():
    # field 6 (Data Size) is empty: the data type's own size is not "the defined size"
    dev = device(['Param1 = 0,,,0x0000,0xD2,,"Word","","",0,65535,0;'], ['Assem1 = "a","",1,,,,,Param1;'])
    assert member_bits(dev, "Assem1") == shown_bits(dev, "Assem1") == [None]
    assert size_codes(dev) == []  # unknown: nothing to compare with Size 1


def test_a_nested_assembly_without_a_size_is_what_its_members_add_up_to():
    dev = device([PARAM_WORD], ['Assem1 = "inner","",,,,,16,Param1,8,;', 'Assem2 = "outer","",3,,,,,Assem1;'])
    assert member_bits(dev, "Assem2") == shown_bits(dev, "Assem2") == [24]
    assert dev.assembly_bits(dev.assemblies["Assem1"]) == 24
    assert size_codes(dev) == []


def test_a_nested_assembly_whose_members_disagree_with_the_outer_size_is_reported():
    dev = device([PARAM_WORD], ['Assem1 = "inner","",,,,,16,Param1,8,;', 'Assem2 = "outer","",2,,,,,Assem1;'])
    assert member_bits(dev, "Assem2") == shown_bits(dev, "Assem2") == [24]
    assert size_codes(dev) == ["EDS324"]


def test_a_nested_assembly_with_a_size_uses_it():
    dev = device([PARAM_WORD], ['Assem1 = "inner","",4,,,,16,Param1,16,;', 'Assem2 = "outer","",4,,,,,Assem1;'])
    assert member_bits(dev, "Assem2") == shown_bits(dev, "Assem2") == [32]


def test_an_assembly_with_neither_size_nor_members_is_empty():
    dev = device([], ['Assem1 = "empty";', 'Assem2 = "outer","",1,,,,8,Assem1,8,;'])
    assert dev.assembly_bits(dev.assemblies["Assem1"]) == 0
    assert member_bits(dev, "Assem2") == [8, 8]


def test_a_cycle_of_assemblies_has_no_size():
    dev = device([], ['Assem1 = "a","",,,,,,Assem2;', 'Assem2 = "b","",,,,,,Assem1;'])
    assert member_bits(dev, "Assem1") == shown_bits(dev, "Assem1") == [None]


def test_a_member_size_that_cannot_be_read_is_unknown():
    # the Member Size is written (so the referenced size does not apply) but is no UINT
    dev = device([PARAM_WORD], ['Assem1 = "a","",2,,,,sixteen,Param1;'])
    assert member_bits(dev, "Assem1") == shown_bits(dev, "Assem1") == [None]
    assert size_codes(dev) == []
