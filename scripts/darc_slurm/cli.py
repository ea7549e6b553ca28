"""darc-slurm's command line: `submit` (the sequence's frames not yet done, as one Slurm array job)
and `status` (done / missing / failed frames). Exit codes: 0 success (status: every frame done);
1 a Slurm command failed, jobs of the folder are still queued (submit), or frames are not done
(status, submit --wait); 2 usage error."""

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

EXIT_OK, EXIT_FAILED, EXIT_USAGE = 0, 1, 2
DEFAULT_FOLDER = "darc-farm"
REPOSITORY = Path(__file__).resolve().parents[2]  # scripts/darc_slurm/cli.py
# submit --wait asks squeue this often whether the jobs are still there: a few seconds is nothing
# beside a frame's render, and well within what a scheduler takes from one user.
WAIT_POLL_SECONDS = 3.0
# darc options that each task sets itself, per frame.
OWN_DARC_OPTIONS = ("--frames", "--output", "--stats", "--skip-existing", "--cat")


class UsageError(Exception):
    pass


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="darc-slurm",
        description="Render a darc frame sequence on a Slurm cluster as an array job, resume it after "
        "failures, and list which frames are done, missing or failed. The farm folder (--dir) holds the "
        "sequence, its jobs, and each frame's log and stats. Exit codes: 0 success; 1 a Slurm command "
        "failed, or frames are not done; 2 usage error.")
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
    s.add_argument("--chunk", type=int, default=1, metavar="N", help="frames per array task (default 1)")
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
    return p


def _split_darc_args(argv: list[str]) -> tuple[list[str], list[str]]:
    """Everything after the first '--' goes to darc."""
    if "--" in argv:
        i = argv.index("--")
        return argv[:i], argv[i + 1:]
    return argv, []


def _gives_option(arg: str, option: str) -> bool:
    return arg == option or arg.startswith(option + "=")


def _check_darc_args(darc_args: list[str]) -> None:
    for a in darc_args:
        taken = next((o for o in OWN_DARC_OPTIONS if _gives_option(a, o)), None)
        if taken is None and a.startswith("-o") and not a.startswith("--"):
            taken = "-o"
        if taken:
            raise UsageError(f"darc option {a}: darc-slurm sets {taken} itself (give -o and --frames to darc-slurm)")


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
    return Sequence(tuple(ribs), tuple(frames), output, tuple(darc_args))


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
    print(f"darc-slurm: {folder.path}: {len(sequence.frames)} frames ({format_frame_list(list(sequence.frames))}) "
          f"of {sequence.output}")
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
    def entries(state):
        return [{"frame": s.frame, "reason": s.reason, "log": str(s.log) if s.log else None}
                for s in statuses if s.state == state]
    return {"folder": str(folder.path), "output": sequence.output, "frames": list(sequence.frames),
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


def _write_task_script(folder: FarmFolder, sequence: Sequence, darc: Path, task_frames: list[list[int]],
                       number: int) -> str:
    """Writes submission `number`'s batch script; returns its name in the folder."""
    name = f"tasks/submit-{number}.sh"
    user_threads = any(_gives_option(a, "--threads") for a in sequence.darc_args)
    script = folder.file(name)
    script.write_text(task_script(folder, sequence, str(darc), task_frames, number, name, user_threads))
    script.chmod(0o755)
    return name


def submit_command(args, darc_args: list[str]) -> int:
    _check_darc_args(darc_args)
    sequence = _sequence(args, darc_args)
    options = _sbatch_options(args, sequence)
    darc = Path(args.darc).resolve()
    if not (darc.is_file() and os.access(darc, os.X_OK)):
        raise UsageError(f"no darc command at {darc} (build it with scripts/build, or pass --darc PATH)")
    folder = FarmFolder(Path(args.dir))
    if has_frame_pattern(str(folder.path)):
        raise UsageError(f"--dir {folder.path}: holds '#' or %d, which darc would take for the frame number")
    folder.create()
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
        to_render = [s.frame for s in statuses if s.state != DONE and s.frame not in queued]
        if not to_render:
            done = sum(s.state == DONE for s in statuses)
            print(f"darc-slurm: nothing to submit: {done} of {len(statuses)} frames done"
                  + (f", the others queued or running in job {', '.join(sorted(active))}" if queued else ""))
            return _wait(folder) if args.wait else EXIT_OK
        task_frames = chunks(to_render, args.chunk)
        number = len(submissions) + 1
        script_name = _write_task_script(folder, sequence, darc, task_frames, number)
        command = sbatch_command(str(folder.file(script_name)), len(task_frames), str(folder.file("slurm/%A_%a.out")),
                                 os.getcwd(), options)
        frames_text = format_frame_list(to_render)
        if args.dry_run:
            print(f"darc-slurm: would submit {len(task_frames)} array tasks for frames {frames_text}:\n{shlex.join(command)}")
            return EXIT_OK
        job_id = submit(command)
        submissions.append(Submission(number, job_id, to_render, len(task_frames), script_name,
                                      datetime.datetime.now().astimezone().isoformat(timespec="seconds")))
        folder.save(sequence, submissions)
    print(f"darc-slurm: submitted job {job_id}: {len(task_frames)} array tasks of up to {args.chunk} frames, "
          f"frames {frames_text} ({len(to_render)} of {len(sequence.frames)})")
    if args.wait:
        return _wait(folder)
    print(f"darc-slurm: status: {shlex.join([sys.argv[0], 'status', '--dir', str(folder.path)])}")
    return EXIT_OK


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    own, darc_args = _split_darc_args(argv)
    parser = _parser()
    args = parser.parse_args(own)
    try:
        if args.command == "status":
            if darc_args:
                parser.error("status takes no darc options")
            return status(args)
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
