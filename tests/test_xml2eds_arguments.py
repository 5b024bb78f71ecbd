"""xml2eds joins only the profiles of one device (issue 18 item 6): XML008, XML009, and a usage error
for a third argument."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from conftest import REAL_EDS, REPO
from edsconv.cli import cli
from edsconv.xml.convert import device_from_profiles

EXAMPLE = REPO / "corpus" / "examples" / "io_adapter.eds"


@pytest.fixture(scope="module")
def profiles(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    out = tmp_path_factory.mktemp("profiles")
    assert CliRunner().invoke(cli, ["eds2xml", str(EXAMPLE), "-o", str(out)]).exit_code == 0
    return out / "io_adapter_device.xml", out / "io_adapter_commnet.xml"


def _other_device(commnet: Path, tmp_path: Path, old: str, new: str) -> Path:
    text = commnet.read_text(encoding="utf-8")
    assert old in text
    other = tmp_path / "other_commnet.xml"
    other.write_text(text.replace(old, new), encoding="utf-8")
    return other


def test_the_profiles_of_one_device_convert(profiles: tuple[Path, Path]) -> None:
    device, diagnostics = device_from_profiles(list(profiles))
    assert device is not None and [d.code for d in diagnostics] == []
    assert not {"XML008", "XML009"} & {d.code for d in diagnostics}


@pytest.mark.parametrize(("old", "new"), [("65535-12-1001-COMM", "65535-12-9999-COMM"),
                                          ("<ProfileDate>2", "<ProfileDate>1")])
def test_another_devices_network_profile_is_xml008_and_nothing_is_written(
        profiles: tuple[Path, Path], tmp_path: Path, old: str, new: str) -> None:
    other = _other_device(profiles[1], tmp_path, old, new)
    target = tmp_path / "x.eds"
    result = CliRunner().invoke(cli, ["xml2eds", str(profiles[0]), str(other), "-o", str(target)])
    assert result.exit_code == 1 and not target.exists()
    (line,) = result.stderr.splitlines()
    assert "XML008 the profiles describe different devices: io_adapter_device.xml is '65535-12-1001'" in line


def test_a_network_profile_alone_or_two_device_profiles_are_xml009(profiles: tuple[Path, Path]) -> None:
    for arguments, what in (([profiles[1]], "a network profile alone describes no device"),
                            ([profiles[0], profiles[0]], "two device profiles")):
        result = CliRunner().invoke(cli, ["xml2eds", *map(str, arguments)])
        assert result.exit_code == 1 and result.stdout == ""
        assert f"XML009 {what}: give the device profile" in result.stderr


def test_a_third_profile_is_a_usage_error(profiles: tuple[Path, Path]) -> None:
    result = CliRunner().invoke(cli, ["xml2eds", str(profiles[0]), str(profiles[1]), str(profiles[1])])
    assert result.exit_code == 2 and result.stdout == ""
    assert "xml2eds takes a device profile and at most its network profile; 3 files were given" in result.stderr


def test_the_network_reader_alone_still_reads_a_network_profile(profiles: tuple[Path, Path]) -> None:
    device, diagnostics = device_from_profiles([profiles[1]], network_alone=True)
    assert device is not None and "XML009" not in [d.code for d in diagnostics]


# and five real files of different vendors
@pytest.mark.parametrize("eds", [*sorted((REPO / "corpus" / "examples").glob("*.eds")), *REAL_EDS[:60:12]],
                         ids=lambda path: path.name)
def test_xml2eds_writes_what_fmt_check_accepts(tmp_path: Path, eds: Path) -> None:
    """Issue 18 item 15: the README promises "an EDS in canonical form"; fmt --check rejected it."""
    converted = CliRunner().invoke(cli, ["eds2xml", str(eds), "-o", str(tmp_path)])
    if converted.exit_code != 0:
        pytest.skip("eds2xml does not convert this file (XML103) or finds errors")
    stem = eds.stem
    target = tmp_path / "back.eds"
    back = CliRunner().invoke(cli, ["xml2eds", str(tmp_path / f"{stem}_device.xml"),
                                    str(tmp_path / f"{stem}_commnet.xml"), "-o", str(target)])
    assert back.exit_code == 0, back.output
    checked = CliRunner().invoke(cli, ["fmt", "--check", str(target)])
    assert checked.exit_code == 0, checked.output
