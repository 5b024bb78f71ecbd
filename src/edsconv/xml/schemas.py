"""Catalogue of the ISO 15745-4 profile schemas and their cached loading.

Each profile kind maps to one of the schemas restored in ``schemas/`` (see
``schemas/ERRATA.md``). Two of them need XSD 1.1: their trailing ``##any``
wildcards after optional elements violate Unique Particle Attribution in XSD 1.0.

Documents edsconv writes are validated with lxml (libxml2, XSD 1.0 only), against
the schema itself or, for the two 1.1 schemas, against its XSD 1.0 rendition in
``schemas/xsd10/`` (derived by ``schemas/derive_xsd10.py``, never more permissive
than the 1.1 schema; see ``schemas/xsd10/README.md``): 50-100 times faster than
xmlschema. The restored schemas loaded by xmlschema stay the reference for
``edsconv validate`` and for the messages of a rejected document.

Building an xmlschema schema object costs 0.05-0.3 s, so built schemas are also pickled to
a per-user disk cache (:mod:`edsconv.cache`) and later processes unpickle them
(~0.04 s). The cache key hashes every ``.xsd`` file, the schemas directory, the
xmlschema version and the Python version; any trouble with the cache falls back
to building the schema.
"""

from __future__ import annotations

import functools
import hashlib
import pickle
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from edsconv import cache
from edsconv.cache import cache_dir
from edsconv.resources import data_dir

if TYPE_CHECKING:
    import xmlschema
    from lxml import etree


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
    # ISO 15745 families recognised but not validated (edsconv holds no schema): xml/validate.py FAMILIES
    ProfileKind("powerlink-xdd", "", None, "EPSG DS 311"),
    ProfileKind("canopen-xdd", "", None, "CiA 311"),
    ProfileKind("profinet-gsdml", "Device", None, "GSDML"),
    ProfileKind("iolink-iodd", "Device", None, "IODD"),
)

_BY_NAME = {kind.name: kind for kind in PROFILE_KINDS}
_BY_XSD = {kind.xsd: kind for kind in PROFILE_KINDS if kind.xsd}


def kind_named(name: str) -> ProfileKind:
    """Look a kind up by identifier or by schema file name (``KeyError`` if neither)."""
    return _BY_NAME.get(name) or _BY_XSD[name]


def write_validator_path(xsd: str) -> Path:
    """The schema file lxml validates documents of ``xsd`` with: its XSD 1.0 rendition when it needs XSD 1.1."""
    directory = data_dir("schemas")
    return directory / "xsd10" / xsd if _BY_XSD[xsd].xsd_version == "1.1" else directory / xsd


@functools.cache
def load_write_validator(xsd: str) -> etree.XMLSchema:
    """lxml's validator for documents of ``xsd``, loaded once per process (a few milliseconds)."""
    from lxml import etree

    parser = etree.XMLParser(resolve_entities=False, no_network=True)
    return etree.XMLSchema(etree.parse(str(write_validator_path(xsd)), parser))


@functools.cache
def load_schema(xsd: str) -> xmlschema.XMLSchemaBase:
    """Load a schema once per process, from the disk cache when it holds it."""
    return load_schema_uncached(xsd)


def load_schema_uncached(xsd: str) -> xmlschema.XMLSchemaBase:
    """Unpickle the schema from the disk cache, or build it and store it there."""
    # Imported here: it costs 0.13 s, which every other edsconv command would pay at start-up.
    import xmlschema

    cache_file = schema_cache_file(xsd, xmlschema.__version__)
    if cache_file is not None:
        schema = _read_cache(cache_file, _schema_class(xsd))
        if schema is not None:
            return schema
    schema = build_schema(xsd)
    if cache_file is not None:
        _write_cache(cache_file, schema)
    return schema


def build_schema(xsd: str) -> xmlschema.XMLSchemaBase:
    """Build the schema from its file; no network access (schemas and includes are local files)."""
    return _schema_class(xsd)(str(data_dir("schemas") / xsd), allow="local", defuse="always")


def _schema_class(xsd: str) -> type[xmlschema.XMLSchemaBase]:
    import xmlschema

    return xmlschema.XMLSchema11 if _BY_XSD[xsd].xsd_version == "1.1" else xmlschema.XMLSchema10


# Bump when the pickled content or the build options change.
_CACHE_FORMAT = "1"


def schema_cache_file(xsd: str, xmlschema_version: str) -> Path | None:
    """Where the pickled ``xsd`` goes, or ``None`` when the schemas cannot be read for the key."""
    schemas = data_dir("schemas")
    digest = hashlib.sha256()
    for part in (_CACHE_FORMAT, sys.version, xmlschema_version, str(schemas), xsd):
        digest.update(part.encode() + b"\0")
    try:
        for path in sorted(schemas.glob("*.xsd")):
            digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    except OSError:
        return None
    return cache_dir() / f"{Path(xsd).stem}-{digest.hexdigest()[:24]}.pickle"


# Unpickling runs code chosen by whoever wrote the file: edsconv.cache reads only
# files of the current user's own cache directory.
def _read_cache(cache_file: Path, schema_class: type[xmlschema.XMLSchemaBase]) -> xmlschema.XMLSchemaBase | None:
    """The cached schema, or ``None`` when absent, untrusted or unreadable for any reason."""
    data = cache.read_file(cache_file)
    if data is None:
        return None
    try:
        schema = pickle.loads(data)
    except Exception:  # noqa: BLE001 - a corrupt pickle can raise nearly anything; rebuild and overwrite
        return None
    return schema if isinstance(schema, schema_class) and type(schema) is schema_class and schema.built else None


def _write_cache(cache_file: Path, schema: xmlschema.XMLSchemaBase) -> None:
    """Store the pickled schema; failures only cost start-up time later."""
    try:
        data = pickle.dumps(schema, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # noqa: BLE001 - an unpicklable object: keep the built schema
        return
    cache.write_file(cache_file, data)
