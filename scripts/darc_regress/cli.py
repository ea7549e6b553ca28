"""darc-regress's command line: which tests, how many at once, what to approve, and the exit
code (0 all passed, warnings allowed; 1 a test failed or errored; 2 usage error)."""

from __future__ import annotations

import argparse
import concurrent.futures
import fnmatch
import os
import shlex
import shutil
import sys
import time
import traceback
from pathlib import Path

from darc_regress.comparison import ERROR, VERDICTS
from darc_regress.html_report import write_html
from darc_regress.junit_report import write_junit
from darc_regress.outcome import IMAGES_FOLDER, RENDERS_FOLDER, RunSettings, TestOutcome, run_test
from darc_regress.render import RenderResult
from darc_regress.suite import SuiteError, TestCase, load_suite

EXIT_PASSED, EXIT_FAILED, EXIT_USAGE = 0, 1, 2
DEFAULT_OUT = "darc-regress-out"
REPOSITORY = Path(__file__).resolve().parents[2]  # scripts/darc_regress/cli.py


def _cores() -> int:
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="darc-regress",
        description="Render every NAME.rib of SUITE with darc and compare it with SUITE/golden/NAME.exr "
        "(thresholds and darc arguments in SUITE/regress.toml). Exit code 0: every test passed "
        "(warnings allowed); 1: a test failed or errored; 2: usage error.",
    )
    p.add_argument("suite", metavar="SUITE", help="the suite folder")
    p.add_argument("--out", metavar="DIR", default=DEFAULT_OUT,
                   help=f"where index.html, junit.xml, renders/ and images/ go (default: ./{DEFAULT_OUT})")
    p.add_argument("--update", metavar="NAME", nargs="*",
                   help="approve these tests' new renders as their golden images (shell patterns allowed; "
                   "every test: --update '*'); the whole suite is still rendered and reported")
    p.add_argument("--jobs", metavar="N", type=int, default=_cores(),
                   help="tests rendered at once (default: the number of cores)")
    p.add_argument("--darc", metavar="PATH", default=str(REPOSITORY / "build" / "darc"),
                   help="the darc command (default: build/darc of this repository)")
    return p


def _tests_to_approve(patterns: list[str] | None, cases: list[TestCase], parser) -> set[str]:
    if patterns is None:
        return set()
    if not patterns:
        parser.error("--update needs the names of the tests to approve (every test: --update '*')")
    names = [c.name for c in cases]
    chosen = set()
    for pattern in patterns:
        matched = fnmatch.filter(names, pattern)
        if not matched:
            parser.error(f"--update {pattern}: no such test in the suite (tests: {', '.join(names)})")
        chosen.update(matched)
    return chosen


def _update_command(args) -> str:
    """The command line that approves tests (their names follow), as this run was called."""
    words = [sys.argv[0], args.suite]
    if args.darc != _parser().get_default("darc"):
        words += ["--darc", args.darc]
    return shlex.join(words + ["--update"])


def _run_safely(case: TestCase, settings: RunSettings, approve: bool) -> TestOutcome:
    """A bug of the runner in one test is that test's error, not a lost report."""
    try:
        return run_test(case, settings, approve)
    except Exception:  # noqa: BLE001 -- reported in the test's outcome
        empty = RenderResult([], None, "", 0.0, settings.out / RENDERS_FOLDER / f"{case.name}.exr")
        return TestOutcome(case, ERROR, "darc-regress failed:\n" + traceback.format_exc(), empty)


def _clear_outputs(out: Path) -> None:
    """Only what an earlier run wrote, so a stale image can never appear in this report."""
    for folder in (RENDERS_FOLDER, IMAGES_FOLDER):
        shutil.rmtree(out / folder, ignore_errors=True)
        (out / folder).mkdir(parents=True)
    for name in ("index.html", "junit.xml"):
        (out / name).unlink(missing_ok=True)


def _print_outcome(o: TestOutcome) -> None:
    approved = f"  approved as {o.case.golden}" if o.approved else ""
    print(f"{o.verdict:5}  {o.case.name}  ({o.render.seconds:.2f} s){approved}", flush=True)
    if o.verdict != "pass":
        for line in o.message.splitlines():
            print(f"       {line}", flush=True)


def main(argv: list[str] | None = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    darc = Path(args.darc)
    if not (darc.is_file() and os.access(darc, os.X_OK)):
        parser.error(f"no darc command at {darc} (build it with scripts/build, or pass --darc PATH)")
    suite_folder = Path(args.suite)
    try:
        cases = load_suite(suite_folder)
    except SuiteError as e:
        print(f"darc-regress: {e}", file=sys.stderr)
        return EXIT_USAGE
    approve = _tests_to_approve(args.update, cases, parser)
    out = Path(args.out).resolve()
    _clear_outputs(out)
    jobs = min(args.jobs, len(cases))
    settings = RunSettings(darc.resolve(), out, max(1, _cores() // jobs), _update_command(args))

    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(_run_safely, c, settings, c.name in approve) for c in cases]
        for f in concurrent.futures.as_completed(futures):
            _print_outcome(f.result())
        outcomes = [f.result() for f in futures]  # in the suite's order
    seconds = time.monotonic() - start

    suite_name = suite_folder.resolve().name
    counts = ", ".join(f"{sum(o.verdict == v for o in outcomes)} {v}" for v in VERDICTS)
    summary = f"{len(outcomes)} tests: {counts}; {seconds:.1f} s (--jobs {jobs}), darc {settings.darc}"
    write_html(outcomes, suite_name, summary, out / "index.html")
    write_junit(outcomes, suite_name, seconds, out / "junit.xml")
    print(summary)
    print(f"report: {out / 'index.html'}\njunit:  {out / 'junit.xml'}")
    return EXIT_FAILED if any(o.failed for o in outcomes) else EXIT_PASSED
