"""Where each frame of a sequence stands, from its image and its log:

    done     the image exists, opens, and records no scene errors (what darc --skip-existing skips)
    failed   the log's last attempt ended with a non-zero exit, or without the image written, or the
             image records scene errors (darc:errors, README "Running darc")
    missing  anything else: never rendered, interrupted (scancel, time limit, preemption), still
             rendering, or an image that does not open

One exception to "non-zero exit": darc parses every frame of a RIB file, also those --frames
leaves out, and exits with 3 (scene error) for an error in any of them. Each image records the
errors of its own frame, so a frame whose darc exited with 3 but whose image exists and records
no errors is done: the error belongs to another frame, which is failed by its own image.

A new submission renders the failed and missing frames; darc's --skip-existing renders a frame
with recorded errors again too."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from darc_slurm.farm_folder import FarmFolder, Sequence
from darc_slurm.task_script import LOG_ATTEMPT_PREFIX, LOG_EXIT_PREFIX, LOG_INTERRUPTED_PREFIX

DONE, FAILED, MISSING = "done", "failed", "missing"
# darc killed by SIGTERM (128 + 15): the task's trap may not have had the last word in the log.
EXIT_BY_SIGTERM = 143
EXIT_SCENE_ERROR = 3  # darc's exit code for scene errors (README "Running darc")
# What darc prints when --frames selects no FrameBegin block of the RIB files.
NO_SUCH_FRAME_WARNING = "--frames selected none of the frames in the input"

try:
    import OpenImageIO as oiio
except ImportError:  # python3-openimageio (scripts/setup installs it); without it, images are not opened
    oiio = None


@dataclasses.dataclass(frozen=True)
class FrameStatus:
    frame: int
    state: str  # DONE, FAILED or MISSING
    reason: str  # for FAILED and MISSING: why, in a few words
    log: Path | None  # the frame's log, when it has one


@dataclasses.dataclass(frozen=True)
class ImageRecord:
    opens: bool
    errors: int = 0
    first_error: str = ""


def _int(value) -> int:
    try:
        return int(value)
    except (TypeError, ValueError):
        return 0


def read_image_record(path: Path) -> ImageRecord:
    """Whether the image opens and the scene errors it records: darc:errors / darc:first_error as
    attributes (EXR, PNG) or as ImageDescription lines (TIFF, JPEG), as darc reads them back."""
    if oiio is None:
        return ImageRecord(opens=True)
    reader = oiio.ImageInput.open(str(path))
    if reader is None:
        oiio.geterror()  # clear OIIO's error for the next open
        return ImageRecord(opens=False)
    try:
        spec = reader.spec()
        errors = spec.getattribute("darc:errors")
        first = spec.getattribute("darc:first_error") or ""
        if errors is None:
            fields = dict(line.split("=", 1) for line in (spec.getattribute("ImageDescription") or "").splitlines()
                          if line.startswith("darc:") and "=" in line)
            errors, first = fields.get("darc:errors"), fields.get("darc:first_error", "")
        return ImageRecord(opens=True, errors=_int(errors), first_error=str(first))
    finally:
        reader.close()


@dataclasses.dataclass(frozen=True)
class LogOutcome:
    started: bool  # the log exists (a task began the frame)
    exit_code: int | None = None  # from "darc-slurm: exit N"
    interrupted_by: str = ""  # from "darc-slurm: interrupted by SIGTERM"
    no_such_frame: bool = False  # darc said the RIB files have no such frame


def read_log_outcome(log: Path) -> LogOutcome:
    """How the last attempt recorded in a frame's log ended (the task script appends each attempt)."""
    try:
        lines = log.read_text(errors="replace").splitlines()
    except FileNotFoundError:
        return LogOutcome(started=False)
    starts = [i for i, line in enumerate(lines) if line.startswith(LOG_ATTEMPT_PREFIX)]
    attempt = lines[starts[-1]:] if starts else lines
    no_such_frame = any(NO_SUCH_FRAME_WARNING in line for line in attempt)
    for line in reversed(attempt):
        if line.startswith(LOG_INTERRUPTED_PREFIX):
            return LogOutcome(True, interrupted_by=line[len(LOG_INTERRUPTED_PREFIX):].strip())
        if line.startswith(LOG_EXIT_PREFIX):
            return LogOutcome(True, exit_code=_int(line[len(LOG_EXIT_PREFIX):]), no_such_frame=no_such_frame)
    return LogOutcome(started=True)


def _with_errors(record: ImageRecord) -> str:
    first = f": {record.first_error}" if record.first_error else ""
    return f"the image records {record.errors} scene error{'s' if record.errors != 1 else ''}{first}"


def frame_status(folder: FarmFolder, sequence: Sequence, frame: int, queued_frames: set[int]) -> FrameStatus:
    """`queued_frames`: the frames of the folder's jobs that Slurm still has queued or running."""
    image = sequence.image(frame)
    log_path = folder.log(frame)
    outcome = read_log_outcome(log_path)
    log = log_path if outcome.started else None
    record = read_image_record(image) if image.exists() else None
    interrupted_by = outcome.interrupted_by or ("SIGTERM" if outcome.exit_code == EXIT_BY_SIGTERM else "")

    def status(state: str, reason: str = "") -> FrameStatus:
        return FrameStatus(frame, state, reason, log)

    if outcome.exit_code not in (None, 0, EXIT_SCENE_ERROR, EXIT_BY_SIGTERM):
        errors = f"; {_with_errors(record)}" if record and record.errors > 0 else ""
        return status(FAILED, f"darc exited with {outcome.exit_code}{errors}")
    if record is not None and not record.opens:
        return status(MISSING, "the image does not open")
    if record is not None and record.errors > 0:
        exited = f"darc exited with {outcome.exit_code}; " if outcome.exit_code else ""
        return status(FAILED, exited + _with_errors(record))
    if record is not None:
        return status(DONE)
    if outcome.no_such_frame:
        return status(FAILED, f"the RIB files have no FrameBegin {frame} (darc wrote no image)")
    if outcome.exit_code in (0, EXIT_SCENE_ERROR):
        return status(FAILED, f"darc exited with {outcome.exit_code} but wrote no {image.name}")
    if interrupted_by:
        return status(MISSING, f"interrupted by {interrupted_by} (scancel, time limit or preemption)")
    if outcome.started:
        return status(MISSING, "rendering" if frame in queued_frames else "stopped while rendering (the task was killed)")
    return status(MISSING, "queued" if frame in queued_frames else "not rendered")


def sequence_status(folder: FarmFolder, sequence: Sequence, queued_frames: set[int]) -> list[FrameStatus]:
    return [frame_status(folder, sequence, f, queued_frames) for f in sequence.frames]
