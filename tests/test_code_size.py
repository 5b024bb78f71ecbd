"""Small units: no function over 60 lines, no module over 700 lines in src/ (data tables excepted)."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "edsconv"
MAX_FUNCTION_LINES = 60
MAX_MODULE_LINES = 700
#: The spec's tables as data and the rule texts: long by their content, not by their logic.
DATA_MODULES = {"spec_tables.py", "cip_tables.py"}


def is_data(path: Path) -> bool:
    return path.name in DATA_MODULES or path.name.endswith("_rules.py")


def modules() -> list[Path]:
    return sorted(SRC.rglob("*.py"))


def function_lengths(path: Path) -> list[tuple[str, int]]:
    """(``module:line name``, lines) of every function and method, decorators and docstring included."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            start = min([node.lineno, *(d.lineno for d in node.decorator_list)])
            end = node.end_lineno or node.lineno
            out.append((f"{path.relative_to(SRC)}:{node.lineno} {node.name}", end - start + 1))
    return out


def test_the_measure_sees_the_tree():
    assert len(modules()) > 50
    assert any(length > 30 for path in modules() for _, length in function_lengths(path))


def test_no_function_is_over_60_lines():
    long = [(name, length) for path in modules() for name, length in function_lengths(path)
            if length > MAX_FUNCTION_LINES]
    assert long == []


def test_no_module_is_over_700_lines():
    long = [(str(path.relative_to(SRC)), lines) for path in modules() if not is_data(path)
            and (lines := len(path.read_text(encoding="utf-8").splitlines())) > MAX_MODULE_LINES]
    assert long == []


def test_the_excepted_data_modules_exist():
    # a renamed table module would otherwise be measured as code, or an exception outlive its file
    assert {path.name for path in modules()} >= DATA_MODULES
