"""No traceback, honest exit codes: write failures, unexpected exceptions, signals (issue 11, defects 2, 5, 6)."""

from __future__ import annotations

import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REPO
from edsconv import cli as cli_package
from edsconv.cli import cli, main

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"
PROFILE = REPO / "corpus" / "xml" / "cip-device" / "valid-complete.xml"


def run_main(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str]:
    """Run the installed entry point in this process: exit code and standard error."""
    monkeypatch.setattr(sys, "argv", ["edsconv", *args])
    with pytest.raises(SystemExit) as exited:
        main()
    return exited.value.code, capsys.readouterr().err  # type: ignore[return-value]


@pytest.mark.parametrize("command", [
    ["eds2xml", str(EXAMPLE), "-o", "{file}/sub"],
    ["xml2eds", str(PROFILE), "-o", "{file}/x.eds"],
    ["merge", str(REPO / "corpus" / "modular" / "adapter.eds"), str(REPO / "corpus" / "modular" / "module.eds"),
     "-o", "{file}/x.eds"],
])
def test_writing_under_a_file_is_one_line_naming_it(tmp_path: Path, command: list[str]) -> None:
    blocker = tmp_path / "a_file"
    blocker.write_text("")
    result = CliRunner().invoke(cli, [part.replace("{file}", str(blocker)) for part in command])
    assert result.exit_code == 2
    (line,) = [line for line in result.stderr.splitlines() if "cannot write" in line]
    assert line.startswith(str(blocker / ("sub" if command[0] == "eds2xml" else "x.eds")))
    assert line.endswith(f": cannot write: {blocker} is not a directory")
    assert "Errno" not in result.stderr and "Traceback" not in result.stderr


@pytest.mark.parametrize("command", [["eds2xml", str(EXAMPLE), "-o", "{dir}"], ["xml2eds", str(PROFILE), "-o",
                                     "{dir}/y.eds"], ["fmt", "{dir}/x.eds"]])
def test_a_permission_error_is_one_line_and_exit_2(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                   command: list[str]) -> None:
    # chmod cannot refuse root (who runs CI), so the refusal comes from the file system call itself
    (tmp_path / "x.eds").write_text("[Device]\nVendCode = 1;\n[File]\nDescText = \"x\";\n")
    import edsconv.atomic

    def refuse(*args: object, **kwargs: object) -> None:
        raise PermissionError(13, "Permission denied", str(tmp_path / ".x.tmp"))

    monkeypatch.setattr(edsconv.atomic.tempfile, "mkstemp", refuse)
    result = CliRunner().invoke(cli, [part.replace("{dir}", str(tmp_path)) for part in command])
    assert result.exit_code == 2
    (line,) = [line for line in result.stderr.splitlines() if "cannot write" in line]
    assert line.startswith(str(tmp_path)) and ".tmp" not in line
    assert line.endswith(": cannot write: Permission denied")
    if command[0] == "fmt":  # defect 6: a failed write is not counted as reformatted
        assert result.stderr.splitlines()[-1] == "0 file(s) reformatted, 0 unchanged, 1 not formatted"


def test_an_unexpected_exception_is_one_line_asking_for_a_report(monkeypatch: pytest.MonkeyPatch,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    import edsconv.cli.convert

    def broken(*args: object) -> None:
        raise ValueError("boom")

    monkeypatch.setattr(edsconv.cli.convert, "header_for", broken)
    monkeypatch.delenv(cli_package.DEBUG_VARIABLE, raising=False)
    code, err = run_main(monkeypatch, capsys, "eds2xml", str(EXAMPLE), "-o", "/nonexistent")
    assert code == 2
    (line,) = err.splitlines()
    assert line.startswith("edsconv: internal error (ValueError: boom); this is a bug in edsconv, please report it")
    code, err = run_main(monkeypatch, capsys, "--debug", "eds2xml", str(EXAMPLE), "-o", "/nonexistent")
    assert code == 2 and "Traceback (most recent call last)" in err and 'raise ValueError("boom")' in err
    monkeypatch.setenv(cli_package.DEBUG_VARIABLE, "1")
    code, err = run_main(monkeypatch, capsys, "eds2xml", str(EXAMPLE), "-o", "/nonexistent")
    assert code == 2 and "Traceback (most recent call last)" in err


def test_an_os_error_no_command_expected_names_its_file(monkeypatch: pytest.MonkeyPatch,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    import edsconv.cli.convert

    def broken(*args: object) -> None:
        raise OSError(5, "Input/output error", "/dev/sdz")

    monkeypatch.setattr(edsconv.cli.convert, "header_for", broken)
    code, err = run_main(monkeypatch, capsys, "eds2xml", str(EXAMPLE), "-o", "/nonexistent")
    assert (code, err) == (2, "/dev/sdz: Input/output error\n")


def _catches(pid: int, signal_number: int) -> bool:
    status = Path(f"/proc/{pid}/status").read_text()
    caught = int(next(line for line in status.splitlines() if line.startswith("SigCgt:")).split()[1], 16)
    return bool(caught & (1 << (signal_number - 1)))


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads the signal mask from /proc")
@pytest.mark.parametrize("signal_number", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_a_signal_writes_neither_profile_and_leaves_nothing(tmp_path: Path, signal_number: int) -> None:
    big = tmp_path / "big.eds"
    text = EXAMPLE.read_text()
    params = "".join(f'    Param{n} = 0,,,0x0000,0xC7,2,"P{n}","","",0,100,{n % 100};\n' for n in range(10, 4000))
    big.write_text(text.replace("[Params]\n", "[Params]\n" + params, 1))
    out = tmp_path / "out"
    process = subprocess.Popen([sys.executable, "-m", "edsconv", "eds2xml", str(big), "-o", str(out)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while not _catches(process.pid, signal.SIGHUP) and time.monotonic() < deadline:
        time.sleep(0.01)  # until main() has installed its handlers
    process.send_signal(signal_number)
    _, err = process.communicate(timeout=60)
    assert process.returncode in (0, 128 + signal_number), err
    written = sorted(p.name for p in out.iterdir()) if out.exists() else []
    if process.returncode == 0:  # the conversion ended before the signal came
        assert written == ["big_commnet.xml", "big_device.xml"]
    else:
        assert written == []
        assert err == f"edsconv: interrupted by {signal.Signals(signal_number).name}\n"


def test_lint_of_a_directory_without_eds_files_cannot_run(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "readme.txt").write_text("not an EDS")
    result = CliRunner().invoke(cli, ["lint", str(tmp_path)])
    assert (result.exit_code, result.stdout) == (2, "")
    assert result.stderr == f"no EDS file (*.eds) found in {tmp_path}; nothing checked\n"
    (tmp_path / "sub" / "a.eds").write_text('[File]\nDescText = "x";\n')
    assert CliRunner().invoke(cli, ["lint", str(tmp_path)]).exit_code == 1  # found and checked


def test_eds2xml_help_names_the_files_it_writes_and_the_exit_codes() -> None:
    text = " ".join(CliRunner().invoke(cli, ["eds2xml", "--help"]).stdout.split())
    for words in ("STEM_device.xml and STEM_commnet.xml", "STEM_device_wrapper.xml and STEM_commnet_wrapper.xml",
                  "0 converted, no errors", "1 converted but the checks found errors, or not converted (XML103)",
                  "2 could not run"):
        assert words in text


def test_lint_of_one_long_line_of_letters_says_what_was_expected(tmp_path: Path) -> None:
    path = tmp_path / "letters.eds"
    path.write_text("A" * 5_000_000)
    result = CliRunner().invoke(cli, ["lint", str(path)])
    assert result.exit_code == 1
    assert result.stdout == (f"{path}:1:1: EDS001 unexpected 'AAAAAAAAAAAAAAAAAAAAAAAAAAA...': expected a section "
                             "header '[Name]', an entry 'Keyword =' or the end of the file [C.4.1.2.2]\n")
    assert "something else" not in result.stdout
