"""darc-slurm's command line: `submit` (the sequence's frames not yet done, as one Slurm array job;
with --tiles, their tiles), `status` (done / missing / failed frames) and `merge` (a tiled frame's
tiles into its image, as the array tasks do). Exit codes: 0 success (status: every frame done);
1 a Slurm command failed, jobs of the folder are still queued (submit), frames are not done
(status, submit --wait), or tiles could not be merged; 2 usage error."""

from __future__ import annotations

import argparse
import datetime
import json
import os
import shlex
import sys
import time
from pathlib import Path

from darc_slurm.farm_folder import FarmFolder, FarmFolderError, Sequence, Submission
from darc_slurm.frame_status import DONE, FAILED, MISSING, FrameStatus, sequence_status
from darc_slurm.frames import (FrameListError, chunks, format_frame_list, has_frame_pattern, parse_frame_list,
                               split_frame_pattern, substitute_frame_number)
from darc_slurm.slurm import SbatchOptions, SlurmError, active_jobs, sbatch_command, submit
from darc_slurm.task_script import task_script
from darc_slurm.tile_merge import MergeError, merge_tiles
from darc_slurm.tiles import MAX_TILES

EXIT_OK, EXIT_FAILED, EXIT_USAGE = 0, 1, 2
DEFAULT_FOLDER = "darc-farm"
REPOSITORY = Path(__file__).resolve().parents[2]  # scripts/darc_slurm/cli.py
DARC_SLURM = REPOSITORY / "scripts" / "darc-slurm"  # what the array tasks run to merge tiles
# submit --wait asks squeue this often whether the jobs are still there: a few seconds is nothing
# beside a frame's render, and well within what a scheduler takes from one user.
WAIT_POLL_SECONDS = 3.0
# darc options that each task sets itself, per frame.
OWN_DARC_OPTIONS = ("--frames", "--output", "--stats", "--skip-existing", "--cat")
# darc options that --tiles cannot take: each tile sets its --crop, and one preview per tile would
# be the preview of a row, each over the last.
OWN_TILE_OPTIONS = ("--crop", "--preview")


class UsageError(Exception):
    pass


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="darc-slurm",
        description="Render a darc frame sequence on a Slurm cluster as an array job, resume it after "
        "failures, and list which frames are done, missing or failed. The farm folder (--dir) holds the "
        "sequence, its jobs, and each frame's log and stats. Exit codes: 0 success; 1 a Slurm command "
        "failed, frames are not done, or tiles could not be merged; 2 usage error.")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    s = sub.add_parser(
        "submit", help="submit the frames that are not done yet",
        usage="darc-slurm submit --frames LIST -o IMAGE [options] RIB... [-- DARC OPTIONS...]",
        description="Submit the sequence's frames that are not done (missing or failed) as one Slurm array "
        "job; each array task renders a chunk of them, one darc run per frame, with --skip-existing. Run "
        "the same command again after failures: it submits only what is still missing. Options after "
        "'--' go to darc (e.g. -- --hider stochastic --pixel-samples 4).")
    s.add_argument("ribs", metavar="RIB", nargs="+",
                   help="RIB files, given to darc in this order; a '#' run or %%04d in a name makes it one file "
                   "per frame (shot.####.rib)")
    s.add_argument("--frames", required=True, metavar="LIST", help="the sequence's frames, e.g. 1-240 or 1-10,15,20-40x5")
    s.add_argument("-o", "--output", required=True, metavar="IMAGE",
                   help="image of each frame, with a '#' run or %%04d for the frame number (out/shot.####.exr)")
    s.add_argument("--dir", default=DEFAULT_FOLDER, metavar="DIR", help=f"the farm folder (default: ./{DEFAULT_FOLDER})")
    s.add_argument("--chunk", type=int, default=1, metavar="N",
                   help="frames per array task (tiles, with --tiles; default 1)")
    s.add_argument("--tiles", type=int, default=1, metavar="N",
                   help="cut each frame into N rows, top to bottom, rendered by their own array tasks (darc --crop) "
                   "and merged into the frame's image, bitwise the image one darc run renders; needs an EXR "
                   "output and fewer tiles than the image has pixel rows (default 1: whole frames)")
    s.add_argument("--max-running", type=int, metavar="N", help="array tasks running at once (sbatch --array ...%%N)")
    slurm = s.add_argument_group("Slurm options (passed to sbatch)")
    slurm.add_argument("--partition", metavar="NAME")
    slurm.add_argument("--time", metavar="LIMIT", help="time limit of each array task (e.g. 2:00:00)")
    slurm.add_argument("--mem", metavar="SIZE", help="memory per task's node (e.g. 8G)")
    slurm.add_argument("--cpus-per-task", type=int, metavar="N",
                       help="CPUs of each task, and darc's --threads (default: what Slurm allocates, often 1)")
    slurm.add_argument("--job-name", metavar="NAME", help="default: darc-IMAGE NAME")
    slurm.add_argument("--sbatch-arg", action="append", default=[], metavar="ARG",
                       help="any other sbatch argument, one per use: --sbatch-arg=--account=vfx")
    s.add_argument("--darc", default=str(REPOSITORY / "build" / "darc"), metavar="PATH",
                   help="the darc command the nodes run (default: build/darc of this repository; the nodes must "
                   "see it, the RIB files and the output folder at the same paths)")
    s.add_argument("--wait", action="store_true",
                   help="wait until the folder's jobs have left the queue, then print the status "
                   "(exit code 0 only if every frame is done)")
    s.add_argument("--dry-run", action="store_true",
                   help="write the farm folder and the task script, print the sbatch command, submit nothing")
    s.add_argument("--force", action="store_true",
                   help="submit although earlier jobs of the folder are still queued or running (their frames are "
                   "left out)")

    t = sub.add_parser("status", help="list done, missing and failed frames",
                       description="List the sequence's done, missing and failed frames (failed: darc exited non-zero, "
                       "or the image records scene errors), with the reason for each frame not done. Exit code 0 "
                       "when every frame is done, 1 otherwise.")
    t.add_argument("--dir", default=DEFAULT_FOLDER, metavar="DIR", help=f"the farm folder (default: ./{DEFAULT_FOLDER})")
    t.add_argument("--json", action="store_true", help="print the status as JSON")

    m = sub.add_parser("merge", help="merge a tiled frame's tiles into its image",
                       description="Merge the tiles of a frame submitted with --tiles into the frame's image, "
                       "if every tile is rendered (the array tasks do it after each tile; run it by hand only to "
                       "retry a failed merge). Exit code 0 when merged or not every tile is there yet, 1 when the "
                       "tiles cannot be merged.")
    m.add_argument("--dir", default=DEFAULT_FOLDER, metavar="DIR", help=f"the farm folder (default: ./{DEFAULT_FOLDER})")
    m.add_argument("--frame", type=int, required=True, metavar="N")
    return p


def _split_darc_args(argv: list[str]) -> tuple[list[str], list[str]]:
    """Everything after the first '--' goes to darc."""
    if "--" in argv:
        i = argv.index("--")
        return argv[:i], argv[i + 1:]
    return argv, []


def _gives_option(arg: str, option: str) -> bool:
    return arg == option or arg.startswith(option + "=")


def _check_darc_args(darc_args: list[str], tiles: int) -> None:
    for a in darc_args:
        taken = next((o for o in OWN_DARC_OPTIONS if _gives_option(a, o)), None)
        if taken is None and a.startswith("-o") and not a.startswith("--"):
            taken = "-o"
        if taken:
            raise UsageError(f"darc option {a}: darc-slurm sets {taken} itself (give -o and --frames to darc-slurm)")
        tile_option = next((o for o in OWN_TILE_OPTIONS if _gives_option(a, o)), None)
        if tile_option and tiles > 1:
            raise UsageError(f"darc option {a}: not with --tiles (each tile sets its own --crop; a preview would "
                             "be of one tile)")


def _absolute_pattern(name: str, what: str) -> str:
    """The absolute form of a file name with darc's frame pattern, refusing a current directory
    whose own name holds '#' or %d (darc would fill in the first pattern it finds)."""
    absolute = os.path.abspath(name)
    if substitute_frame_number(absolute, 7) != os.path.abspath(substitute_frame_number(name, 7)):
        raise UsageError(f"{what} {name}: the folder {os.path.dirname(absolute)} holds '#' or %d, which darc "
                         "would take for the frame number")
    return absolute


def _sequence(args, darc_args: list[str]) -> Sequence:
    try:
        frames = parse_frame_list(args.frames)
    except FrameListError as e:
        raise UsageError(f"--frames: {e}") from None
    if not has_frame_pattern(args.output):
        raise UsageError(f"-o {args.output}: needs the frame number in the name ('#' run or %04d, as out/shot.####.exr)")
    output = _absolute_pattern(args.output, "-o")
    ribs = []
    for rib in args.ribs:
        if rib == "-":
            raise UsageError("a farm cannot read RIB from standard input: name the RIB files")
        ribs.append(_absolute_pattern(rib, "RIB"))
    missing = [substitute_frame_number(r, f) for r in ribs for f in (frames if has_frame_pattern(r) else frames[:1])
               if not os.path.isfile(substitute_frame_number(r, f))]
    if missing:
        more = f" and {len(missing) - 5} more" if len(missing) > 5 else ""
        raise UsageError(f"no such RIB file: {', '.join(missing[:5])}{more}")
    if not 1 <= args.tiles <= MAX_TILES:
        raise UsageError(f"--tiles must be from 1 to {MAX_TILES}")
    if args.tiles > 1 and not output.lower().endswith(".exr"):
        raise UsageError(f"-o {args.output}: --tiles needs an EXR image (its data window holds a tile; the "
                         "8-bit formats would need the display transform again)")
    return Sequence(tuple(ribs), tuple(frames), output, tuple(darc_args), args.tiles)


def _queued_frames(submissions: list[Submission], active: set[str]) -> set[int]:
    return {f for s in submissions if s.job_id in active for f in s.frames}


def _runs(statuses: list[FrameStatus]) -> list[list[FrameStatus]]:
    """Runs of consecutive frames with the same reason."""
    runs: list[list[FrameStatus]] = []
    for s in statuses:
        if runs and runs[-1][-1].reason == s.reason and runs[-1][-1].frame == s.frame - 1:
            runs[-1].append(s)
        else:
            runs.append([s])
    return runs


def _print_status(folder: FarmFolder, sequence: Sequence, statuses: list[FrameStatus],
                  submissions: list[Submission], active: set[str] | None) -> None:
    tiles = f", {sequence.tiles} tiles (rows) each" if sequence.tiles > 1 else ""
    print(f"darc-slurm: {folder.path}: {len(sequence.frames)} frames ({format_frame_list(list(sequence.frames))}) "
          f"of {sequence.output}{tiles}")
    for state in (DONE, FAILED, MISSING):
        chosen = [s for s in statuses if s.state == state]
        listed = f"  {format_frame_list([s.frame for s in chosen])}" if chosen else ""
        print(f"{state:8} {len(chosen):5}{listed}")
        if state == DONE:
            continue
        for run in _runs(chosen):
            log = f"  (log: {run[0].log})" if run[0].log and state == FAILED else ""
            print(f"  {format_frame_list([s.frame for s in run]):>12}  {run[0].reason}{log}")
    if submissions:
        if active is None:
            jobs = "squeue failed: which jobs are still queued is unknown"
        else:
            jobs = ", ".join(f"{s.job_id} ({'queued or running' if s.job_id in active else 'finished'})"
                             for s in submissions)
        print(f"jobs     {jobs}")


def _status_json(folder: FarmFolder, sequence: Sequence, statuses: list[FrameStatus],
                 submissions: list[Submission], active: set[str] | None) -> dict:
    def tiles(s: FrameStatus) -> dict:
        return {state: [t.tile.number for t in s.tiles if t.state == state] for state in (DONE, FAILED, MISSING)}

    def entries(state):
        return [{"frame": s.frame, "reason": s.reason, "log": str(s.log) if s.log else None}
                | ({"tiles": tiles(s)} if s.tiles else {}) for s in statuses if s.state == state]
    return {"folder": str(folder.path), "output": sequence.output, "frames": list(sequence.frames),
            "tiles": sequence.tiles,
            DONE: [s.frame for s in statuses if s.state == DONE], FAILED: entries(FAILED), MISSING: entries(MISSING),
            "jobs": [{"job_id": s.job_id, "frames": s.frames, "tasks": s.tasks,
                      "active": None if active is None else s.job_id in active} for s in submissions]}


def _active_or_none(submissions: list[Submission]) -> set[str] | None:
    try:
        return active_jobs([s.job_id for s in submissions])
    except SlurmError as e:
        print(f"darc-slurm: warning: {e}", file=sys.stderr)
        return None


def status(args) -> int:
    folder = FarmFolder(Path(args.dir))
    sequence, submissions = folder.load()
    active = _active_or_none(submissions)
    statuses = sequence_status(folder, sequence, _queued_frames(submissions, active or set()))
    if args.json:
        print(json.dumps(_status_json(folder, sequence, statuses, submissions, active), indent=2))
    else:
        _print_status(folder, sequence, statuses, submissions, active)
    return EXIT_OK if all(s.state == DONE for s in statuses) else EXIT_FAILED


def _sbatch_options(args, sequence: Sequence) -> SbatchOptions:
    for name in ("chunk", "max_running", "cpus_per_task"):
        value = getattr(args, name)
        if value is not None and value < 1:
            raise UsageError(f"--{name.replace('_', '-')} must be at least 1")
    name = os.path.basename(sequence.output)
    parts = split_frame_pattern(name)
    stem = (parts[0] if parts else name).rstrip("._-")
    job_name = args.job_name or "darc-" + (stem or "sequence")
    return SbatchOptions(args.partition, args.time, args.mem, args.cpus_per_task, job_name, args.max_running,
                         tuple(args.sbatch_arg))


def _wait(folder: FarmFolder) -> int:
    while True:
        _, submissions = folder.load()
        if not active_jobs([s.job_id for s in submissions]):
            break
        time.sleep(WAIT_POLL_SECONDS)
    return status(argparse.Namespace(dir=str(folder.path), json=False))


def _write_task_script(folder: FarmFolder, sequence: Sequence, darc: Path, task_items: list[list[str]],
                       number: int) -> str:
    """Writes submission `number`'s batch script; returns its name in the folder."""
    name = f"tasks/submit-{number}.sh"
    user_threads = any(_gives_option(a, "--threads") for a in sequence.darc_args)
    script = folder.file(name)
    script.write_text(task_script(folder, sequence, str(darc), str(DARC_SLURM), task_items, number, name, user_threads))
    script.chmod(0o755)
    return name


def _items(sequence: Sequence, status: FrameStatus) -> list[str]:
    """The task script's items for a frame not done: the frame; or its tiles not done; or, when
    every tile is done, the merge."""
    if sequence.tiles == 1:
        return [str(status.frame)]
    if not status.tiles:  # its tiles were merged (into an image with errors, or one that does not open)
        return [f"{status.frame}:{k}" for k in range(1, sequence.tiles + 1)]
    left = [f"{status.frame}:{t.tile.number}" for t in status.tiles if t.state != DONE]
    return left or [f"{status.frame}:merge"]


def _tile_work(items: list[str]) -> str:
    """What a tiled submission's items are, in words: "7 tiles, 1 merge"."""
    merges = sum(i.endswith(":merge") for i in items)
    tiles = len(items) - merges
    return f"{tiles} tile{'s' if tiles != 1 else ''}, {merges} merge{'s' if merges != 1 else ''}"


def submit_command(args, darc_args: list[str]) -> int:
    _check_darc_args(darc_args, args.tiles)
    sequence = _sequence(args, darc_args)
    options = _sbatch_options(args, sequence)
    darc = Path(args.darc).resolve()
    if not (darc.is_file() and os.access(darc, os.X_OK)):
        raise UsageError(f"no darc command at {darc} (build it with scripts/build, or pass --darc PATH)")
    folder = FarmFolder(Path(args.dir))
    if has_frame_pattern(str(folder.path)):
        raise UsageError(f"--dir {folder.path}: holds '#' or %d, which darc would take for the frame number")
    folder.create(tiled=sequence.tiles > 1)
    output_folder = os.path.dirname(sequence.output)
    if not has_frame_pattern(output_folder):  # darc does not make the folders of its images
        os.makedirs(output_folder, exist_ok=True)
    with folder.locked():
        submissions: list[Submission] = []
        if folder.exists():
            recorded, submissions = folder.load()
            if recorded != sequence:
                raise UsageError(f"{folder.path} holds another sequence ({'; '.join(sequence.differences(recorded))}); "
                                 "use another --dir, or remove the folder to start over")
        folder.save(sequence, submissions)
        active = active_jobs([s.job_id for s in submissions]) if submissions else set()
        if active and not args.force:
            print(f"darc-slurm: jobs {', '.join(sorted(active))} of {folder.path} are still queued or running: wait "
                  "for them (darc-slurm status), or scancel them; --force submits the other frames now",
                  file=sys.stderr)
            return EXIT_FAILED
        queued = _queued_frames(submissions, active)
        statuses = sequence_status(folder, sequence, queued)
        left = [s for s in statuses if s.state != DONE and s.frame not in queued]
        to_render = [s.frame for s in left]
        if not to_render:
            done = sum(s.state == DONE for s in statuses)
            print(f"darc-slurm: nothing to submit: {done} of {len(statuses)} frames done"
                  + (f", the others queued or running in job {', '.join(sorted(active))}" if queued else ""))
            return _wait(folder) if args.wait else EXIT_OK
        items = [item for s in left for item in _items(sequence, s)]
        task_items = chunks(items, args.chunk)
        number = len(submissions) + 1
        script_name = _write_task_script(folder, sequence, darc, task_items, number)
        command = sbatch_command(str(folder.file(script_name)), len(task_items), str(folder.file("slurm/%A_%a.out")),
                                 os.getcwd(), options)
        frames_text = format_frame_list(to_render)
        tile_work = _tile_work(items) if sequence.tiles > 1 else ""
        if args.dry_run:
            print(f"darc-slurm: would submit {len(task_items)} array tasks for frames {frames_text}"
                  f"{f' ({tile_work})' if tile_work else ''}:\n{shlex.join(command)}")
            return EXIT_OK
        job_id = submit(command)
        submissions.append(Submission(number, job_id, to_render, len(task_items), script_name,
                                      datetime.datetime.now().astimezone().isoformat(timespec="seconds")))
        folder.save(sequence, submissions)
    unit = f"tile{'s' if args.chunk > 1 else ''} of {sequence.tiles} per frame" if sequence.tiles > 1 else "frames"
    print(f"darc-slurm: submitted job {job_id}: {len(task_items)} array tasks of up to {args.chunk} {unit}, "
          f"frames {frames_text} ({len(to_render)} of {len(sequence.frames)}{f'; {tile_work}' if tile_work else ''})")
    if args.wait:
        return _wait(folder)
    print(f"darc-slurm: status: {shlex.join([sys.argv[0], 'status', '--dir', str(folder.path)])}")
    return EXIT_OK


def merge_command(args) -> int:
    folder = FarmFolder(Path(args.dir))
    sequence, _ = folder.load()
    if sequence.tiles == 1:
        raise UsageError(f"{folder.path}: its frames are not cut into tiles (submit --tiles)")
    if args.frame not in sequence.frames:
        raise UsageError(f"frame {args.frame} is not in the sequence ({format_frame_list(list(sequence.frames))})")
    try:
        print(f"darc-slurm: {merge_tiles(folder, sequence, args.frame)}")
    except MergeError as e:
        print(f"darc-slurm: error: frame {args.frame}: {e}", file=sys.stderr)
        return EXIT_FAILED
    return EXIT_OK


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    own, darc_args = _split_darc_args(argv)
    parser = _parser()
    args = parser.parse_args(own)
    try:
        if args.command in ("status", "merge"):
            if darc_args:
                parser.error(f"{args.command} takes no darc options")
            return status(args) if args.command == "status" else merge_command(args)
        return submit_command(args, darc_args)
    except (UsageError, FarmFolderError) as e:
        print(f"darc-slurm: {e}", file=sys.stderr)
        return EXIT_USAGE
    except SlurmError as e:
        print(f"darc-slurm: {e}", file=sys.stderr)
        return EXIT_FAILED
    except OSError as e:
        print(f"darc-slurm: error: {e}", file=sys.stderr)
        return EXIT_FAILED
