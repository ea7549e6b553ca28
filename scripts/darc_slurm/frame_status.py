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

A frame cut into tiles (--tiles) is done by its merged image alone. Until then each tile stands
by the same rules, from its own image and log; the frame is failed when a tile is, or when the
last attempt at merging its finished tiles failed (the frame's log holds the merge attempts), and
missing otherwise, saying how many tiles are done and why the first other one is not.

A new submission renders the failed and missing frames (tiles); darc's --skip-existing renders a
frame (tile) with recorded errors again too."""

from __future__ import annotations

import dataclasses
from pathlib import Path

from darc_slurm.farm_folder import FarmFolder, Sequence
from darc_slurm.task_script import LOG_ATTEMPT_PREFIX, LOG_EXIT_PREFIX, LOG_INTERRUPTED_PREFIX
from darc_slurm.tiles import Tile, frame_tiles

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
class TileStatus:
    tile: Tile
    state: str  # DONE, FAILED or MISSING
    reason: str  # for FAILED and MISSING: why, in a few words
    log: Path | None  # the tile's log, when it has one


@dataclasses.dataclass(frozen=True)
class FrameStatus:
    frame: int
    state: str  # DONE, FAILED or MISSING
    reason: str  # for FAILED and MISSING: why, in a few words
    log: Path | None  # the log that says why (a tile's, or the merge's, for a tiled frame), when it has one
    # A tiled frame not done: where each of its tiles stands (empty for a frame rendered whole, or done).
    tiles: tuple[TileStatus, ...] = ()


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


def render_status(image: Path, log_path: Path, frame: int, queued: bool) -> tuple[str, str, Path | None]:
    """(state, reason, log) of one darc render of frame `frame` into `image` (the frame's image, or a
    tile's), from the image and the log of its attempts; `queued`: Slurm still has its task queued
    or running."""
    outcome = read_log_outcome(log_path)
    log = log_path if outcome.started else None
    record = read_image_record(image) if image.exists() else None
    interrupted_by = outcome.interrupted_by or ("SIGTERM" if outcome.exit_code == EXIT_BY_SIGTERM else "")

    def status(state: str, reason: str = "") -> tuple[str, str, Path | None]:
        return state, reason, log

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
        return status(MISSING, "rendering" if queued else "stopped while rendering (the task was killed)")
    return status(MISSING, "queued" if queued else "not rendered")


def frame_status(folder: FarmFolder, sequence: Sequence, frame: int, queued_frames: set[int]) -> FrameStatus:
    """`queued_frames`: the frames of the folder's jobs that Slurm still has queued or running."""
    queued = frame in queued_frames
    if sequence.tiles == 1:
        return FrameStatus(frame, *render_status(sequence.image(frame), folder.log(frame), frame, queued))
    return _tiled_frame_status(folder, sequence, frame, queued)


def _tiled_frame_status(folder: FarmFolder, sequence: Sequence, frame: int, queued: bool) -> FrameStatus:
    image = sequence.image(frame)
    if image.exists():
        record = read_image_record(image)
        if record.opens and record.errors == 0:
            return FrameStatus(frame, DONE, "", None)
        if record.opens:
            return FrameStatus(frame, FAILED, _with_errors(record), None)
        # An image that does not open: its tiles say what is left to do.
    tiles = tuple(TileStatus(tile, *render_status(folder.tile_image(frame, tile), folder.tile_log(frame, tile), frame,
                                                  queued))
                  for tile in frame_tiles(sequence.tiles))
    done = sum(t.state == DONE for t in tiles)
    failed = next((t for t in tiles if t.state == FAILED), None)
    if failed:
        return FrameStatus(frame, FAILED, f"tile {failed.tile.number} of {sequence.tiles}: {failed.reason}", failed.log,
                           tiles)
    if done < sequence.tiles:
        first = next(t for t in tiles if t.state != DONE)
        return FrameStatus(frame, MISSING, f"{done} of {sequence.tiles} tiles done; tile {first.tile.number}: "
                           f"{first.reason}", first.log, tiles)
    merge_log = folder.log(frame)
    merge = read_log_outcome(merge_log)
    log = merge_log if merge.started else None
    if merge.exit_code not in (None, 0, EXIT_BY_SIGTERM):
        return FrameStatus(frame, FAILED, f"merging the tiles failed (exit {merge.exit_code})", log, tiles)
    if image.exists():
        return FrameStatus(frame, MISSING, "the merged image does not open", log, tiles)
    if merge.interrupted_by or merge.exit_code == EXIT_BY_SIGTERM:
        return FrameStatus(frame, MISSING, "merging the tiles was interrupted by "
                           f"{merge.interrupted_by or 'SIGTERM'}", log, tiles)
    return FrameStatus(frame, MISSING, f"all {sequence.tiles} tiles done, not merged" + (" yet" if queued else ""),
                       log, tiles)


def sequence_status(folder: FarmFolder, sequence: Sequence, queued_frames: set[int]) -> list[FrameStatus]:
    return [frame_status(folder, sequence, f, queued_frames) for f in sequence.frames]
