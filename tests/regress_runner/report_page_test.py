#!/usr/bin/python3
"""The HTML report is a page people open: headless Chromium loads index.html from disk for a
suite with every verdict (pass, warn, fail, error), and the page's own check (#image-check,
written by an inline script on load) must say that every image loaded; the verdicts must show.
A report with a PNG removed must say "broken", so the check cannot pass by not running.
Exits with 77 (ctest's SKIP_RETURN_CODE for this test) when no Chromium is installed."""

import re
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import scratch_suite  # noqa: E402
from scratch_suite import add_to_region, run_regress  # noqa: E402

SKIP = 77
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def dump_dom(page: Path) -> str:
    """The page's DOM after load, as headless Chromium sees it."""
    with tempfile.TemporaryDirectory(prefix="darc-chromium-") as profile:
        done = subprocess.run(
            [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", f"--user-data-dir={profile}",
             "--dump-dom", page.as_uri()],
            capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL,
        )
    assert done.returncode == 0, f"chromium exited with {done.returncode}:\n{done.stderr}"
    return done.stdout


def image_check(dom: str) -> str:
    found = re.search(r'<span id="image-check">([^<]*)</span>', dom)
    assert found, "no #image-check element in the page"
    return found.group(1)


class ReportPage(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # sphere passes; strands warns; changed fails; unapproved errs (no golden image).
        cls.scratch = scratch_suite.scratch_folder("page")
        suite = scratch_suite.make_suite(cls.scratch / "suite")
        (suite / "changed.rib").write_text(scratch_suite.SPHERE_RIB)
        cls.out = cls.scratch / "out"
        done = run_regress(str(suite), "--out", str(cls.out), "--update", "sphere", "strands", "changed")
        assert done.returncode == 0, done.stdout + done.stderr
        add_to_region(suite / "golden" / "strands.exr", 1e-3)
        add_to_region(suite / "golden" / "changed.exr", 0.25)
        (suite / "unapproved.rib").write_text(scratch_suite.SPHERE_RIB)
        cls.regress = run_regress(str(suite), "--out", str(cls.out))

    @classmethod
    def tearDownClass(cls):
        scratch_suite.remove(cls.scratch)

    def test_every_image_loads_and_every_verdict_shows(self):
        self.assertEqual(self.regress.returncode, 1, self.regress.stdout + self.regress.stderr)
        dom = dump_dom(self.out / "index.html")
        # Three images (golden, new, difference) per compared test; the new one only without a golden.
        self.assertEqual(image_check(dom), "all 10 images loaded")
        for name, verdict in (("sphere", "pass"), ("strands", "warn"), ("changed", "fail"), ("unapproved", "error")):
            section = re.search(rf'<section id="test-{name}" class="test (\w+)"><h2>{name} <span class="verdict (\w+)">(\w+)</span>', dom)
            self.assertIsNotNone(section, name)
            self.assertEqual(section.groups(), (verdict, verdict, verdict), name)
        self.assertIn("4 tests: 1 pass, 1 warn, 1 fail, 1 error", dom)
        self.assertIn("--update unapproved", dom)

    def test_a_missing_image_shows_as_broken(self):
        broken = self.scratch / "broken"
        shutil.copytree(self.out, broken)
        (broken / "images" / "changed.difference.png").unlink()
        self.assertEqual(image_check(dump_dom(broken / "index.html")), "broken: images/changed.difference.png")


if __name__ == "__main__":
    if CHROMIUM is None:
        print("SKIPPED: no chromium on PATH (scripts/setup installs Debian's chromium; it could not here)")
        sys.exit(SKIP)
    unittest.main(verbosity=2)
