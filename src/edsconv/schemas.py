"""Catalogue of the ISO 15745-4 profile schemas and their cached loading.

Each profile kind maps to one of the schemas restored in ``schemas/`` (see
``schemas/ERRATA.md``). Two of them need XSD 1.1: their trailing ``##any``
wildcards after optional elements violate Unique Particle Attribution in XSD 1.0.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import TYPE_CHECKING

from edsconv.resources import data_dir

if TYPE_CHECKING:
    import xmlschema


@dataclass(frozen=True, slots=True)
class ProfileKind:
    #: Stable identifier, used by ``--schema`` and in JSON output.
    name: str
    #: ProfileClassID the header declares (``Device`` or ``CommunicationNetwork``).
    profile_class: str
    #: Schema file in ``schemas/``; ``None`` for kinds recognised but not validated.
    xsd: str | None
    #: The clause of ISO 15745-4 that prints the schema.
    clause: str
    xsd_version: str = "1.0"


PROFILE_KINDS: tuple[ProfileKind, ...] = (
    ProfileKind("cip-device", "Device", "CIP_Device_Profile.xsd", "C.2.1.3.3", "1.1"),
    ProfileKind("eds-device-wrapper", "Device", "EDS_Device_Profile_wrapper.xsd", "C.2.2.2"),
    ProfileKind("ethernetip-commnet", "CommunicationNetwork", "ENet_CommNet_Profile.xsd", "C.3.1.3", "1.1"),
    ProfileKind("eds-commnet-wrapper", "CommunicationNetwork", "EDS_CommNet_Profile_wrapper.xsd", "C.3.2.2"),
    ProfileKind("adsnet-device", "Device", "ADS-net_Device_Profile.xsd", "A.2.3"),
    ProfileKind("adsnet-commnet", "CommunicationNetwork", "ADS-net_CommNet_Profile.xsd", "A.3.3"),
    ProfileKind("flnet-device", "Device", "FL-net_Device_Profile.xsd", "B.1.5"),
    ProfileKind("flnet-commnet", "CommunicationNetwork", "FL-net_CommNet_Profile.xsd", "B.2.4.5"),
    ProfileKind("powerlink-xdd", "", None, "ISO 15745-1 container"),
)

_BY_NAME = {kind.name: kind for kind in PROFILE_KINDS}
_BY_XSD = {kind.xsd: kind for kind in PROFILE_KINDS if kind.xsd}


def kind_named(name: str) -> ProfileKind:
    """Look a kind up by identifier or by schema file name (``KeyError`` if neither)."""
    return _BY_NAME.get(name) or _BY_XSD[name]


@functools.cache
def load_schema(xsd: str) -> xmlschema.XMLSchemaBase:
    """Load a schema once per process; no network access (schemas and includes are local files)."""
    # Imported here: it costs 0.13 s, which every other edsconv command would pay at start-up.
    import xmlschema

    kind = _BY_XSD[xsd]
    schema_class = xmlschema.XMLSchema11 if kind.xsd_version == "1.1" else xmlschema.XMLSchema10
    return schema_class(str(data_dir("schemas") / xsd), allow="local", defuse="always")
