"""The content beyond the 2003 text, phase 2 of issue 10: the typed model (edsconv.model.cip), the
checks EDS501-EDS514 on our own files of corpus/cip and corpus/idioms, the one "is it known" answer
(cip_tables.known) behind EDS006 / EDS219 / EDS220, and the real corpus (skipped without ../shared)."""

from __future__ import annotations

import functools
from pathlib import Path

import pytest
from lxml import etree

import edsconv
from conftest import REAL_EDS, REPO, needs_real_corpus
from edsconv import cip_tables
from edsconv.cip_tables import Known
from edsconv.lint import lint_file
from edsconv.model import Assembly, Device
from edsconv.model.cip import Service
from edsconv.model.cip_build import attach

CORPUS = REPO / "corpus"

#: code -> (a file of ours that breaks the rule once, the file it was derived from, which does not)
CASES = {
    "EDS501": ("cip/capacity_value_type.eds", "cip/capacity_clean.eds"),
    "EDS502": ("cip/capacity_connsize_range.eds", "cip/capacity_clean.eds"),
    "EDS503": ("cip/devicenet_io_info_type.eds", "cip/devicenet_io_info_clean.eds"),
    "EDS504": ("cip/capacity_txrx_keyword.eds", "cip/capacity_clean.eds"),
    "EDS505": ("cip/network_class_code_mismatch.eds", "cip/network_objects_clean.eds"),
    "EDS506": ("cip/network_class_code_practice.eds", "cip/network_objects_clean.eds"),
    "EDS507": ("cip/security_required_entry.eds", "cip/security_vendor_clean.eds"),
    "EDS508": ("cip/network_label_beyond_maxinst.eds", "cip/network_objects_clean.eds"),
    "EDS509": ("cip/icon_not_base64.eds", "cip/icon_clean.eds"),
    "EDS510": ("cip/icon_not_ico.eds", "cip/icon_clean.eds"),
    "EDS511": ("cip/assembly_exa_undefined_member.eds", "cip/assembly_exa_clean.eds"),
    "EDS512": ("cip/devicenet_io_info_default_input.eds", "cip/devicenet_io_info_clean.eds"),
    "EDS513": ("cip/devicenet_io_info_path_size.eds", "cip/devicenet_io_info_clean.eds"),
    "EDS514": ("idioms/opaque_self_assembly.eds", "idioms/nested_assembly.eds"),
}
#: What content beyond the 2003 text drew before it was modelled (EDS220 is now an alias of EDS222).
BEYOND_2003 = ("EDS006", "EDS219", "EDS220")


@functools.cache
def codes(relative: str) -> list[str]:
    return [d.code for d in lint_file(str(CORPUS / relative)).diagnostics]


def device(relative: str) -> Device:
    return edsconv.build(edsconv.load(CORPUS / relative))


def test_every_newer_rule_has_a_case():
    assert sorted(CASES) == sorted(code for code in edsconv.diagnostics.load_rules().rules if code.startswith("EDS5"))


@pytest.mark.parametrize("code", sorted(CASES))
def test_rule_triggers_once_on_its_fault_file(code):
    bad, _ = CASES[code]
    assert codes(bad).count(code) == 1


@pytest.mark.parametrize("code", sorted(CASES))
def test_rule_quiet_on_the_clean_file(code):
    _, good = CASES[code]
    assert code not in codes(good)


# --- EDS006 / EDS219 / EDS220 ----------------------------------------------------------------------


@pytest.mark.parametrize("relative", sorted(str(p.relative_to(CORPUS)) for p in (CORPUS / "cip").glob("*_clean.eds")))
def test_modelled_content_draws_no_beyond_2003_note(relative):
    assert [c for c in codes(relative) if c in BEYOND_2003] == []


def test_unknown_content_is_still_reported():
    """Unknown content: EDS222 for an entry keyword (a warning, with "did you mean"), EDS228 for a section
    (an error); a keyword the tables define for another section: EDS219; a section name outside the keyword
    rules that no table defines: EDS006 too."""
    text = ("[File]\nDescText = \"x\";\nCreateDate = 01-02-2024;\nCreateTime = 10:00:00;\nRevision = 1.0;\n"
            "[Capacity]\nMaxIOConnections = 4;\nMaxFoo = 1;\n65535_Foo = 1;\nMaxInst = 2;\n"
            "[Diagnostics/Extra]\nRevision = 1;\n[TCP/IP Interface Class]\nRevision = 4;\n")
    found = sorted((d.code, d.line) for d in edsconv.analyse(edsconv.parse(text))[1]
                   if d.code in (*BEYOND_2003, "EDS222", "EDS228"))
    assert found == [("EDS006", 11), ("EDS219", 10), ("EDS222", 8), ("EDS228", 11)]


def test_the_safety_classification_and_fields_are_known():
    assert not {"EDS209", "EDS219"} & set(codes("cip/safety_clean.eds"))
    assert cip_tables.known_choice(cip_tables.CLASSIFICATION_ENTRIES[0].fields[0], "Safety") is Known.NEWER
    assert cip_tables.known_choice(cip_tables.CLASSIFICATION_ENTRIES[0].fields[0], "Foo") is None


def test_known_answers_for_sections_and_keywords():
    assert cip_tables.known("[TCP/IP Interface Class]") is Known.NEWER
    assert cip_tables.known("Params") is Known.ISO_2003
    assert cip_tables.known("65535_Tool") is Known.VENDOR
    assert cip_tables.known("Class940_Vendor1") is Known.VENDOR
    assert cip_tables.known("Diagnostics Extra") is None
    assert cip_tables.known("Capacity", "TSpec12") is Known.NEWER
    assert cip_tables.known("Capacity", "MaxInst") is None
    assert cip_tables.known("Assembly", "AssemExa3") is Known.NEWER
    assert cip_tables.known("Assembly", "Assem3") is Known.ISO_2003
    assert cip_tables.known("Class940_Vendor1", "1_Ingress_TCP_Ports") is Known.VENDOR
    assert cip_tables.known("Class940_Vendor1", "Object_Class_Code") is Known.NEWER
    assert cip_tables.known("65535_Tool", "Anything") is Known.VENDOR


# --- the typed model -------------------------------------------------------------------------------


def test_capacity():
    capacity = device("cip/capacity_clean.eds").capacity
    assert capacity is not None
    assert [(t.number, t.direction, t.connection_size, t.packets_per_second) for t in capacity.traffic_specs] == [
        (1, "TxRx", 16, 2500), (2, "Rx", 400, 1200), (3, "Tx", 400, 1000)]
    assert (capacity.connection_overhead, capacity.max_msg_connections, capacity.max_io_connections) == (0.005, 8, 4)
    assert capacity.max_cip_connections is None


def test_network_objects_and_object_classes():
    found = device("cip/network_objects_clean.eds")
    tcpip = found.object_classes["TCP/IP Interface Class"]
    assert (tcpip.class_id, tcpip.class_code, tcpip.revision, tcpip.name) == (0xF5, 0xF5, 4, "TCP/IP Interface Object")
    assert tcpip.instance_services == (Service(0x0E, (), True), Service(0x10, (3, 5, 6)))
    assert str(tcpip.instance_services[1]) == "{0x10,3,5,6}"
    assert found.object_classes["Assembly"].class_code == 4 and found.object_classes["Port"].class_id == 0xF4
    assert [(q.ready_for_connection_time, q.accumulated_connection_time)
            for q in found.tcpip_interface.quick_connect_targets] == [(300, 40)]
    assert [(i.instance, i.label, i.interface_type) for i in found.ethernet_link.interfaces] == [
        (1, "P1", 2), (2, "P2", 2)]
    assert found.dlr.ring_supervisor_capable == "No"
    assert (found.additions.pitns, found.additions.pitns_usec) == ("Yes", "No")


def test_vendor_class_section():
    record = device("cip/security_vendor_clean.eds").object_classes["Class900_Vendor65535"]
    assert (record.class_id, record.vendor_id, record.class_code) == (900, 65535, 900)


def test_devicenet_io_info_references_are_resolved():
    io = device("cip/devicenet_io_info_clean.eds").devicenet
    poll = io.modes["PollInfo"]
    assert poll.default_input.target is io.inputs["Input1"] and poll.default_output.target is io.outputs["Output1"]
    assert io.modes["COSInfo"].default_output is None  # 0: none
    assert (io.inputs["Input1"].size, io.inputs["Input1"].size_in_bits, io.inputs["Input1"].path_size) == (2, 12, 6)
    assert io.enum_strings == {"Param1": ("Off", "3 ms", "10 ms")}


def test_safety_additions_name_their_connection_and_assembly():
    found = device("cip/safety_clean.eds")
    (connection,) = found.additions.default_safety_connections
    assert connection.target is found.connections["Connection1"]
    assert found.additions.safety_cfg_assembly.target is found.assemblies["Assem800"]
    assert (found.additions.max_safety_connections, found.additions.safety_format) == (1, 2)


def test_extended_assembly_is_an_assembly_with_resolved_members():
    found = device("cip/assembly_exa_clean.eds")
    exa = found.extended_assemblies["AssemExa101"]
    assert isinstance(exa, Assembly) and exa.family == "AssemExa"
    assert exa.size.target is found.parameters["Param2"]
    assert [m.reference.target.keyword for m in exa.members] == ["Assem100", "Param4", "Param4"]
    assert found.connections["Connection1"].t_to_o.format.target is exa
    assert found.resolve("AssemExa101") is exa


def test_icon_is_decoded():
    icon = device("cip/icon_clean.eds").icon_contents
    assert icon.valid_ico and icon.data[:4] == b"\0\0\1\0"
    assert [(i.width, i.height, i.encoding) for i in icon.images] == [(16, 16, "bmp")]
    broken = device("cip/icon_not_ico.eds").icon_contents
    assert (broken.kind, broken.valid_ico) == ("ico", False) and "beyond the end" in broken.problem
    assert device("cip/icon_not_base64.eds").icon_contents.data is None


def test_opaque_assembly_is_data_of_its_size():
    found = device("idioms/opaque_self_assembly.eds")
    (assembly,) = found.assemblies.values()
    assert assembly.opaque and found.assembly_bits(assembly) == 1024
    assert not {"EDS326", "EDS327"} & set(codes("idioms/opaque_self_assembly.eds"))


def test_opaque_assembly_of_another_size_is_a_size_disagreement_not_a_cycle():
    """Issue 20 item 11: 4096 bits against 496 bytes is EDS324, and the idiom is still recognised."""
    relative = "shall/C.4.1.4.8_opaque_assembly_size_agrees.eds"
    found = device(relative)
    assert found.assemblies["Assem150"].opaque and found.assembly_bits(found.assemblies["Assem150"]) == 496 * 8
    assert [c for c in codes(relative) if c in {"EDS324", "EDS326", "EDS327", "EDS514"}] == ["EDS324", "EDS514"]


def test_the_typed_view_attaches_to_a_device_read_from_xml():
    """The XML reader fills extra_entries / other_sections without syntax entries; attach reads them alike."""
    from edsconv.xml.common import Header
    from edsconv.xml.convert import profile_documents
    from edsconv.xml.device_read import read_device_profile

    original = device("cip/network_objects_clean.eds")
    device_xml, _ = profile_documents(original, Header.derive(original, "x"), "x")
    back = Device()
    read_device_profile(etree.fromstring(device_xml.data), back)
    attach(back)
    assert back.object_classes == original.object_classes
    assert (back.tcpip_interface, back.ethernet_link, back.dlr, back.additions) == (
        original.tcpip_interface, original.ethernet_link, original.dlr, original.additions)


# --- the real corpus ---------------------------------------------------------------------------------


@functools.cache
def real_diagnostics() -> list:
    return [d for path in REAL_EDS for d in lint_file(str(path)).diagnostics]


@needs_real_corpus
def test_real_files_draw_no_beyond_2003_note():
    """Everything the real files write beyond the 2003 text is modelled or vendor-specific."""
    assert [d.format() for d in real_diagnostics() if d.code in BEYOND_2003] == []


@needs_real_corpus
def test_real_files_draw_no_newer_error_and_four_icon_warnings():
    """No new error on a real file; the four icons that are not ICOs are warnings (3 BMP files, 1 neither)."""
    newer = [d for d in real_diagnostics() if d.code.startswith("EDS5")]
    assert sorted((Path(d.path).name[:40], d.code, str(d.severity)) for d in newer) == [
        ("ME-Catalyst__iodd-manager__Cube67_BNEIP_", "EDS510", "warning"),
        ("ME-Catalyst__iodd-manager__Cube67_BNEIP_", "EDS510", "warning"),
        ("MexicanMan2__Intern_EthernetIP_Comm__MT_", "EDS510", "warning"),
        ("omidbimo__eds_pie__netx.EDS", "EDS510", "warning")]


def test_a_value_with_one_reading_is_kept_and_reported_once():
    """The values policy: leading zeros break C.4.1.3.7 but read one way (kept, EDS501); a string
    flaw is the check of every string's (EDS116), not EDS501 again."""
    text = ('[Capacity]\nMaxIOConnections = 04;\n[QoS Class]\nObject_Name = "QoS\x01";\n')
    found, diagnostics = edsconv.analyse(edsconv.parse(text))
    assert found.capacity.max_io_connections == 4 and found.object_classes["QoS Class"].name == "QoS\x01"
    assert sorted(d.code for d in diagnostics if d.code in ("EDS116", "EDS501")) == ["EDS116", "EDS501"]
