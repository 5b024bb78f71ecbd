"""The command line is a layer of its own: click only under edsconv/cli, one way to give up, help that
names documentation the installation has."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv.cli import LazyGroup, cli

SRC = REPO / "src" / "edsconv"
CLI = SRC / "cli"
EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
IMPORTS_CLICK = re.compile(r"^\s*(import click\b|from click\b)", re.MULTILINE)
IMPORTS_CLI = re.compile(r"^\s*(import edsconv\.cli\b|from edsconv\.cli\b|from edsconv import cli\b)", re.MULTILINE)


def library_modules() -> list[Path]:
    return [p for p in SRC.rglob("*.py") if CLI not in p.parents and p.name != "__main__.py"]


def test_click_is_imported_only_by_the_command_line():
    assert sorted(str(p.relative_to(SRC)) for p in library_modules() if IMPORTS_CLICK.search(p.read_text())) == []
    assert IMPORTS_CLICK.search((CLI / "common.py").read_text())  # the pattern finds what it looks for


def test_the_library_never_imports_the_command_line():
    assert sorted(str(p.relative_to(SRC)) for p in library_modules() if IMPORTS_CLI.search(p.read_text())) == []
    assert IMPORTS_CLI.search((SRC / "__main__.py").read_text())


@pytest.mark.parametrize("name", sorted(LazyGroup.lazy))
def test_every_command_lives_in_the_cli_package(name: str):
    assert LazyGroup.lazy[name].startswith("edsconv.cli.")
    assert cli.get_command(None, name) is not None  # type: ignore[arg-type]


@pytest.mark.parametrize("name", sorted(LazyGroup.lazy))
def test_help_names_documentation_that_exists(name: str):
    result = CliRunner().invoke(cli, [name, "--help"])
    assert result.exit_code == 0
    assert "docs/" not in result.stdout.replace(" ", "").split("Documentation:")[0]
    (page,) = re.findall(r"Documentation:\s+(\S+)", result.stdout)
    assert Path(page).is_file()


def test_the_readme_command_table_names_every_command():
    """Issue 18 item 19: `lsp` was missing from the table."""
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    listed = set(re.findall(r"^\| `edsconv ([a-z0-9]+)\b", readme, re.MULTILINE))
    assert sorted(set(LazyGroup.lazy) - listed) == []


def test_a_file_that_cannot_be_written_is_reported_not_a_traceback(tmp_path: Path):
    (tmp_path / "io_adapter_device.xml").mkdir()  # a directory where the profile goes
    result = CliRunner().invoke(cli, ["eds2xml", str(EXAMPLE), "-o", str(tmp_path), "--force"])
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{tmp_path / 'io_adapter_device.xml'}: cannot write: ")
    assert result.exception is None or isinstance(result.exception, SystemExit)
    written = CliRunner().invoke(cli, ["eds2xml", str(EXAMPLE), "-o", str(tmp_path / "out")])
    assert (written.exit_code, written.stderr) == (0, "")


def test_refusing_to_overwrite_says_why(tmp_path: Path):
    target = tmp_path / "out.eds"
    target.write_text("")
    profile = REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"
    result = CliRunner().invoke(cli, ["xml2eds", str(profile), "-o", str(target)])
    assert (result.exit_code, result.stderr) == (2, f"{target} exists (use --force to overwrite it)\n")
    assert CliRunner().invoke(cli, ["xml2eds", str(profile), "-o", str(target), "--force"]).exit_code == 0


def test_fmt_goes_on_after_a_file_it_cannot_read(tmp_path: Path):
    canonical = tmp_path / "b.eds"
    canonical.write_text("[File]\n    DescText = \"x\";\n")
    result = CliRunner().invoke(cli, ["fmt", "--check", str(tmp_path / "missing.eds"), str(canonical)])
    assert result.exit_code == 2
    assert result.stderr.splitlines() == [f"{tmp_path / 'missing.eds'}: cannot read: No such file or directory",
                                          "0 file(s) would be reformatted, 1 unchanged, 1 not formatted"]


def test_architecture_names_every_module():
    text = (REPO / "docs" / "architecture.md").read_text()
    modules = [p.relative_to(SRC) for p in SRC.rglob("*.py") if p.name not in ("__init__.py", "__main__.py")]

    def named(module: Path) -> bool:  # by path; the command modules may go by their name
        return f"`{module.as_posix()}`" in text or (module.parts[0] == "cli" and f"`{module.stem}`" in text)

    missing = [str(m) for m in modules if not named(m)]
    assert missing == [], "docs/architecture.md does not say where these modules belong"
