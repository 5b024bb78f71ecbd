"""Issue 18, the edges a user reaches: reading paths, writing files, signals, standard output.

Each test reproduces a defect of the newcomer's report (reports/newcomer-2026-12-04.md; the item
number is in the test's comment). Permission cases run the command as a subprocess without root's
override (setpriv drops CAP_DAC_OVERRIDE), and skip where setpriv cannot do that.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv import atomic, paths
from edsconv.cli import cli

GOOD = (REPO / "corpus" / "examples" / "io_adapter.eds").read_bytes()
_DESC_TEXT = b'DescText = "edsconv example I/O adapter"'
#: one EDS002 (a missing ';', which has a safe fix)
BROKEN = GOOD.replace(_DESC_TEXT + b";", _DESC_TEXT)
MODULAR = REPO / "corpus" / "modular"
PROFILE = REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"


def invoke(*args: str | Path):
    return CliRunner().invoke(cli, [str(arg) for arg in args])


def edsconv(*args: str | Path, prefix: tuple[str, ...] = (), cwd: Path | None = None,
            **options) -> subprocess.CompletedProcess:
    options.setdefault("capture_output", "stdout" not in options)
    return subprocess.run([*prefix, sys.executable, "-m", "edsconv", *map(str, args)], text=True, timeout=120,
                          cwd=cwd, **options)


def without_root_override() -> tuple[str, ...]:
    """A command prefix that takes away root's permission to read and write anything (setpriv)."""
    if os.geteuid() != 0:
        return ()
    prefix = ("setpriv", "--bounding-set=-dac_override,-dac_read_search,-fowner")
    if shutil.which("setpriv") is None or subprocess.run([*prefix, "true"], capture_output=True).returncode != 0:
        pytest.skip("setpriv cannot drop CAP_DAC_OVERRIDE here")
    return prefix


# --- writing files --------------------------------------------------------------------------------
def test_lint_fix_that_cannot_write_says_so_keeps_the_findings_and_exits_2(tmp_path: Path) -> None:
    # item 1: was "EDS000 cannot read the file", the findings dropped, exit 1
    read_only = tmp_path / "ro"
    read_only.mkdir()
    (read_only / "bad.eds").write_bytes(BROKEN)
    read_only.chmod(0o555)
    try:
        result = edsconv("lint", "--fix", read_only / "bad.eds", prefix=without_root_override())
    finally:
        read_only.chmod(0o755)
    assert result.returncode == 2, result.stderr
    assert " EDS002 " in result.stdout and "EDS000" not in result.stdout
    assert result.stderr.splitlines()[-1] == f"{read_only / 'bad.eds'}: cannot write: Permission denied"
    assert (read_only / "bad.eds").read_bytes() == BROKEN


@pytest.mark.parametrize("command", [
    ["merge", MODULAR / "adapter.eds", MODULAR / "module.eds", "-o", "{out}"],
    ["show", REPO / "corpus" / "cip" / "icon_clean.eds", "--icon", "{out}"],
    ["xml2eds", PROFILE, "-o", "{out}"],
    ["show", REPO / "corpus" / "examples" / "io_adapter.eds", "--format", "html", "-o", "{out}"],
    ["diff", REPO / "corpus" / "examples" / "io_adapter.eds", REPO / "corpus" / "cip" / "icon_clean.eds",
     "--format", "html", "-o", "{out}"],
])
def test_every_writer_refuses_an_existing_file_without_force(tmp_path: Path, command: list) -> None:
    # item 5: merge -o and show --icon overwrote an existing file
    out = tmp_path / "existing"
    out.write_text("keep me")
    result = invoke(*[str(part).replace("{out}", str(out)) for part in command])
    assert (result.exit_code, out.read_text()) == (2, "keep me")
    assert result.stderr == f"{out} exists (use --force to overwrite it)\n"
    assert invoke(*[str(part).replace("{out}", str(out)) for part in command], "--force").exit_code in (0, 1)
    assert out.read_bytes() != b"keep me"


def test_no_writer_writes_over_its_own_input_even_with_force(tmp_path: Path) -> None:
    # item 5: `merge a.eds m.eds -o a.eds` replaced the adapter, `show x.eds --icon x.eds` the EDS
    adapter, module, eds = tmp_path / "a.eds", tmp_path / "m.eds", tmp_path / "icon.eds"
    adapter.write_bytes((MODULAR / "adapter.eds").read_bytes())
    module.write_bytes((MODULAR / "module.eds").read_bytes())
    eds.write_bytes((REPO / "corpus" / "cip" / "icon_clean.eds").read_bytes())
    (tmp_path / "link.eds").symlink_to(adapter)
    profile = tmp_path / "p.xml"
    profile.write_bytes(PROFILE.read_bytes())
    for command, target in [(["merge", adapter, module, "-o", tmp_path / "link.eds"], adapter),
                            (["merge", adapter, module, "-o", module], module),
                            (["show", eds, "--icon", eds], eds), (["xml2eds", profile, "-o", profile], profile),
                            (["show", eds, "--format", "json", "-o", eds], eds),
                            (["diff", adapter, module, "--format", "html", "-o", module], module)]:
        before = target.read_bytes()
        result = invoke(*command, "--force")
        assert result.exit_code == 2, command
        assert result.stderr.endswith(": not written: it is an input of this command (name another output file)\n")
        assert target.read_bytes() == before


def test_the_write_rule_knows_a_hard_link_of_an_input(tmp_path: Path) -> None:
    source = tmp_path / "in.eds"
    source.write_bytes(GOOD)
    os.link(source, tmp_path / "hard.eds")
    with pytest.raises(atomic.Refused, match="it is an input"):
        atomic.write_atomically(tmp_path / "hard.eds", b"x", inputs=[source], force=True)
    assert source.read_bytes() == GOOD


def test_a_rewrite_breaks_a_hard_link_as_the_docs_say(tmp_path: Path) -> None:
    # item 34: decided and documented: the atomic rename wins over the link (never half-written)
    target = tmp_path / "target.eds"
    target.write_bytes(BROKEN)
    os.link(target, tmp_path / "hard.eds")
    assert invoke("lint", "--fix", target).exit_code == 0
    assert (tmp_path / "hard.eds").read_bytes() == BROKEN and target.read_bytes() != BROKEN
    for page in ("lint.md", "fmt.md"):
        assert "hard link" in (REPO / "docs" / page).read_text(), page


# --- standard output ------------------------------------------------------------------------------
@pytest.mark.parametrize("command", [["lint", REPO / "corpus" / "examples" / "io_adapter.eds"], ["rules"],
                                     ["show", REPO / "corpus" / "examples" / "io_adapter.eds"], ["--help"]])
def test_a_closed_standard_output_is_one_line_and_exit_2(command: list) -> None:
    # item 30: was "internal error (AttributeError ...)", or (rules) exit 0 with nothing written
    result = edsconv(*command, preexec_fn=lambda: os.close(1))
    assert (result.returncode, result.stderr) == (2, "edsconv: cannot write to standard output: it is closed\n")


# --- reading paths --------------------------------------------------------------------------------
def test_an_unreadable_sub_directory_is_a_finding(tmp_path: Path) -> None:
    # item 8: was skipped silently, exit 0
    (tmp_path / "d" / "locked").mkdir(parents=True)
    (tmp_path / "d" / "ok.eds").write_bytes(GOOD)
    (tmp_path / "d" / "locked" / "bad.eds").write_bytes(BROKEN)
    (tmp_path / "d" / "locked").chmod(0)
    try:
        result = edsconv("lint", tmp_path / "d", prefix=without_root_override())
    finally:
        (tmp_path / "d" / "locked").chmod(0o755)
    assert result.returncode == 1, result.stderr
    assert result.stdout == (f"{tmp_path / 'd' / 'locked'}:1:1: error: EDS000 cannot search the directory: "
                             "Permission denied [edsconv]\n")
    assert result.stderr.startswith("2 files: 1 error,")


def test_a_named_file_that_cannot_be_read_is_eds000_and_the_run_goes_on(tmp_path: Path) -> None:
    # item 11: a dangling link or an unreadable file named explicitly was a click usage error, nothing checked
    (tmp_path / "ok.eds").write_bytes(BROKEN)
    (tmp_path / "dangling.eds").symlink_to(tmp_path / "gone.eds")
    (tmp_path / "secret.eds").write_bytes(GOOD)
    (tmp_path / "secret.eds").chmod(0)
    result = edsconv("lint", "dangling.eds", "secret.eds", "ok.eds", prefix=without_root_override(), cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    assert [line.split(": ")[2].split()[0] for line in result.stdout.splitlines()] == ["EDS000", "EDS000", "EDS002"]
    assert "secret.eds:1:1: error: EDS000 cannot read the file: Permission denied" in result.stdout
    missing = edsconv("lint", "nothing-here.eds", "ok.eds", cwd=tmp_path)  # a typo still cannot run
    assert missing.returncode == 2 and "'nothing-here.eds' does not exist" in missing.stderr


def test_symbolic_links_to_directories_are_followed_once(tmp_path: Path) -> None:
    # item 12: were not followed, silently; a loop must still end
    (tmp_path / "real" / "sub").mkdir(parents=True)
    (tmp_path / "real" / "sub" / "x.eds").write_bytes(GOOD)
    (tmp_path / "tree").mkdir()
    (tmp_path / "tree" / "linked").symlink_to(tmp_path / "real")
    (tmp_path / "real" / "sub" / "loop").symlink_to(tmp_path / "tree")
    found = paths.discover([tmp_path / "tree"])
    assert found.files == [str(tmp_path / "tree" / "linked" / "sub" / "x.eds")]
    assert invoke("lint", tmp_path / "tree").exit_code == 0


def test_a_search_leaves_out_hidden_and_tool_directories(tmp_path: Path) -> None:
    # item 13: .git, .venv and node_modules were linted
    for directory in (".git/x", ".venv/lib", "node_modules/p", ".hidden", "venv", "src"):
        (tmp_path / directory).mkdir(parents=True)
        (tmp_path / directory / "a.eds").write_bytes(BROKEN)
    (tmp_path / ".top.eds").write_bytes(GOOD)  # a hidden file is not a hidden directory
    found = paths.discover([tmp_path])
    assert [Path(f).relative_to(tmp_path).as_posix() for f in found.files] == [".top.eds", "src/a.eds"]
    named = paths.discover([tmp_path / ".venv", tmp_path / "node_modules" / "p" / "a.eds"])
    assert len(named.files) == 2  # named explicitly: always taken


def test_force_exclude_leaves_out_named_files_as_a_search_does(tmp_path: Path) -> None:
    # item 7: the pre-commit hook linted what `lint .` skips
    (tmp_path / "pyproject.toml").write_text('[tool.edsconv]\nexclude = ["third_party"]\n')
    (tmp_path / "third_party").mkdir()
    (tmp_path / "third_party" / "vendor.eds").write_bytes(BROKEN)
    (tmp_path / "own.eds").write_bytes(GOOD)
    assert edsconv("lint", ".", cwd=tmp_path).returncode == 0
    assert edsconv("lint", "third_party/vendor.eds", "own.eds", cwd=tmp_path).returncode == 1
    hooked = edsconv("lint", "--force-exclude", "third_party/vendor.eds", "own.eds", cwd=tmp_path)
    assert (hooked.returncode, hooked.stderr.splitlines()[0]) == (0, "1 file: 0 errors, 0 warnings, 0 notes")
    alone = edsconv("lint", "--force-exclude", "third_party/vendor.eds", cwd=tmp_path)
    assert alone.returncode == 0  # a commit of excluded files only passes
    assert "entry: edsconv lint --force-exclude" in (REPO / ".pre-commit-hooks.yaml").read_text()


def test_a_named_directory_without_eds_files_is_named_in_a_warning(tmp_path: Path) -> None:
    # item 14: exit 0 without a word about it
    (tmp_path / "empty").mkdir()
    (tmp_path / "ok.eds").write_bytes(GOOD)
    result = invoke("lint", tmp_path / "empty", tmp_path / "ok.eds")
    assert result.exit_code == 0
    assert result.stderr.splitlines()[0] == f"edsconv: warning: no EDS file (*.eds) found in {tmp_path / 'empty'}"


def test_one_file_under_several_spellings_is_checked_once(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # item 33: was checked three times
    (tmp_path / "d").mkdir()
    (tmp_path / "d" / "x.eds").write_bytes(BROKEN)
    monkeypatch.chdir(tmp_path)
    result = invoke("lint", "d", "d/x.eds", "d/../d/x.eds", tmp_path / "d" / "x.eds")
    assert result.stdout.count("EDS002") == 1 and result.stderr.startswith("1 file:")


def test_config_with_isolated_is_a_usage_error(tmp_path: Path) -> None:
    # item 26: --isolated silently won
    (tmp_path / "other.toml").write_text("ignore = []\n")
    (tmp_path / "x.eds").write_bytes(GOOD)
    result = invoke("lint", "--config", tmp_path / "other.toml", "--isolated", tmp_path / "x.eds")
    assert result.exit_code == 2 and "cannot be used with --config" in result.stderr


# --- fmt ------------------------------------------------------------------------------------------
def test_fmt_takes_a_directory_and_formats_in_parallel(tmp_path: Path) -> None:
    # item 27: `fmt DIR` was refused ("is a directory")
    for index in range(12):
        (tmp_path / "eds" / f"sub{index % 2}").mkdir(parents=True, exist_ok=True)
        (tmp_path / "eds" / f"sub{index % 2}" / f"f{index:02}.eds").write_bytes(GOOD)
    (tmp_path / "eds" / ".git").mkdir()
    (tmp_path / "eds" / ".git" / "skip.eds").write_bytes(GOOD)
    result = invoke("fmt", "-j", "2", tmp_path / "eds")
    assert result.exit_code == 0, result.stderr
    assert result.stderr.splitlines()[-1] == "12 file(s) reformatted, 0 unchanged"
    assert (tmp_path / "eds" / ".git" / "skip.eds").read_bytes() == GOOD
    checked = invoke("fmt", "--check", tmp_path / "eds")
    assert checked.stderr.splitlines()[-1] == "0 file(s) would be reformatted, 12 unchanged"


def test_fmt_shows_a_progress_bar_on_a_terminal(tmp_path: Path) -> None:
    import pty

    from edsconv.parallel import PROGRESS_THRESHOLD

    for index in range(PROGRESS_THRESHOLD):
        (tmp_path / f"f{index:02}.eds").write_bytes(GOOD)
    primary, secondary = pty.openpty()
    with os.fdopen(primary, "rb", buffering=0) as terminal:
        result = edsconv("fmt", "--check", "-j", "2", tmp_path, stderr=secondary, stdout=subprocess.DEVNULL)
        os.close(secondary)
        shown = terminal.read(65536).decode(errors="replace")
    assert result.returncode == 1
    assert "formatting" in shown and f"{PROGRESS_THRESHOLD} file(s) would be reformatted" in shown


def test_fmt_points_to_lint_fix_when_a_syntax_error_has_a_safe_fix(tmp_path: Path) -> None:
    # item 28
    (tmp_path / "bad.eds").write_bytes(BROKEN)
    (tmp_path / "worse.eds").write_text('[File]\nDescText = "x";\n  this is ; not an entry\n')
    result = invoke("fmt", tmp_path / "bad.eds", tmp_path / "worse.eds")
    bad, worse = result.stderr.splitlines()[:2]
    assert bad.endswith(f"; 'edsconv lint --fix {tmp_path / 'bad.eds'}' repairs it")
    assert "lint --fix" not in worse


# --- signals --------------------------------------------------------------------------------------
def _children(pid: int) -> set[int]:
    """The processes whose parent is ``pid`` (from /proc)."""
    found = set()
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == pid and fields[0] != "Z":
                found.add(int(entry.name))
    return found


def _slow_tree(directory: Path, files: int) -> None:
    """Files of about 80 ms of work each: the whole tree takes several seconds on two workers."""
    params = "".join(f'    Param{n} = 0,,,0x0000,0xC7,2,"P{n}","","",0,100,{n % 100};\n' for n in range(10, 400))
    text = GOOD.replace(b"[Params]\n", b"[Params]\n" + params.encode(), 1)
    directory.mkdir()
    for index in range(files):
        (directory / f"f{index:03}.eds").write_bytes(text)


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="finds the worker processes in /proc")
@pytest.mark.parametrize(("command", "signal_number", "to_group"), [
    ("lint", signal.SIGINT, True),  # Ctrl-C: the whole process group gets it
    ("lint", signal.SIGTERM, False),  # CI cancellation
    ("fmt", signal.SIGHUP, False),  # the terminal closed, while files are rewritten
])
def test_a_signal_stops_a_parallel_run_within_a_second(tmp_path: Path, command: str, signal_number: int,
                                                       to_group: bool) -> None:
    # item 2: the run went on until every file was done (19-21 s on 2,000 files)
    _slow_tree(tmp_path / "tree", 150)
    process = subprocess.Popen([sys.executable, "-m", "edsconv", command, "-j", "2", str(tmp_path / "tree")],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, start_new_session=True)
    deadline = time.monotonic() + 30
    while len(workers := _children(process.pid)) < 2 and time.monotonic() < deadline:
        time.sleep(0.02)
    time.sleep(0.3)  # every worker busy with a file
    assert process.poll() is None, "the run ended before the signal"
    sent = time.monotonic()
    (os.killpg if to_group else os.kill)(process.pid, signal_number)
    _, err = process.communicate(timeout=30)
    stopped = time.monotonic() - sent
    assert process.returncode == 128 + signal_number, err
    assert err == f"edsconv: interrupted by {signal.Signals(signal_number).name}\n"  # one line, no traceback
    assert stopped < 2.0, f"took {stopped:.1f} s"  # a second, and slack for a loaded machine
    time.sleep(0.1)
    assert not {pid for pid in workers if Path(f"/proc/{pid}").exists() and
                (Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z")}, "a worker lives on"
    assert not list((tmp_path / "tree").glob(".*.tmp")), "a temporary file was left"


def test_a_directory_named_twice_or_inside_another_is_not_called_empty(tmp_path: Path) -> None:
    (tmp_path / "d" / "sub").mkdir(parents=True)
    (tmp_path / "d" / "sub" / "x.eds").write_bytes(GOOD)
    found = paths.discover([tmp_path / "d", tmp_path / "d" / "sub", tmp_path / "d"])
    assert (found.files, found.empty) == ([str(tmp_path / "d" / "sub" / "x.eds")], [])


def test_a_named_file_below_a_directory_that_cannot_be_searched_is_eds000(tmp_path: Path) -> None:
    (tmp_path / "locked").mkdir()
    (tmp_path / "locked" / "x.eds").write_bytes(GOOD)
    (tmp_path / "locked").chmod(0)
    try:
        result = edsconv("lint", tmp_path / "locked" / "x.eds", prefix=without_root_override())
    finally:
        (tmp_path / "locked").chmod(0o755)
    assert result.returncode == 1, result.stderr
    assert "EDS000 cannot read the file: Permission denied" in result.stdout
