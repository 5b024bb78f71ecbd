"""The bounded fuzz run of CI (about 60 s): every input kept in tests/fuzz_regressions/ replays without
breaking the invariant, and each target survives a short mutation run (docs/fuzzing.md)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from conftest import REPO

sys.path.insert(0, str(REPO / "fuzz"))
import fuzz_targets  # noqa: E402 - lives in fuzz/, beside the atheris driver
import mutation  # noqa: E402

REGRESSIONS = Path(__file__).resolve().parent / "fuzz_regressions"
KEPT = sorted((p.parent.name, p) for p in REGRESSIONS.glob("*/*") if p.is_file() and p.name != "README.md")
#: seconds of mutation per target: four targets stay within the minute the CI run may spend
SECONDS_PER_TARGET = 12


def test_every_regression_directory_names_a_target() -> None:
    assert {p.name for p in REGRESSIONS.iterdir() if p.is_dir()} <= set(fuzz_targets.TARGETS)


@pytest.mark.parametrize(("name", "path"), KEPT, ids=[f"{name}/{path.name}" for name, path in KEPT])
def test_a_kept_input_ends_in_diagnostics(name: str, path: Path) -> None:
    diagnostics = fuzz_targets.checked(fuzz_targets.TARGETS[name], path.read_bytes())
    assert isinstance(diagnostics, list)


@pytest.mark.mutation_run
@pytest.mark.parametrize("name", sorted(fuzz_targets.TARGETS))
def test_each_target_survives_a_short_mutation_run(name: str) -> None:
    outcome = mutation.run(name, SECONDS_PER_TARGET, seed=11)
    assert outcome.executions > 0


def test_a_broken_invariant_is_caught_and_the_input_kept(monkeypatch: pytest.MonkeyPatch) -> None:
    def crash(data: bytes) -> list:
        raise ValueError("boom")

    monkeypatch.setitem(fuzz_targets.TARGETS, "validate", fuzz_targets.Target("validate", crash, (".xml",)))
    monkeypatch.setattr(fuzz_targets, "seconds_per_byte", lambda target, seeds: 1.0)
    with pytest.raises(AssertionError, match=r"validate failed on .*mutation-[0-9a-f]{16}: ValueError: boom") as raised:
        mutation.run("validate", 5, seed=1)
    saved = Path(str(raised.value).split(" failed on ")[1].split(":")[0])
    assert saved.is_file()
    saved.unlink()


def test_a_slow_input_breaks_the_invariant() -> None:
    slow = fuzz_targets.Timed(fuzz_targets.TARGETS["parse_analyse"], seconds_per_byte=1e-12)
    with pytest.raises(fuzz_targets.InvariantBroken, match="more than 50x the seeds' time per byte"):
        slow(b"[File]\n")
