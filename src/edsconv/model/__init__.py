"""The typed device: the semantic model of an EDS, built by :mod:`edsconv.model.build`.

:mod:`edsconv.model.device` holds the classes (re-exported here), :mod:`edsconv.model.values`
the C.4.1.3 notation rules that turn written values into typed ones, :mod:`edsconv.model.epath`
the decoder of CIP paths for people and :mod:`edsconv.model.plain` model values as JSON data.
"""

from edsconv.model.device import (
    MODULE,
    MODULE_MEMBER_LIST,
    PARAMETER_FIELD_ATTRIBUTES,
    SINGLE_ENTRY_ATTRIBUTES,
    Assembly,
    AssemblyMember,
    Classification,
    CommentNote,
    Connection,
    ConnectionEndpoint,
    Device,
    FileDescription,
    GenericEntry,
    GenericSection,
    Identity,
    Modular,
    ParamClass,
    Parameter,
    ParameterGroup,
    Port,
    Query,
    Rack,
    Reference,
    Scaling,
    Unreadable,
    parameter_field,
    parameter_field_type,
)

__all__ = [
    "Assembly", "AssemblyMember", "Classification", "CommentNote", "Connection",
    "ConnectionEndpoint", "Device", "FileDescription", "GenericEntry", "GenericSection", "Identity",
    "MODULE", "MODULE_MEMBER_LIST", "Modular", "ParamClass", "Parameter", "ParameterGroup", "Port",
    "PARAMETER_FIELD_ATTRIBUTES", "Query", "Rack", "Reference", "SINGLE_ENTRY_ATTRIBUTES", "Scaling",
    "Unreadable", "parameter_field", "parameter_field_type",
]
