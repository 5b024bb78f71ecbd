"""Catalogue of the ISO 15745-4 profile schemas and their cached loading.

Each profile kind maps to one of the schemas restored in ``schemas/`` (see
``schemas/ERRATA.md``). Two of them need XSD 1.1: their trailing ``##any``
wildcards after optional elements violate Unique Particle Attribution in XSD 1.0.

Building a schema object costs 0.05-0.3 s, so built schemas are also pickled to
a per-user disk cache (see :func:`cache_dir`) and later processes unpickle them
(~0.04 s). The cache key hashes every ``.xsd`` file, the schemas directory, the
xmlschema version and the Python version; any trouble with the cache falls back
to building the schema.
"""

from __future__ import annotations

import functools
import hashlib
import os
import pickle
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
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


def cache_dir() -> Path:
    """``$XDG_CACHE_HOME/edsconv`` when that variable is set, else a per-user directory in the temp dir."""
    xdg = os.environ.get("XDG_CACHE_HOME")
    if xdg and os.path.isabs(xdg):
        return Path(xdg) / "edsconv"
    user = os.getuid() if hasattr(os, "getuid") else "user"
    return Path(tempfile.gettempdir()) / f"edsconv-{user}"


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


# Unpickling runs arbitrary code chosen by whoever wrote the file, so the cache
# must never load a file someone else could have put there: the directory is
# created 0o700 and must belong to the current user and not be group- or
# world-writable, and the file itself must belong to the current user (checked
# on the opened descriptor, symlinks refused). On systems without os.getuid
# (Windows) the temp dir is already per-user and the ownership checks are skipped.
def _trusted_dir(directory: Path) -> bool:
    try:
        os.makedirs(directory, mode=0o700, exist_ok=True)
        status = os.stat(directory)
    except OSError:
        return False
    if hasattr(os, "getuid"):
        return status.st_uid == os.getuid() and not status.st_mode & 0o022
    return True


def _read_cache(cache_file: Path, schema_class: type) -> xmlschema.XMLSchemaBase | None:
    """The cached schema, or ``None`` when absent, untrusted or unreadable for any reason."""
    if not _trusted_dir(cache_file.parent):
        return None
    try:
        descriptor = os.open(cache_file, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0))
    except OSError:
        return None
    try:
        with os.fdopen(descriptor, "rb") as stream:
            if hasattr(os, "getuid") and os.fstat(stream.fileno()).st_uid != os.getuid():
                return None
            schema = pickle.load(stream)
    except Exception:  # noqa: BLE001 - a corrupt pickle can raise nearly anything; rebuild and overwrite
        return None
    return schema if type(schema) is schema_class and schema.built else None


def _write_cache(cache_file: Path, schema: xmlschema.XMLSchemaBase) -> None:
    """Store atomically (temp file + rename); failures only cost start-up time later."""
    if not _trusted_dir(cache_file.parent):
        return
    temporary = None
    try:
        # NamedTemporaryFile creates the file 0o600.
        with tempfile.NamedTemporaryFile("wb", dir=cache_file.parent, prefix=".tmp-", delete=False) as stream:
            temporary = stream.name
            pickle.dump(schema, stream, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(temporary, cache_file)
    except Exception:  # noqa: BLE001 - read-only or full disk, unpicklable object: keep the built schema
        if temporary is not None:
            try:
                os.unlink(temporary)
            except OSError:
                pass
