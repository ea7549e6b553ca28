"""A suite: the NAME.rib files of one folder, their approved images golden/NAME.exr, and the
thresholds and darc arguments of each test from the folder's regress.toml.

regress.toml (optional; read with the standard library's tomllib) holds a [defaults] table for
every test and one [tests.NAME] table per test that differs; a test's keys override the
defaults key by key (a test's `args` replace the defaults' `args`, they are not appended)."""

from __future__ import annotations

import dataclasses
import math
import tomllib
from pathlib import Path

CONFIG_FILE_NAME = "regress.toml"
GOLDEN_FOLDER_NAME = "golden"


class SuiteError(Exception):
    """A suite that cannot be run as given (a usage error: exit code 2)."""


@dataclasses.dataclass(frozen=True)
class Thresholds:
    """idiff's thresholds, with idiff's defaults. Differences are absolute, per channel; a pixel
    is over a threshold when any of its channels is."""

    fail: float = 1e-6  # a pixel differing by more than this fails...
    failpercent: float = 0.0  # ...and the test fails when more than this % of pixels do
    hardfail: float = math.inf  # the test fails when any one pixel differs by more than this
    warn: float = 1e-6  # the same three for a warning (a test that warns still passes)
    warnpercent: float = 0.0
    hardwarn: float = math.inf


# The longest a single render may take before it is stopped and counted as an error: far above
# any regression scene (they should render in seconds), low enough that a hang cannot eat a CI run.
DEFAULT_TIMEOUT_SECONDS = 600.0


@dataclasses.dataclass(frozen=True)
class TestCase:
    name: str
    rib: Path
    golden: Path
    thresholds: Thresholds
    args: tuple[str, ...]  # extra darc arguments, before the RIB file
    timeout: float  # seconds


_THRESHOLD_KEYS = {f.name for f in dataclasses.fields(Thresholds)}
_KEYS = _THRESHOLD_KEYS | {"args", "timeout"}


def _check_settings(table: dict, where: str) -> dict:
    """Validates one [defaults] or [tests.NAME] table; returns it with numbers as floats."""
    if not isinstance(table, dict):
        raise SuiteError(f"{where}: expected a table")
    checked = {}
    for key, value in table.items():
        if key not in _KEYS:
            raise SuiteError(f"{where}: unknown key '{key}' (known: {', '.join(sorted(_KEYS))})")
        if key == "args":
            if not isinstance(value, list) or not all(isinstance(a, str) for a in value):
                raise SuiteError(f"{where}: 'args' must be a list of strings")
            checked[key] = tuple(value)
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float)) or math.isnan(value) or value < 0:
            raise SuiteError(f"{where}: '{key}' must be a number >= 0 (inf allowed)")
        if key == "timeout" and value == 0:
            raise SuiteError(f"{where}: 'timeout' must be more than 0 seconds")
        checked[key] = float(value)
    return checked


def _read_config(path: Path) -> tuple[dict, dict[str, dict]]:
    """The [defaults] table and the per-test tables of regress.toml, validated."""
    if not path.exists():
        return {}, {}
    try:
        with path.open("rb") as f:
            config = tomllib.load(f)
    except tomllib.TOMLDecodeError as e:
        raise SuiteError(f"{path}: {e}") from e
    unknown = set(config) - {"defaults", "tests"}
    if unknown:
        raise SuiteError(f"{path}: unknown table(s) {', '.join(sorted(unknown))} (known: defaults, tests)")
    defaults = _check_settings(config.get("defaults", {}), f"{path} [defaults]")
    tests = config.get("tests", {})
    if not isinstance(tests, dict):
        raise SuiteError(f"{path}: 'tests' must be a table of tables ([tests.NAME])")
    per_test = {name: _check_settings(table, f"{path} [tests.{name}]") for name, table in tests.items()}
    return defaults, per_test


def load_suite(folder: Path) -> list[TestCase]:
    """Every NAME.rib directly in `folder`, sorted by name, with its settings."""
    if not folder.is_dir():
        raise SuiteError(f"suite folder {folder} does not exist")
    config_path = folder / CONFIG_FILE_NAME
    defaults, per_test = _read_config(config_path)
    ribs = sorted(folder.glob("*.rib"), key=lambda rib: rib.stem)
    names = {rib.stem for rib in ribs}
    strays = sorted(set(per_test) - names)
    if strays:
        raise SuiteError(f"{config_path}: [tests.{strays[0]}] names no {strays[0]}.rib in {folder}")
    if not ribs:
        raise SuiteError(f"suite folder {folder} has no .rib files")
    cases = []
    for rib in ribs:
        settings = {**defaults, **per_test.get(rib.stem, {})}
        thresholds = Thresholds(**{k: v for k, v in settings.items() if k in _THRESHOLD_KEYS})
        cases.append(
            TestCase(
                name=rib.stem,
                rib=rib,
                golden=folder / GOLDEN_FOLDER_NAME / f"{rib.stem}.exr",
                thresholds=thresholds,
                args=settings.get("args", ()),
                timeout=settings.get("timeout", DEFAULT_TIMEOUT_SECONDS),
            )
        )
    return cases
