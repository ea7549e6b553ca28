#!/usr/bin/python3
"""ctest farm_task_script: scripts/darc-slurm without a Slurm cluster. `submit --dry-run` writes
the farm folder and the batch script; the test runs the script's array tasks by hand
(SLURM_ARRAY_TASK_ID=i bash SCRIPT, as the script's header says) and checks the logs, the
per-frame stats and what `status` makes of them: a frame with a scene error and a frame the RIB
does not have are failed, a task stopped with SIGTERM leaves its frame missing (interrupted), and
the next submission covers exactly the frames not done. Frames cut into tiles (--tiles) are merged
by the task of their last tile into bitwise the image of a local darc run. Also the usage errors
of `submit`.

    tests/farm/task_script_test.py --darc build/darc --darc-slurm scripts/darc-slurm --scratch DIR
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from farm_images import same_image  # noqa: E402
from farm_scene import frame_rib, write_sequence_rib  # noqa: E402

EXIT_USAGE = 2
# Far above what each step takes (a few seconds): only a hang ends the test.
WAIT_SECONDS = 120
POLL_SECONDS = 0.1


class TestFailure(Exception):
    pass


def check(condition: bool, message: str) -> None:
    if not condition:
        raise TestFailure(message)


def run(command: list[str], expect: int | None = 0, env: dict | None = None) -> subprocess.CompletedProcess:
    r = subprocess.run(command, capture_output=True, text=True, timeout=WAIT_SECONDS, env=env)
    if expect is not None and r.returncode != expect:
        raise TestFailure(f"{' '.join(command)}: exit {r.returncode}, expected {expect}\n"
                          f"stdout:\n{r.stdout}\nstderr:\n{r.stderr}")
    return r


def run_task(script: Path, task: int, expect: int | None = 0) -> subprocess.CompletedProcess:
    return run(["bash", str(script)], expect, dict(os.environ, SLURM_ARRAY_TASK_ID=str(task)))


def status(darc_slurm: str, farm: Path, expect: int) -> dict:
    r = run([darc_slurm, "status", "--dir", str(farm), "--json"], expect)
    return json.loads(r.stdout)


def test_failed_frames(args, scratch: Path) -> None:
    """Frames 1-4 of a RIB with frames 1-3, frame 2 with a scene error; two frames per task."""
    rib = scratch / "three.rib"
    write_sequence_rib(rib, 3, broken_frame=2)
    farm = scratch / "farm"
    submit = [args.darc_slurm, "submit", "--dir", str(farm), "--frames", "1-4", "--chunk", "2", "--darc", args.darc,
              "-o", str(scratch / "out" / "f.%04d.exr"), "--dry-run", str(rib)]
    r = run(submit)
    check("would submit 2 array tasks for frames 1-4" in r.stdout and "--array=0-1" in r.stdout, r.stdout)
    script = farm / "tasks" / "submit-1.sh"
    check(run_task(script, 0, expect=None).returncode == 3, "task 0 (frame 2 has a scene error) should exit 3")
    # darc parses every frame of the RIB, so frames 3 and 4 report frame 2's error and exit 3 too:
    # frame 3's image is written and records no error (done); frame 4 is not in the RIB (failed).
    check(run_task(script, 1, expect=None).returncode == 3, "task 1 should exit 3 (frame 2's error, reported again)")
    check((farm / "logs" / "frame.0003.log").read_text().rstrip().endswith("darc-slurm: exit 3"),
          "frame 3's darc should exit 3 for frame 2's error")
    r = run_task(script, 2, expect=EXIT_USAGE)
    check("no array task 2" in r.stderr, r.stderr)

    s = status(args.darc_slurm, farm, expect=1)
    check(s["done"] == [1, 3], f"done: {s['done']}")
    failed = {f["frame"]: f["reason"] for f in s["failed"]}
    check(sorted(failed) == [2, 4] and s["missing"] == [], f"failed: {s['failed']}, missing: {s['missing']}")
    check(failed[2].startswith("darc exited with 3; the image records 1 scene error: ") and "three.rib:47:1: error: Basis" in failed[2],
          f"frame 2: {failed[2]}")
    check(failed[4] == "the RIB files have no FrameBegin 4 (darc wrote no image)", f"frame 4: {failed[4]}")
    for f in (1, 2, 3):
        stats = json.loads((farm / "stats" / f"frame.{f:04d}.json").read_text())
        check([e["frame"] for e in stats["frames"]] == [f], f"frame {f}'s stats: {stats}")
        log = (farm / "logs" / f"frame.{f:04d}.log").read_text()
        check("'--threads' '1'" in log, f"outside Slurm a task gives darc --threads 1:\n{log}")
    text = run([args.darc_slurm, "status", "--dir", str(farm)], expect=1).stdout
    check(re.search(r"^failed +2  2,4$", text, re.M) is not None and "(log: " in text, f"status:\n{text}")

    # The same command again would submit only the failed frames.
    r = run(submit)
    check("would submit 1 array tasks for frames 2,4" in r.stdout, r.stdout)

    # Submitting another sequence into the folder is refused, saying what differs.
    other = submit[:]
    other[other.index("1-4")] = "1-3"
    r = run(other, expect=EXIT_USAGE)
    check("holds another sequence (frames: 1-4 in the folder, 1-3 now)" in r.stderr, r.stderr)


def test_interrupted_task(args, scratch: Path) -> None:
    """SIGTERM to the task's script while darc renders: the script stops darc and logs it."""
    rib = scratch / "slow.rib"
    write_sequence_rib(rib, 2, slow_frame=1)
    farm = scratch / "farm-interrupted"
    run([args.darc_slurm, "submit", "--dir", str(farm), "--frames", "1-2", "--chunk", "2", "--darc", args.darc,
         "-o", str(scratch / "out-interrupted" / "f.####.exr"), "--dry-run", str(rib)])
    task = subprocess.Popen(["bash", str(farm / "tasks" / "submit-1.sh")], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, env=dict(os.environ, SLURM_ARRAY_TASK_ID="0"))
    try:
        log = farm / "logs" / "frame.0001.log"
        deadline = time.monotonic() + WAIT_SECONDS
        while not (log.exists() and re.search(r"\.exr: \d+% ", log.read_text())):
            check(time.monotonic() < deadline and task.poll() is None, "darc never reported progress on frame 1")
            time.sleep(POLL_SECONDS)
        task.send_signal(signal.SIGTERM)
        check(task.wait(timeout=WAIT_SECONDS) == 128 + signal.SIGTERM, f"task exit {task.returncode}")
    finally:
        if task.poll() is None:
            task.kill()
            task.wait()
    check(log.read_text().rstrip().endswith("darc-slurm: interrupted by SIGTERM"), log.read_text())
    check(not (scratch / "out-interrupted" / "f.0001.exr").exists(), "the interrupted frame's image exists")
    check(not (farm / "logs" / "frame.0002.log").exists(), "the task went on to frame 2 after SIGTERM")
    s = status(args.darc_slurm, farm, expect=1)
    reasons = [(m["frame"], m["reason"]) for m in s["missing"]]
    check(reasons == [(1, "interrupted by SIGTERM (scancel, time limit or preemption)"), (2, "not rendered")],
          f"missing: {reasons}")


def test_rib_per_frame_and_own_threads(args, scratch: Path) -> None:
    """shot.####.rib: each frame reads its own file; --threads after '--' replaces the task's."""
    for f in (1, 2):
        (scratch / f"shot.{f:04d}.rib").write_text(frame_rib(f, 2, 1))
    farm = scratch / "farm-per-frame"
    run([args.darc_slurm, "submit", "--dir", str(farm), "--frames", "1-2", "--darc", args.darc,
         "-o", str(scratch / "out-per-frame" / "f.#.exr"), "--dry-run", str(scratch / "shot.####.rib"),
         "--", "--threads", "2"])
    for task in (0, 1):
        run_task(farm / "tasks" / "submit-1.sh", task)
    for f in (1, 2):
        log = (farm / "logs" / f"frame.{f:04d}.log").read_text()
        check(f"shot.{f:04d}.rib'" in log and log.count("'--threads'") == 1 and "'--threads' '2'" in log, log)
    status(args.darc_slurm, farm, expect=0)


def test_tiled_frames(args, scratch: Path) -> None:
    """--tiles 3 on two frames of the stochastic hider: the tasks render rows, the last tile of a
    frame merges it into bitwise the image of a local darc run, and the tiles go; a frame whose
    last tile was rendered but not merged (its task killed in between) is "not merged", and the
    next submission only merges it."""
    rib = scratch / "tiled.rib"
    write_sequence_rib(rib, 2)
    (scratch / "tiled-local").mkdir()
    run([args.darc, "--quiet", "--hider", "stochastic", "-o", str(scratch / "tiled-local" / "f.####.exr"), str(rib)])
    farm = scratch / "farm-tiled"
    out = scratch / "out-tiled"
    submit = [args.darc_slurm, "submit", "--dir", str(farm), "--frames", "1-2", "--tiles", "3", "--darc", args.darc,
              "-o", str(out / "f.####.exr"), "--dry-run", str(rib), "--", "--hider", "stochastic"]
    r = run(submit)
    check("would submit 6 array tasks for frames 1-2 (6 tiles, 0 merges)" in r.stdout, r.stdout)
    script = farm / "tasks" / "submit-1.sh"
    for task in (0, 1, 2):  # frame 1's three rows: the third task merges them
        run_task(script, task)
    check(same_image(out / "f.0001.exr", scratch / "tiled-local" / "f.0001.exr") == "",
          same_image(out / "f.0001.exr", scratch / "tiled-local" / "f.0001.exr"))
    check(not list((farm / "tiles").glob("frame.0001.tile.*")), "frame 1's tiles are left after the merge")
    log = (farm / "logs" / "frame.0001.tile.2.log").read_text()
    check("'--crop' '0' '1' '0.3333333333333333' '0.6666666666666666'" in log, f"tile 2's crop:\n{log}")
    merges = (farm / "logs" / "frame.0001.log").read_text()
    check(merges.count("darc-slurm: frame 1 merge, task") == 3 and "merged 3 tiles into" in merges and
          merges.count("tiles rendered; the task of the last one merges them") == 2, f"frame 1's merges:\n{merges}")

    for task in (3, 4):  # frame 2's first two rows
        run_task(script, task)
    s = status(args.darc_slurm, farm, expect=1)
    check(s["done"] == [1] and s["tiles"] == 3, f"status: {s}")
    check(s["missing"][0]["reason"] == "2 of 3 tiles done; tile 3: not rendered" and
          s["missing"][0]["tiles"] == {"done": [1, 2], "failed": [], "missing": [3]}, f"missing: {s['missing']}")
    check("would submit 1 array tasks for frames 2 (1 tile, 0 merges)" in run(submit).stdout, "only tile 3 of frame 2")

    # Frame 2's last row rendered as its task would, then the task killed before the merge.
    crop = ["--crop", "0", "1", repr(2 / 3), "1"]
    run([args.darc, "--quiet", "--frames", "2", "--hider", "stochastic", *crop,
         "-o", str(farm / "tiles" / "frame.0002.tile.3.exr"), str(rib)])
    s = status(args.darc_slurm, farm, expect=1)
    check(s["missing"][0]["reason"] == "all 3 tiles done, not merged", f"missing: {s['missing']}")
    r = run(submit)
    check("would submit 1 array tasks for frames 2 (0 tiles, 1 merge)" in r.stdout, r.stdout)
    run_task(script, 0)  # a dry run writes its script as submission 1 again: now only the merge
    status(args.darc_slurm, farm, expect=0)
    check(same_image(out / "f.0002.exr", scratch / "tiled-local" / "f.0002.exr") == "",
          same_image(out / "f.0002.exr", scratch / "tiled-local" / "f.0002.exr"))
    check(sorted(p.name for p in out.iterdir()) == ["f.0001.exr", "f.0002.exr"], f"{list(out.iterdir())}")
    check("nothing to submit: 2 of 2 frames done" in run(submit).stdout, "a third submission")


def test_usage_errors(args, scratch: Path) -> None:
    rib = scratch / "three.rib"
    base = [args.darc_slurm, "submit", "--dir", str(scratch / "farm-usage"), "--frames", "1-3", "--darc", args.darc,
            "--dry-run"]
    cases = [
        (["-o", "no-pattern.exr", str(rib)], "needs the frame number in the name"),
        (["-o", "f.#.exr", str(rib), "--", "--frames", "2"], "darc-slurm sets --frames itself"),
        (["-o", "f.#.exr", str(rib), "--", "-ox.exr"], "darc-slurm sets -o itself"),
        (["-o", "f.#.exr", str(scratch / "nothing.rib")], "no such RIB file"),
        (["-o", "f.#.exr", "--chunk", "0", str(rib)], "--chunk must be at least 1"),
        (["-o", "f.#.exr", "-"], "cannot read RIB from standard input"),
        (["-o", "f.#.exr", "--tiles", "0", str(rib)], "--tiles must be from 1 to 999"),
        (["-o", "f.#.png", "--tiles", "2", str(rib)], "--tiles needs an EXR image"),
        (["-o", "f.#.exr", "--tiles", "2", str(rib), "--", "--crop", "0", "1", "0", "1"], "not with --tiles"),
        (["-o", "f.#.exr", "--tiles", "2", str(rib), "--", "--preview=p.#.png"], "not with --tiles"),
    ]
    for extra, message in cases:
        r = run(base + extra, expect=EXIT_USAGE)
        check(message in r.stderr, f"{extra}: expected '{message}' in:\n{r.stderr}")
    frames = base[:]
    frames[frames.index("1-3")] = "3-1"
    r = run(frames + ["-o", "f.#.exr", str(rib)], expect=EXIT_USAGE)
    check('--frames: bad frame list item "3-1"' in r.stderr, r.stderr)
    r = run([args.darc_slurm, "status", "--dir", str(scratch / "no-farm")], expect=EXIT_USAGE)
    check("is not a darc-slurm farm folder" in r.stderr, r.stderr)
    r = run([args.darc_slurm, "merge", "--dir", str(scratch / "farm"), "--frame", "1"], expect=EXIT_USAGE)
    check("its frames are not cut into tiles" in r.stderr, r.stderr)


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--darc", required=True)
    p.add_argument("--darc-slurm", required=True)
    p.add_argument("--scratch", required=True, type=Path)
    args = p.parse_args()
    args.darc, args.darc_slurm = os.path.abspath(args.darc), os.path.abspath(args.darc_slurm)
    scratch = args.scratch.resolve()
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir(parents=True)
    os.chdir(scratch)  # relative -o names in the usage cases land here
    tests = (test_failed_frames, test_interrupted_task, test_rib_per_frame_and_own_threads, test_tiled_frames,
             test_usage_errors)
    failures = 0
    for test in tests:
        try:
            test(args, scratch)
            print(f"farm_task_script: {test.__name__}: passed", flush=True)
        except TestFailure as e:
            failures += 1
            print(f"farm_task_script: {test.__name__}: FAILED: {e}", flush=True)
    print(f"{len(tests) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
