"""Project configuration: ``[tool.edsconv]`` in pyproject.toml, or an ``edsconv.toml``, as ruff finds its own.

The configuration of a file is the first one found walking up from the file's
directory: in each directory ``edsconv.toml`` (keys at the top level) wins over
``pyproject.toml`` (keys under ``[tool.edsconv]``; a pyproject.toml without that
table is passed over). Nothing is merged across directories. Keys:

``select``, ``extend-select``, ``ignore``
    rule codes or code prefixes, as ``edsconv lint --select/--ignore`` take them
``per-file-ignores``
    a table of glob -> codes: those codes are not reported for matching files
``warnings-as-errors``
    true: warnings are reported as errors and fail the run
``exclude``
    globs of files and directories that a directory search skips

A glob without ``/`` matches a file's name or the name of any directory it lies
in; a glob with ``/`` matches the path relative to the configuration file's
directory (``*`` matches across ``/`` there). Command-line options override the
file: ``--select`` replaces ``select`` and ``extend-select``, ``--ignore`` adds to
``ignore``, ``--warnings-as-errors/--no-warnings-as-errors`` replaces its key.

Both ``edsconv lint`` and the language server (:mod:`edsconv.lsp.settings`) read
configuration through :func:`settings_for`. A bad file raises :class:`ConfigError`
naming the file and line.
"""

from __future__ import annotations

import fnmatch
import os
import re
import tomllib
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path, PurePath

from edsconv.diagnostics import Diagnostic, Selection, load_rules

#: The files looked for in each directory, in the order they win.
CONFIG_FILES = ("edsconv.toml", "pyproject.toml")
#: Where each key's value came from when no file and no option set it.
DEFAULT = "default"
COMMAND_LINE = "command line"
_CODE_LISTS = ("select", "extend-select", "ignore")
KEYS = (*_CODE_LISTS, "per-file-ignores", "warnings-as-errors", "exclude")
#: Prefixes that select every rule.
_EVERY_CODE = ("EDS", "XML")


class ConfigError(Exception):
    """A configuration file that cannot be used: ``path:line: reason``."""

    def __init__(self, path: Path | str, line: int, reason: str) -> None:
        super().__init__(f"{path}:{line}: {reason}" if line else f"{path}: {reason}")
        self.path, self.line, self.reason = str(path), line, reason


@dataclass(frozen=True, slots=True)
class Settings:
    """The configuration in force for a file, and where each value came from."""

    select: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    #: (glob, codes) pairs, in file order
    per_file_ignores: tuple[tuple[str, tuple[str, ...]], ...] = ()
    warnings_as_errors: bool = False
    exclude: tuple[str, ...] = ()
    #: the configuration file (None: no file was found, or it was not read)
    source: str | None = None
    #: key -> "path:line", "command line" or "default"
    origins: dict[str, str] = field(default_factory=dict, compare=False, hash=False)

    @property
    def root(self) -> Path:
        """The directory globs are relative to: the configuration file's, else the working directory."""
        return Path(self.source).parent if self.source else Path.cwd()

    def for_file(self, path: str | Path) -> FileRules:
        """What is reported for ``path``: the selection, less the per-file ignores that match it."""
        relative = _relative(path, self.root)
        dropped = tuple(code for glob, codes in self.per_file_ignores if _matches(glob, relative) for code in codes)
        # extend-select adds to select, or to everything when select is not given (so that it can win over ignore)
        base = self.select or (_EVERY_CODE if self.extend_select else ())
        return FileRules(Selection.of((*base, *self.extend_select), self.ignore), dropped, self.warnings_as_errors)

    def excludes(self, path: str | Path) -> bool:
        relative = _relative(path, self.root)
        return any(_matches(glob, relative) for glob in self.exclude)

    def origin(self, key: str) -> str:
        return self.origins.get(key, DEFAULT)

    def describe(self, path: str | Path) -> str:
        """The settings in force for ``path``, one ``key = value  # origin`` line each (``lint --show-settings``)."""
        lines = [f"# {path}", f"# configuration: {_shown(self.source) if self.source else 'none found'}"]
        values: dict[str, object] = {"select": list(self.select), "extend-select": list(self.extend_select),
                                     "ignore": list(self.ignore),
                                     "per-file-ignores": {glob: list(codes) for glob, codes in self.per_file_ignores},
                                     "warnings-as-errors": self.warnings_as_errors, "exclude": list(self.exclude)}
        for key, value in values.items():
            lines.append(f"{key} = {_toml(value)}  # {_shown(self.origin(key))}")
        rules = self.for_file(path)
        lines.append(f"# per-file ignores matching this file: {_toml(list(rules.dropped))}")
        lines.append(f"# excluded from directory searches: {_toml(self.excludes(path))}")
        return "\n".join(lines) + "\n"


@dataclass(frozen=True, slots=True)
class FileRules:
    """The rules reported for one file (picklable: it travels to the worker processes)."""

    selection: Selection = Selection()
    #: per-file ignores: codes or prefixes never reported for this file, whatever is selected
    dropped: tuple[str, ...] = ()
    warnings_as_errors: bool = False

    def reports(self, code: str) -> bool:
        return code in self.selection and not any(code.startswith(prefix) for prefix in self.dropped)

    def kept(self, diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
        return [d for d in diagnostics if self.reports(d.code)]


@dataclass(frozen=True, slots=True)
class Overrides:
    """Command-line options that override the configuration files."""

    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    #: None: as the file says
    warnings_as_errors: bool | None = None
    #: a configuration file to use for every path instead of searching
    config: Path | None = None
    #: read no configuration file
    isolated: bool = False

    def apply(self, settings: Settings) -> Settings:
        origins = dict(settings.origins)
        changes: dict = {}
        if self.select:
            changes.update(select=self.select, extend_select=())
            origins.update({"select": COMMAND_LINE, "extend-select": COMMAND_LINE})
        if self.ignore:
            changes["ignore"] = (*settings.ignore, *self.ignore)
            origins["ignore"] = COMMAND_LINE if not settings.ignore else f"{settings.origin('ignore')} + command line"
        if self.warnings_as_errors is not None:
            changes["warnings_as_errors"] = self.warnings_as_errors
            origins["warnings-as-errors"] = COMMAND_LINE
        return replace(settings, **changes, origins=origins)


class Resolver:
    """Finds and reads the configuration of each file, each directory and file once."""

    def __init__(self, overrides: Overrides = Overrides()) -> None:
        self.overrides = overrides
        self._by_directory: dict[Path, Path | None] = {}
        self._read: dict[Path, Settings] = {}

    def settings_for(self, path: str | Path) -> Settings:
        if self.overrides.isolated:
            found = None
        elif self.overrides.config is not None:
            found = self.overrides.config
        else:
            where = Path(os.path.abspath(path))
            found = self.find(where if _is_directory(where) else where.parent)
        base = Settings() if found is None else self._load(found)
        return self.overrides.apply(base)

    def find(self, directory: Path) -> Path | None:
        """The configuration file that governs ``directory``: its own, or its nearest parent's."""
        if directory in self._by_directory:
            return self._by_directory[directory]
        found = next((directory / name for name in CONFIG_FILES if _configures(directory / name)), None)
        if found is None and directory.parent != directory:
            found = self.find(directory.parent)
        self._by_directory[directory] = found
        return found

    def _load(self, path: Path) -> Settings:
        if path not in self._read:
            self._read[path] = read_config(path)
        return self._read[path]


def settings_for(path: str | Path, overrides: Overrides = Overrides()) -> Settings:
    """The settings in force for the file at ``path`` (a one-off :class:`Resolver`)."""
    return Resolver(overrides).settings_for(path)


def _is_directory(path: Path) -> bool:
    try:
        return path.is_dir()
    except OSError:  # below a directory that cannot be searched: the command reports the path itself
        return False


def _configures(path: Path) -> bool:
    try:
        if not path.is_file():
            return False
    except OSError:  # a directory that cannot be searched holds no configuration edsconv can read
        return False
    if path.name != "pyproject.toml":
        return True
    try:
        return "edsconv" in tomllib.loads(path.read_text(encoding="utf-8")).get("tool", {})
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return True  # read_config reports what is wrong with it


def read_config(path: Path) -> Settings:
    """The settings a configuration file states; :class:`ConfigError` for anything it should not say."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        raise ConfigError(path, 0, f"cannot read: {getattr(error, 'strerror', None) or error}") from error
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        line = int(match.group(1)) if (match := re.search(r"at line (\d+)", str(error))) else 0
        raise ConfigError(path, line, f"not valid TOML: {error}") from error
    table = document.get("tool", {}).get("edsconv", {}) if path.name == "pyproject.toml" else document
    lines = _Lines(text, "[tool.edsconv" if path.name == "pyproject.toml" else None)
    if not isinstance(table, dict):
        raise ConfigError(path, lines.of("edsconv"), "[tool.edsconv] is not a table")
    return _settings(table, path, lines)


def _settings(table: dict, path: Path, lines: _Lines) -> Settings:
    unknown = [key for key in table if key not in KEYS]
    if unknown:
        raise ConfigError(path, lines.of(unknown[0]), f"unknown key {unknown[0]!r}; the keys are {', '.join(KEYS)}")
    values: dict = {}
    for key in _CODE_LISTS:
        if key in table:
            values[key.replace("-", "_")] = _codes(table[key], key, path, lines)
    if "per-file-ignores" in table:
        ignores = table["per-file-ignores"]
        if not isinstance(ignores, dict):
            raise ConfigError(path, lines.of("per-file-ignores"), "per-file-ignores is a table of glob = [codes]")
        values["per_file_ignores"] = tuple((glob, _codes(codes, f"per-file-ignores {glob!r}", path, lines,
                                                         (f'"{glob}"', f"'{glob}'")))
                                           for glob, codes in ignores.items())
    if "warnings-as-errors" in table:
        if not isinstance(table["warnings-as-errors"], bool):
            raise ConfigError(path, lines.of("warnings-as-errors"), "warnings-as-errors is true or false")
        values["warnings_as_errors"] = table["warnings-as-errors"]
    if "exclude" in table:
        values["exclude"] = _strings(table["exclude"], "exclude", path, lines)
    origins = {key: f"{path}:{lines.of(key)}" for key in table}
    return Settings(**values, source=str(path), origins=origins)


def _strings(value: object, key: str, path: Path, lines: _Lines, where: tuple[str, ...] = ()) -> tuple[str, ...]:
    if not isinstance(value, list) or not all(isinstance(item, str) for item in value):
        raise ConfigError(path, lines.of(*(where or (key,))), f"{key} is a list of strings")
    return tuple(value)


def _codes(value: object, key: str, path: Path, lines: _Lines, where: tuple[str, ...] = ()) -> tuple[str, ...]:
    """Rule codes or prefixes, each naming at least one rule (upper-cased, as the command line takes them)."""
    codes = _strings(value, key, path, lines, where)
    registry = load_rules()
    for code in codes:
        if not registry.knows_prefix(code.strip().upper()):
            raise ConfigError(path, lines.of(f'"{code}"', f"'{code}'"),
                              f"{key}: no rule code starts with {code!r} (see 'edsconv rules')")
    return tuple(code.strip().upper() for code in codes)


class _Lines:
    """Finds the line that states a key or value, within edsconv's table (tomllib keeps no positions)."""

    def __init__(self, text: str, table_header: str | None) -> None:
        self.lines = text.splitlines()
        self.first = 0
        if table_header is not None:
            self.first = next((i for i, line in enumerate(self.lines) if line.strip().startswith(table_header)), 0)

    def of(self, *needles: str) -> int:
        for index in range(self.first, len(self.lines)):
            text = self.lines[index].split("#", 1)[0]
            if any(re.search(rf"(^|[\s\"'{{,\[.]){re.escape(n)}", text) for n in needles):
                return index + 1
        return self.first + 1


def _shown(where: str) -> str:
    """A path (or ``path:line``) relative to the working directory when it lies below it, as printed."""
    if not os.path.isabs(where):
        return where
    relative = _relative(where, Path.cwd())
    return where if relative.is_absolute() else relative.as_posix()


def _relative(path: str | Path, root: Path) -> PurePath:
    absolute = Path(os.path.abspath(path))
    try:
        return absolute.relative_to(os.path.abspath(root))
    except ValueError:
        return absolute


def _matches(glob: str, relative: PurePath) -> bool:
    """A glob without ``/`` against every name in the path, one with ``/`` against the whole relative path."""
    if "/" not in glob.rstrip("/"):
        return any(fnmatch.fnmatchcase(part, glob.rstrip("/")) for part in relative.parts)
    return fnmatch.fnmatchcase(relative.as_posix(), glob.strip("/").removeprefix("./"))


def _toml(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{_toml(k)} = {_toml(v)}" for k, v in value.items()) + " }" if value else "{}"
    if isinstance(value, list):
        return "[" + ", ".join(_toml(item) for item in value) + "]"
    return '"' + str(value).replace("\\", "\\\\").replace('"', '\\"') + '"'

