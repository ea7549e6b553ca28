#!/usr/bin/python3
"""Tests of scripts/darc-regress itself, on a tiny suite in a scratch folder: an unchanged suite
passes; a changed golden image fails with one <failure> in the JUnit file; a missing golden image
fails with the command that creates it, and that command makes it pass; a difference under `fail`
but over `warn` passes with a warn verdict; a render that fails, or whose image carries
darc:errors, is an error with darc's message; usage errors exit with 2.
ctest runs it (tests/CMakeLists.txt); by hand: tests/regress_runner/runner_test.py."""

import shlex
import shutil
import stat
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import scratch_suite  # noqa: E402
from scratch_suite import add_to_region, junit_cases, run_regress  # noqa: E402


class DarcRegress(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # Render and approve the suite once; every test starts from a copy of it.
        cls.pristine = scratch_suite.scratch_folder("pristine")
        suite = scratch_suite.make_suite(cls.pristine / "suite")
        done = run_regress(str(suite), "--out", str(cls.pristine / "out"), "--update", "*")
        assert done.returncode == 0, done.stdout + done.stderr
        shutil.rmtree(cls.pristine / "out")

    @classmethod
    def tearDownClass(cls):
        scratch_suite.remove(cls.pristine)

    def setUp(self):
        self.scratch = scratch_suite.scratch_folder("test")
        self.suite = self.scratch / "suite"
        shutil.copytree(self.pristine / "suite", self.suite)
        self.out = self.scratch / "out"

    def tearDown(self):
        scratch_suite.remove(self.scratch)

    def run_suite(self, *extra: str):
        return run_regress(str(self.suite), "--out", str(self.out), *extra)

    def assert_exit(self, done, code: int):
        self.assertEqual(done.returncode, code, f"stdout:\n{done.stdout}\nstderr:\n{done.stderr}")

    def test_an_unchanged_suite_passes_and_reaches_darc_with_the_tests_arguments(self):
        done = self.run_suite()
        self.assert_exit(done, 0)
        cases = junit_cases(self.out)
        self.assertEqual(sorted(cases), ["sphere", "strands"])
        self.assertEqual(sum(len(c.findall("failure")) for c in cases.values()), 0)
        self.assertIn("--pixel-samples 2", cases["strands"].findtext("system-out"))
        self.assertNotIn("--pixel-samples", cases["sphere"].findtext("system-out"))
        for name in ("sphere", "strands"):
            for kind in ("golden", "new", "difference"):
                self.assertTrue((self.out / "images" / f"{name}.{kind}.png").is_file(), (name, kind))
        self.assertTrue((self.out / "index.html").is_file())

    def test_a_changed_image_fails_with_one_junit_failure(self):
        add_to_region(self.suite / "golden" / "sphere.exr", 0.25)
        done = self.run_suite()
        self.assert_exit(done, 1)
        cases = junit_cases(self.out)
        failures = [(name, f) for name, c in cases.items() for f in c.findall("failure")]
        self.assertEqual(len(failures), 1, failures)
        name, failure = failures[0]
        self.assertEqual(name, "sphere")
        self.assertEqual(failure.get("type"), "fail")
        self.assertIn("differ by more than fail 1e-06", failure.get("message"))
        self.assertIn("64 pixels over fail", failure.get("message"))  # the 8x8 changed pixels
        self.assertIn("fail   sphere", done.stdout)

    def test_the_command_to_approve_names_a_darc_given_with_darc(self):
        (self.suite / "golden" / "strands.exr").unlink()
        darc_link = self.scratch / "my-darc"
        darc_link.symlink_to(scratch_suite.DARC)
        self.assert_exit(run_regress(str(self.suite), "--out", str(self.out), darc=darc_link), 1)
        message = junit_cases(self.out)["strands"].find("failure").get("message")
        self.assertIn(f"--darc {darc_link} --update strands", message)

    def test_a_missing_golden_image_fails_saying_how_to_create_it(self):
        (self.suite / "golden" / "strands.exr").unlink()
        done = self.run_suite()
        self.assert_exit(done, 1)
        failure = junit_cases(self.out)["strands"].find("failure")
        self.assertEqual(failure.get("type"), "error")
        message = failure.get("message")
        self.assertIn("no golden image", message)
        command = message.split("run: ", 1)[1]
        self.assertTrue(command.endswith("--update strands"), command)
        # The command it gives, run as given, approves the image; then the suite passes.
        approve = shlex.split(command)
        self.assertEqual(approve[:2], [str(scratch_suite.DARC_REGRESS), str(self.suite)])
        self.assert_exit(scratch_suite.run_command(approve + ["--out", str(self.out)]), 0)
        self.assertTrue((self.suite / "golden" / "strands.exr").is_file())
        self.assert_exit(self.run_suite(), 0)

    def test_update_approves_a_changed_image(self):
        add_to_region(self.suite / "golden" / "sphere.exr", 0.25)
        done = self.run_suite("--update", "sphere")
        self.assert_exit(done, 0)
        self.assertIn("approved as", done.stdout)
        self.assert_exit(self.run_suite(), 0)

    def test_a_difference_over_warn_only_passes_with_a_warn_verdict(self):
        add_to_region(self.suite / "golden" / "strands.exr", 1e-3)  # strands: warn 1e-4, fail 0.01
        done = self.run_suite()
        self.assert_exit(done, 0)
        self.assertIn("warn   strands", done.stdout)
        cases = junit_cases(self.out)
        self.assertIsNone(cases["strands"].find("failure"))
        self.assertTrue(cases["strands"].findtext("system-out").startswith("verdict: warn"))
        self.assertIn('<span class="verdict warn">warn</span>', (self.out / "index.html").read_text())

    def test_a_different_image_size_fails(self):
        (self.suite / "sphere.rib").write_text(scratch_suite.SPHERE_RIB.replace("Format 32 24", "Format 24 24"))
        done = self.run_suite()
        self.assert_exit(done, 1)
        message = junit_cases(self.out)["sphere"].find("failure").get("message")
        self.assertIn("the new image is 24x24", message)

    def test_a_failed_render_is_an_error_with_darcs_message(self):
        (self.suite / "broken.rib").write_text(scratch_suite.BROKEN_RIB)
        done = self.run_suite()
        self.assert_exit(done, 1)
        failure = junit_cases(self.out)["broken"].find("failure")
        self.assertEqual(failure.get("type"), "error")
        self.assertIn("darc exited with code 3", failure.get("message"))
        self.assertIn("Sphere", failure.get("message"))  # darc's own error line names the request
        self.assertIn("error  broken", done.stdout)

    def test_an_image_with_darc_errors_is_an_error_with_the_first_error(self):
        # A darc that renders, then marks the image as darc does for a scene with errors.
        fake = self.scratch / "darc-with-errors"
        fake.write_text(
            "#!/usr/bin/python3\n"
            "import subprocess, sys, OpenImageIO as oiio\n"
            f"code = subprocess.call([{str(scratch_suite.DARC)!r}] + sys.argv[1:])\n"
            "out = sys.argv[sys.argv.index('-o') + 1]\n"
            "buf = oiio.ImageBuf(out); buf.read(0, 0, True, oiio.FLOAT)\n"
            "buf.specmod().attribute('darc:errors', 2)\n"
            "buf.specmod().attribute('darc:first_error', 'scene.rib:3:1: error: a test error')\n"
            "buf.write(out, oiio.HALF)\n"
            "sys.exit(code)\n"
        )
        fake.chmod(fake.stat().st_mode | stat.S_IXUSR)
        done = run_regress(str(self.suite), "--out", str(self.out), darc=fake)
        self.assert_exit(done, 1)
        for case in junit_cases(self.out).values():
            failure = case.find("failure")
            self.assertEqual(failure.get("type"), "error")
            self.assertIn("darc:errors = 2: scene.rib:3:1: error: a test error", failure.get("message"))

    def test_usage_errors_exit_with_2(self):
        self.assert_exit(run_regress(str(self.scratch / "no-such-suite")), 2)
        self.assert_exit(self.run_suite("--update", "no-such-test"), 2)
        self.assert_exit(self.run_suite("--update"), 2)
        self.assert_exit(self.run_suite("--jobs", "0"), 2)
        (self.suite / "regress.toml").write_text("[defaults]\nfial = 1\n")
        done = self.run_suite()
        self.assert_exit(done, 2)
        self.assertIn("unknown key 'fial'", done.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
