"""The rule registry: rules and checks are collected by functions from listed modules, checks declare
the rules they report, and a check whose rules are all deselected does not run."""

from __future__ import annotations

import importlib
import json
import pkgutil

import pytest
from click.testing import CliRunner

import edsconv
from conftest import REPO, SHARED_REAL
from edsconv import checks, lint, rule_docs
from edsconv.checks import Check, load_checks
from edsconv.cli import cli
from edsconv.diagnostics import EVERYTHING, Rule, Selection, load_rules

#: Triggers EDS313 (a ProxyConnect named Module, checks/entities) and EDS201 (no [Device], checks/structure).
PROXY_CONNECT_NAMED_MODULE = """\
[File]
DescText = "test"; CreateDate = 01-02-2024; CreateTime = 10:00:00; Revision = 1.1;
[Device Classification]
Class1 = EtherNetIP;
[Connection Manager]
ProxyConnect1 = 0x04010002, 0x44640405, , , , , , , , , , , Module, "", "20 04 24 64";
"""


def _defined_anywhere(kind: type) -> dict[int, object]:
    """Every module-level object of ``kind`` in every module of the package."""
    found: dict[int, object] = {}
    for module in pkgutil.walk_packages(edsconv.__path__, "edsconv."):
        if module.name.endswith("__main__"):  # runs the command line
            continue
        for value in vars(importlib.import_module(module.name)).values():
            if isinstance(value, kind):
                found[id(value)] = value
    return found


def test_every_rule_defined_in_the_package_is_in_the_registry():
    registered = {id(r) for r in load_rules().rules.values()}
    assert [r.code for key, r in _defined_anywhere(Rule).items() if key not in registered] == []


def test_every_check_defined_in_the_package_is_loaded():
    loaded = {id(c) for c in load_checks()}
    assert [c.name for key, c in _defined_anywhere(Check).items() if key not in loaded] == []


def _spy_on_checks(monkeypatch) -> list[str]:
    """Replace the loaded checks by ones that record their name when they run."""
    ran: list[str] = []

    def spy(real: Check) -> Check:
        def run(context):
            ran.append(real.name)
            return real.run(context)

        return Check(run, real.rules)

    spied = tuple(map(spy, load_checks()))
    monkeypatch.setattr(checks, "load_checks", lambda: spied)
    return ran


def test_a_check_whose_rules_are_all_deselected_does_not_run(monkeypatch):
    ran = _spy_on_checks(monkeypatch)
    eds = edsconv.parse(PROXY_CONNECT_NAMED_MODULE)

    _, found = edsconv.analyse(eds, Selection.of(select=["EDS313"]))
    assert ran == ["proxy_connect_names"]
    assert [d.code for d in found] == ["EDS313"]

    ran.clear()
    # every check reports EDS2xx, EDS3xx or EDS5xx codes, but two: the string characters of every section (EDS116,
    # EDS117) and ModuleMemberList in place of a pair (EDS406, the merge's rule)
    _, found = edsconv.analyse(eds, Selection.of(ignore=["EDS116", "EDS117", "EDS2", "EDS3", "EDS406", "EDS5"]))
    assert ran == [] and [d.code for d in found if d.code >= "EDS2"] == []

    ran.clear()
    _, found = edsconv.analyse(eds)
    assert ran == [c.name for c in load_checks()]
    assert {"EDS201", "EDS313"} <= {d.code for d in found}


def test_lint_passes_the_selection_down_to_the_checks(tmp_path, monkeypatch):
    ran = _spy_on_checks(monkeypatch)
    (tmp_path / "proxy.eds").write_text(PROXY_CONNECT_NAMED_MODULE)
    (report,) = lint.lint_paths([tmp_path], select=["EDS201"], jobs=1)
    assert ran == ["required_sections"]
    assert [d.code for d in report.diagnostics] == ["EDS201"]


def test_selection_follows_ruffs_longest_prefix_rule():
    assert "EDS313" in EVERYTHING
    assert "EDS313" not in Selection.of(select=["EDS3"], ignore=["EDS31"])
    assert "EDS313" in Selection.of(select=["EDS313"], ignore=["EDS31"])
    assert "EDS313" not in Selection.of(select=["EDS3"], ignore=["EDS3"])
    assert "EDS201" not in Selection.of(select=["EDS3"])


def _files() -> list:
    files = sorted((REPO / "corpus").rglob("*.eds"))
    if SHARED_REAL.is_dir():
        files += sorted(p for p in SHARED_REAL.iterdir() if p.suffix.lower() == ".eds")
    return files


@pytest.mark.parametrize("path", _files(), ids=lambda p: p.name)
def test_each_check_reports_only_the_rules_it_declares(path):
    eds = edsconv.load(path)
    context = checks.Context(eds, edsconv.build(eds))
    for check_ in load_checks():
        declared = {r.code for r in check_.rules}
        assert {d.code for d in check_.run(context)} <= declared, check_.name


# --- aliases: EDS407 names EDS313's fault, EDS403 names EDS331's ------------------------------------
PROXY_ASSEM_MEMBER_MODULE = PROXY_CONNECT_NAMED_MODULE.replace(
    "[Connection Manager]\nProxyConnect1", '[Assembly]\nProxyAssem1 = "Module data","",4,,,,32,Module;\n'
    "[Connection Manager]\nConnection1")


def _lint(tmp_path, text: str, *options: str):
    (tmp_path / "adapter.eds").write_text(text)
    result = CliRunner().invoke(cli, ["lint", "--format", "json", *options, str(tmp_path / "adapter.eds")])
    (report,) = json.loads(result.output)["files"]
    return [d["code"] for d in report["diagnostics"]]


@pytest.mark.parametrize(("text", "alias", "kept"), [(PROXY_CONNECT_NAMED_MODULE, "EDS407", "EDS313"),
                                                     (PROXY_ASSEM_MEMBER_MODULE, "EDS403", "EDS331")])
def test_selecting_or_ignoring_an_alias_acts_on_its_rule(tmp_path, text, alias, kept):
    assert kept in _lint(tmp_path, text)
    assert _lint(tmp_path, text, "--select", alias) == [kept]
    assert kept not in _lint(tmp_path, text, "--ignore", alias)
    assert alias not in _lint(tmp_path, text)
    # only the whole alias code stands for the rule: a prefix of it selects rules by their own codes
    assert kept not in _lint(tmp_path, text, "--select", alias[:5])


def test_the_registry_knows_aliases_only_as_aliases():
    registry = load_rules()
    assert {code: r.code for code, r in registry.aliases.items()} == {"EDS220": "EDS222", "EDS403": "EDS331",
                                                                      "EDS407": "EDS313"}
    assert "EDS403" not in registry.rules and "EDS407" not in registry.rules
    assert registry.resolve("EDS407") == "EDS313" and registry.resolve("EDS313") == "EDS313"


def test_rules_lists_an_alias_with_its_rule_and_explains_it():
    table = CliRunner().invoke(cli, ["rules"]).output.splitlines()
    assert next(line for line in table if line.startswith("EDS313")).endswith("(alias: EDS407)")
    assert next(line for line in table if line.startswith("EDS331")).endswith("(alias: EDS403)")
    assert not any(line.startswith(("EDS403", "EDS407")) for line in table)
    explained = CliRunner().invoke(cli, ["rules", "EDS407"]).output
    assert explained.startswith("### EDS313\n") and "- Alias: [EDS407](#eds407-alias-of-eds313)" in explained
    (record,) = json.loads(CliRunner().invoke(cli, ["rules", "--format", "json", "EDS331"]).output)
    assert [a["code"] for a in record["aliases"]] == ["EDS403"]


def test_docs_give_each_alias_a_heading_that_names_its_rule():
    page = (REPO / "docs" / "rules.md").read_text(encoding="utf-8")
    assert "\n### EDS403 (alias of EDS331)\n" in page and "\n### EDS407 (alias of EDS313)\n" in page
    assert "\n### EDS403\n" not in page and "\n### EDS407\n" not in page


def test_rule_text_for_one_code_and_markdown_for_all():
    one = CliRunner().invoke(cli, ["rules", "EDS321"]).output
    assert one.startswith("### EDS321\n") and "- Severity: info" in one and "Triggers:" in one
    assert CliRunner().invoke(cli, ["rules", "--format", "markdown"]).output == rule_docs.rules_page()
    assert CliRunner().invoke(cli, ["rules", "NOPE"]).exit_code == 2
