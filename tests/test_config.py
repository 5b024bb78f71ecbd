"""``[tool.edsconv]`` / ``edsconv.toml``: found by walking up, every key, overrides, --show-settings, bad files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv.cli import cli
from edsconv.config import ConfigError, Overrides, Resolver, read_config
from edsconv.lsp.settings import settings_for as editor_settings

GOOD = (REPO / "corpus" / "examples" / "io_adapter.eds").read_text(encoding="ascii")
#: EDS103 (error), EDS114 (warning) and a non-ASCII comment (EDS005, warning)
FAULTY = GOOD.replace("ProdCode = 1001;", "ProdCode = 01001;").replace(
    "CreateDate = 11-22-2026;", "CreateDate = 11-22-1994;") + "$ caf\u00e9\n"


def run(*args: str):
    return CliRunner().invoke(cli, list(args), standalone_mode=False, catch_exceptions=False)


def lint_json(*args: str) -> tuple[int, dict[str, list[tuple[str, str]]]]:
    """Exit code, and (code, severity) pairs by file name."""
    result = run("lint", "--format", "json", *args)
    files = json.loads(result.stdout)["files"]
    return result.return_value, {Path(f["path"]).name: [(d["code"], d["severity"]) for d in f["diagnostics"]]
                                 for f in files}


@pytest.fixture
def project(tmp_path: Path) -> Path:
    """pyproject.toml at the top, eds/ and eds/vendor/ below it, a build/ directory to exclude."""
    (tmp_path / "eds" / "vendor").mkdir(parents=True)
    (tmp_path / "build").mkdir()
    for name in ("eds/a.eds", "eds/vendor/b.eds", "build/c.eds"):
        (tmp_path / name).write_text(FAULTY, encoding="utf-8")
    (tmp_path / "pyproject.toml").write_text("""\
[project]
name = "eds-files"

[tool.edsconv]
ignore = ["EDS005"]
warnings-as-errors = true
exclude = ["build"]

[tool.edsconv.per-file-ignores]
"eds/vendor/*.eds" = ["EDS1"]
""", encoding="utf-8")
    return tmp_path


def test_pyproject_is_found_by_walking_up_and_every_key_applies(project: Path, monkeypatch):
    monkeypatch.chdir(project)
    code, found = lint_json(".")
    # build/ is excluded; EDS005 ignored; warnings are errors; vendor files drop EDS1xx
    assert found == {"a.eds": [("EDS114", "error"), ("EDS103", "error")], "b.eds": []}
    assert code == 1
    # a file named explicitly is linted even when excluded, by the configuration above it
    assert lint_json("build/c.eds")[1] == {"c.eds": [("EDS114", "error"), ("EDS103", "error")]}


def test_command_line_overrides_the_file(project: Path):
    _, found = lint_json("--no-warnings-as-errors", "--select", "EDS0,EDS114", str(project / "eds"))
    assert found == {"a.eds": [("EDS114", "warning")], "b.eds": []}
    assert "EDS005" not in [c for c, _ in found["a.eds"]]  # --select replaces select, ignore still applies
    _, found = lint_json("--ignore", "EDS114", str(project / "eds" / "a.eds"))
    assert found == {"a.eds": [("EDS103", "error")]}
    _, isolated = lint_json("--isolated", str(project / "eds" / "a.eds"))
    assert isolated == {"a.eds": [("EDS114", "warning"), ("EDS103", "error"), ("EDS005", "warning")]}


def test_the_nearest_configuration_wins_and_edsconv_toml_before_pyproject(project: Path):
    (project / "eds" / "vendor" / "edsconv.toml").write_text('select = ["EDS005"]\n', encoding="utf-8")
    _, found = lint_json(str(project / "eds"))
    # nothing merges: b.eds has only its own edsconv.toml (no warnings-as-errors)
    assert found == {"a.eds": [("EDS114", "error"), ("EDS103", "error")], "b.eds": [("EDS005", "warning")]}
    (project / "eds" / "pyproject.toml").write_text("[tool.black]\n", encoding="utf-8")  # no [tool.edsconv]
    assert Resolver().find(project / "eds") == project / "pyproject.toml"


def test_extend_select_adds_to_select_and_wins_over_a_shorter_ignore(tmp_path: Path):
    (tmp_path / "a.eds").write_text(FAULTY, encoding="utf-8")
    (tmp_path / "edsconv.toml").write_text('ignore = ["EDS1"]\nextend-select = ["EDS103"]\n', encoding="utf-8")
    assert lint_json(str(tmp_path))[1] == {"a.eds": [("EDS103", "error"), ("EDS005", "warning")]}
    (tmp_path / "edsconv.toml").write_text('select = ["EDS005"]\nextend-select = ["EDS114"]\n', encoding="utf-8")
    assert lint_json(str(tmp_path))[1] == {"a.eds": [("EDS114", "warning"), ("EDS005", "warning")]}


def test_show_settings_says_what_is_in_force_and_where_it_came_from(project: Path):
    result = run("lint", "--show-settings", "--select", "EDS1", str(project / "eds" / "vendor" / "b.eds"))
    assert result.return_value == 0
    lines = result.stdout.splitlines()
    config = project / "pyproject.toml"
    assert lines[1] == f"# configuration: {config}"
    assert 'select = ["EDS1"]  # command line' in lines
    assert f'ignore = ["EDS005"]  # {config}:5' in lines
    assert f"warnings-as-errors = true  # {config}:6" in lines
    assert f'exclude = ["build"]  # {config}:7' in lines
    assert f'per-file-ignores = {{ "eds/vendor/*.eds" = ["EDS1"] }}  # {config}:9' in lines
    assert '# per-file ignores matching this file: ["EDS1"]' in lines


@pytest.mark.parametrize(("text", "line", "reason"), [
    ('[tool.edsconv]\nselect = ["EDS1"]\nwarnings_as_errors = true\n', 3, "unknown key 'warnings_as_errors'"),
    ('[tool.edsconv]\nignore = [\n  "EDS005",\n  "EDS9",\n]\n', 4, "ignore: no rule code starts with 'EDS9'"),
    ('[tool.edsconv]\nwarnings-as-errors = "yes"\n', 2, "warnings-as-errors is true or false"),
    ('[tool.edsconv.per-file-ignores]\n"*.eds" = "EDS1"\n', 2, "per-file-ignores '*.eds' is a list of strings"),
    ('[tool.edsconv]\nselect = [EDS1]\n', 2, "not valid TOML"),
])
def test_a_bad_file_cannot_run_and_names_its_location(tmp_path: Path, text: str, line: int, reason: str):
    (tmp_path / "pyproject.toml").write_text(text, encoding="utf-8")
    (tmp_path / "a.eds").write_text(GOOD, encoding="utf-8")
    with pytest.raises(ConfigError) as raised:
        read_config(tmp_path / "pyproject.toml")
    assert (raised.value.line, raised.value.reason[:len(reason)]) == (line, reason)
    result = CliRunner().invoke(cli, ["lint", str(tmp_path)])
    assert result.exit_code == 2
    assert result.output.startswith(f"{tmp_path / 'pyproject.toml'}:{line}: {reason}")


def test_the_language_server_reads_the_same_settings(project: Path):
    vendor = editor_settings(str(project / "eds" / "vendor" / "b.eds"), [str(project)])
    assert vendor.source == str(project / "pyproject.toml")
    assert not vendor.rules.reports("EDS103") and not vendor.rules.reports("EDS005")
    assert vendor.rules.reports("EDS201") and vendor.rules.warnings_as_errors
    unsaved = editor_settings(None, [str(project)])
    assert unsaved.source == str(project / "pyproject.toml")
    (project / "pyproject.toml").write_text("[tool.edsconv]\nnope = 1\n", encoding="utf-8")
    broken = editor_settings(str(project / "eds" / "a.eds"), [str(project)])
    assert broken.rules.reports("EDS005") and "unknown key 'nope'" in (broken.error or "")


def test_overrides_keep_the_file_origins():
    settings = Overrides(ignore=("EDS2",)).apply(Resolver(Overrides(isolated=True)).settings_for("x.eds"))
    assert settings.ignore == ("EDS2",) and settings.origin("ignore") == "command line"
    assert settings.origin("select") == "default"


def test_show_settings_of_a_directory_reads_the_configuration_inside_it(project: Path):
    (project / "eds" / "edsconv.toml").write_text('ignore = ["EDS2"]\n', encoding="utf-8")
    lines = run("lint", "--show-settings", str(project / "eds")).stdout.splitlines()
    assert lines[1] == f"# configuration: {project / 'eds' / 'edsconv.toml'}"
