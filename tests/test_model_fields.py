"""The model's maps of keywords and fields to attributes agree with the spec's tables, and
device_to_eds writes every ParamN field from them (C.4.1.4.6, C.4.1.5.3.1)."""

from __future__ import annotations

import dataclasses

import edsconv
from edsconv import spec_tables as tables
from edsconv.eds.from_model import device_to_eds
from edsconv.eds.writer import write
from edsconv.model import (
    PARAMETER_FIELD_ATTRIBUTES,
    SINGLE_ENTRY_ATTRIBUTES,
    FileDescription,
    Identity,
    Modular,
    ParamClass,
    Scaling,
    parameter_field_type,
)


def test_every_paramn_field_has_its_attribute():
    assert len(PARAMETER_FIELD_ATTRIBUTES) == len(tables.PARAM_FIELDS)
    scaling = [a.removeprefix("scaling.") for a in PARAMETER_FIELD_ATTRIBUTES if a.startswith("scaling.")]
    assert scaling == [f.name for f in dataclasses.fields(Scaling)]
    assert PARAMETER_FIELD_ATTRIBUTES.index("scaling.multiplier") + 1 == \
        next(f.number for f in tables.PARAM_FIELDS if f.name == "Scaling Multiplier")
    assert parameter_field_type("scaling.offset") == "INT" and parameter_field_type("data_type_code") == "code"


def test_every_single_entry_has_its_attribute():
    records = {"File": FileDescription, "Device": Identity, "ParamClass": ParamClass, "Modular": Modular}
    for section, attributes in SINGLE_ENTRY_ATTRIBUTES.items():
        singles = {e.keyword for e in tables.SECTIONS[section].entries if not e.numbered and len(e.fields) == 1}
        assert set(attributes) == singles, section
        assert set(attributes.values()) <= {f.name for f in dataclasses.fields(records[section])}


def test_module_in_any_field_of_a_proxy_param_is_written_back_as_the_keyword():
    text = '[Params]\nProxyParam1 = 0,Module,Module,0x0000,0xC7,2,"a","","",0,10,1,Module;\n'
    device = edsconv.build(edsconv.parse(text))
    parameter = device.parameters["ProxyParam1"]
    assert (parameter.link_path_size, parameter.link_path, parameter.scaling.multiplier) == ("Module",) * 3
    written = write(device_to_eds(device))
    assert '"Module"' not in written
    again = edsconv.build(edsconv.parse(written))
    assert again.parameters == device.parameters and again.diagnostics == []
