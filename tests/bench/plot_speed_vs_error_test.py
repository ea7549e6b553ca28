#!/usr/bin/python3
"""bench/plot_speed_vs_error.py on small CSVs of both kinds the benchmark writes (settings and
contribution-threshold sweeps): the PNG is written at the plot's size, and the SVG beside it holds
one legend entry per line, the axis labels, dashes for the distance hider only, and the title the
CSV calls for. Malformed CSVs fail with exit status 1, a message naming the file, line and
problem, and no output file.

Exits with 77 (ctest's SKIP_RETURN_CODE for this test) when matplotlib is not installed
(scripts/setup --bench installs it); under CI (CI=true), whose .ci/run installs it, that fails
instead."""

import os
import re
import struct
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

SKIP = 77
SCRIPT = Path(__file__).resolve().parents[2] / "bench" / "plot_speed_vs_error.py"
# The figure's size in pixels (FIGURE_WIDTH_PX, FIGURE_HEIGHT_PX in the script).
PNG_SIZE = (1180, 720)
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"

SETTINGS_CSV = """scene,hider,samples,seconds,rmse,max_error
furball,distance,1,0.0615515,0.00440231,0.108379
furball,distance,4,0.134704,0.0014943,0.0352208
furball,stochastic,1,0.00749075,0.0875645,0.990225
furball,stochastic,4,0.027744,0.0347186,0.652344
furball,stochastic,16,0.102,0.0134,0.4
furball,embree,1,0.0051,0.09,0.99
furball,embree,4,0.019,0.035,0.65
grass,distance,1,0.089,0.0019,0.05
grass,stochastic,1,0.0053,0.026,0.9
grass,stochastic,4,0.02,0.0103,0.5
"""

# The columns of speed-vs-error-secondary-pruning.csv; one line per scene, hider and samples.
SWEEP_HEADER = ("scene,hider,samples,threshold,seconds,runs,primary_rays,traced_shadow,traced_reflection,"
                "traced_refraction,pruned_shadow,pruned_reflection,pruned_refraction,rmse_vs_unpruned,"
                "max_vs_unpruned,rmse_vs_reference,max_vs_reference")


def sweep_row(scene, hider, samples, threshold, seconds, rmse_vs_reference):
    return f"{scene},{hider},{samples},{threshold},{seconds},2,307200,1,0,0,0,0,0,0,0,{rmse_vs_reference},0.2"


SWEEP_CSV = "\n".join([
    SWEEP_HEADER,
    sweep_row("hair-shadow", "distance", 1, 0, 1.87, 0.00904),
    sweep_row("hair-shadow", "distance", 1, 0.0001, 1.56, 0.00904),
    sweep_row("hair-shadow", "distance", 1, 0.1, 0.88, 0.0286),
    sweep_row("hair-shadow", "stochastic", 4, 0, 1.02, 0.0296),
    sweep_row("hair-shadow", "stochastic", 4, 0.1, 0.90, 0.0296),
]) + "\n"


def png_size(path: Path):
    """Width and height from the PNG's IHDR chunk, which the format puts first."""
    data = path.read_bytes()
    if data[:8] != PNG_SIGNATURE or data[12:16] != b"IHDR":
        raise AssertionError(f"{path} is not a PNG file")
    return struct.unpack(">II", data[16:24])


def svg_texts(svg: str):
    """The text elements of the SVG (matplotlib writes text as <text> with svg.fonttype none),
    in document order."""
    return [re.sub(r"\s+", " ", t).strip() for t in re.findall(r"<text[^>]*>([^<]*)</text>", svg)]


class PlotTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="darc-plot-")
        self.dir = Path(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def plot(self, csv_text: str, *extra):
        csv_path = self.dir / "in.csv"
        csv_path.write_text(csv_text)
        png, svg = self.dir / "out.png", self.dir / "out.svg"
        run = subprocess.run([str(SCRIPT), str(csv_path), str(png), "--svg", str(svg), *extra],
                             capture_output=True, text=True, timeout=120)
        return run, csv_path, png, svg

    def plotted(self, csv_text: str, *extra):
        run, _, png, svg = self.plot(csv_text, *extra)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(png_size(png), PNG_SIZE)
        self.assertGreater(png.stat().st_size, 10_000, "a plot with lines, markers and text, not a blank image")
        return svg.read_text()

    def test_settings_csv_one_line_per_scene_and_hider(self):
        svg = self.plotted(SETTINGS_CSV, "--scenes-label", "large")
        texts = svg_texts(svg)
        legend = [t for t in texts if re.fullmatch(r"(furball|grass) (stochastic|distance|embree)", t)]
        self.assertEqual(legend, ["furball stochastic", "furball distance", "furball embree",
                                  "grass stochastic", "grass distance"], "scenes in CSV order, then the hiders")
        self.assertIn("render time (s)", texts)
        self.assertIn("RMSE against the reference (scene-linear RGBA)", texts)
        self.assertIn("darc: RMSE against render time (large scenes; solid: stochastic, dashed: distance, "
                      "pale: Embree)", texts)
        self.assertIn("stroke-dasharray", svg, "the distance hider's lines are dashed")
        for tick in ("0.01", "0.1"):
            self.assertIn(tick, texts, "decades labelled as plain numbers")

    def test_only_the_distance_hider_is_dashed(self):
        stochastic_only = "\n".join(line for line in SETTINGS_CSV.splitlines() if ",distance," not in line) + "\n"
        svg = self.plotted(stochastic_only)
        self.assertNotIn("stroke-dasharray", svg)
        self.assertIn("darc: RMSE against render time (solid: stochastic, dashed: distance, pale: Embree)",
                      svg_texts(svg))

    def test_sweep_csv_one_line_per_scene_hider_and_samples(self):
        svg = self.plotted(SWEEP_CSV)
        texts = svg_texts(svg)
        self.assertEqual([t for t in texts if t.startswith("hair-shadow ")],
                         ["hair-shadow distance 1x1", "hair-shadow stochastic 2x2"])
        self.assertIn("darc: contribution thresholds 0, 0.0001 .. 0.1 along each line (RMSE against the reference)",
                      texts)

    def test_title_option_replaces_the_default(self):
        self.assertIn("a given title", svg_texts(self.plotted(SETTINGS_CSV, "--title", "a given title")))

    def assert_fails(self, csv_text: str, *expected_in_message):
        run, csv_path, png, svg = self.plot(csv_text)
        self.assertEqual(run.returncode, 1, run.stderr)
        self.assertTrue(run.stderr.startswith("plot_speed_vs_error: error: "), run.stderr)
        self.assertIn(str(csv_path), run.stderr)
        for part in expected_in_message:
            self.assertIn(part, run.stderr)
        self.assertFalse(png.exists(), "no PNG from a CSV that cannot be plotted")
        self.assertFalse(svg.exists())
        self.assertEqual(sorted(p.name for p in self.dir.iterdir()), ["in.csv"], "no temporary file left either")

    def test_a_missing_column_is_an_error(self):
        self.assert_fails("scene,hider,samples,seconds\nfurball,distance,1,0.06\n", ":1: no column 'rmse'")

    def test_a_value_that_is_no_number_is_an_error_at_its_line(self):
        bad = SETTINGS_CSV.replace("furball,distance,4,0.134704", "furball,distance,4,fast")
        self.assert_fails(bad, ":3: column 'seconds' is not a number: 'fast'")

    def test_a_row_with_missing_fields_is_an_error_at_its_line(self):
        self.assert_fails(SETTINGS_CSV + "grass,stochastic,16\n", ":12: 3 fields, the header has 6")

    def test_an_empty_file_is_an_error(self):
        self.assert_fails("", "empty file")

    def test_no_positive_point_is_an_error(self):
        self.assert_fails("scene,hider,samples,seconds,rmse,max_error\nfurball,distance,1,0,0.1,0.2\n",
                          "no row with a positive time and RMSE")

    def test_an_unreadable_file_is_an_error(self):
        missing = self.dir / "missing.csv"
        run = subprocess.run([str(SCRIPT), str(missing), str(self.dir / "out.png")], capture_output=True, text=True,
                             timeout=120)
        self.assertEqual(run.returncode, 1)
        self.assertIn(f"{missing}: cannot read", run.stderr)


def matplotlib_missing() -> bool:
    # The script runs under Debian's python3 (its #! line), which is where the package installs.
    return subprocess.run(["/usr/bin/python3", "-c", "import matplotlib"], capture_output=True).returncode != 0


if __name__ == "__main__":
    if matplotlib_missing():
        reason = "matplotlib is not installed for /usr/bin/python3 (scripts/setup --bench installs python3-matplotlib)"
        if os.environ.get("CI"):
            print(f"FAILED: {reason}; CI must run this test (.ci/run calls scripts/setup --bench)", file=sys.stderr)
            sys.exit(1)
        print(f"SKIPPED: {reason}")
        sys.exit(SKIP)
    unittest.main(verbosity=2)
