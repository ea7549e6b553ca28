"""A tiny suite made fresh in a scratch folder for the tests of scripts/darc-regress itself, and
the few things those tests do to it: run the runner, change a golden image, read the JUnit file.
Paths come from the environment ctest sets (tests/CMakeLists.txt), else from this repository."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import OpenImageIO as oiio

REPOSITORY = Path(__file__).resolve().parents[2]
DARC = Path(os.environ.get("DARC_BINARY", REPOSITORY / "build" / "darc"))
DARC_REGRESS = Path(os.environ.get("DARC_REGRESS", REPOSITORY / "scripts" / "darc-regress"))

# 32x24 so that a run of the whole suite takes a fraction of a second.
SPHERE_RIB = """\
Format 32 24 1
PixelSamples 1 1
Projection "perspective" "fov" [40]
Translate 0 0 4
WorldBegin
LightSource "ambientlight" 1 "intensity" [0.2]
LightSource "distantlight" 2 "from" [-1 1 -1] "to" [0 0 0]
Color [0.8 0.4 0.2]
Surface "matte"
Sphere 1 -1 1 360
WorldEnd
"""

STRANDS_RIB = """\
Format 32 24 1
Projection "perspective" "fov" [40]
Translate 0 0 4
WorldBegin
LightSource "ambientlight" 1 "intensity" [0.3]
LightSource "distantlight" 2 "from" [0 1 -1] "to" [0 0 0]
Color [0.9 0.8 0.5]
Surface "hair"
Curves "linear" [2 2] "nonperiodic" "P" [-1.2 -0.8 0  1.2 0.6 0  -1.2 0.6 0  1.2 -0.8 0]
  "constantwidth" [0.05]
WorldEnd
"""

# strands: loose fail and tight warn, so that a small change is a warning only; its own darc
# arguments, so that the tests can see them reach darc.
CONFIG = """\
[tests.strands]
fail = 0.01
warn = 1e-4
args = ["--pixel-samples", "2"]
"""

# A scene error: darc renders nothing and exits with 3.
BROKEN_RIB = """\
Format 32 24 1
WorldBegin
Sphere 1 -1 1
WorldEnd
"""


def make_suite(folder: Path) -> Path:
    """sphere.rib, strands.rib and regress.toml in `folder` (no golden images yet)."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "sphere.rib").write_text(SPHERE_RIB)
    (folder / "strands.rib").write_text(STRANDS_RIB)
    (folder / "regress.toml").write_text(CONFIG)
    return folder


def scratch_folder(name: str) -> Path:
    return Path(tempfile.mkdtemp(prefix=f"darc-regress-{name}-"))


def remove(folder: Path) -> None:
    shutil.rmtree(folder, ignore_errors=True)


def run_command(command: list[str]) -> subprocess.CompletedProcess:
    return subprocess.run(command, capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)


def run_regress(*args: str, darc: Path = DARC) -> subprocess.CompletedProcess:
    """scripts/darc-regress ARGS --darc DARC, output captured as text."""
    return run_command([str(DARC_REGRESS), *args, "--darc", str(darc)])


def add_to_region(exr: Path, delta: float, x_end: int = 8, y_end: int = 8) -> None:
    """Adds `delta` to every channel of pixels [0, x_end) x [0, y_end) of `exr`, in place."""
    buf = oiio.ImageBuf(str(exr))
    buf.read(0, 0, True, oiio.FLOAT)
    roi = oiio.ROI(0, x_end, 0, y_end, 0, 1, 0, buf.nchannels)
    changed = oiio.ImageBufAlgo.add(buf, delta, roi=roi)
    oiio.ImageBufAlgo.paste(buf, 0, 0, 0, 0, changed)
    assert buf.write(str(exr), oiio.HALF), buf.geterror()


def junit_cases(out: Path) -> dict[str, ET.Element]:
    """The <testcase> elements of out/junit.xml by name."""
    suite = ET.parse(out / "junit.xml").getroot()
    assert suite.tag == "testsuite", suite.tag
    return {case.get("name"): case for case in suite.iter("testcase")}
