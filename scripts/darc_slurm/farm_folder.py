"""The farm folder of one sequence: what the sequence is (RIB files, frames, output pattern, darc
arguments, tiles per frame), every submission made for it, and where each frame's log and stats go.

    DIR/sequence.json          the sequence and its submissions (rewritten whole, atomically)
    DIR/tasks/submit-N.sh      the batch script of submission N (task_script.py)
    DIR/logs/frame.NNNN.log    the attempts at frame NNNN: darc's command, its output, its end (with
                               --tiles: the attempts at merging its tiles)
    DIR/stats/frame.NNNN.json  darc's --stats for that frame
    DIR/slurm/JOB_TASK.out     what Slurm captured from each array task's script

With --tiles (tiles.py), each tile K of frame NNNN has its own files, the image only until the
frame's tiles are merged into its image (tile_merge.py):

    DIR/tiles/frame.NNNN.tile.K.exr   the tile: the frame's full display window, the row as data window
    DIR/tiles/frame.NNNN.lock         held while the frame's tiles are merged
    DIR/logs/frame.NNNN.tile.K.log    the attempts at the tile, as a frame's
    DIR/stats/frame.NNNN.tile.K.json  darc's --stats for the tile

A folder holds one sequence: submitting another one into it is refused, so that the status of a
folder always describes the images one command line asked for."""

from __future__ import annotations

import contextlib
import dataclasses
import fcntl
import json
import os
from pathlib import Path

from darc_slurm.frames import format_frame_list, substitute_frame_number
from darc_slurm.tiles import Tile

MANIFEST_NAME = "sequence.json"
# Version 2 added the sequence's tiles per frame; a version 1 manifest is read as one tile per frame.
MANIFEST_VERSION = 2
READABLE_MANIFEST_VERSIONS = (1, 2)
# Names of the per-frame files: darc's '#' rule, so they sort in frame order up to frame 9999.
LOG_PATTERN = "logs/frame.####.log"
STATS_PATTERN = "stats/frame.####.json"
# A tile's files: the frame's name, then ".tile.K" and the extension (tiles.py: Tile.label).
TILE_IMAGE_STEM = "tiles/frame.####"
TILE_LOG_STEM = "logs/frame.####"
TILE_STATS_STEM = "stats/frame.####"


class FarmFolderError(Exception):
    """A farm folder that cannot be used as asked (a usage error: exit code 2)."""


@dataclasses.dataclass(frozen=True)
class Sequence:
    """What is rendered: two submissions of the same Sequence render the same images."""

    ribs: tuple[str, ...]  # absolute; a name may hold a frame pattern (one RIB file per frame)
    frames: tuple[int, ...]  # sorted, distinct
    output: str  # absolute image name with darc's frame pattern
    darc_args: tuple[str, ...]  # passed to darc before the RIB files
    tiles: int = 1  # rows each frame is cut into (tiles.py); 1: frames are rendered whole

    def image(self, frame: int) -> Path:
        return Path(substitute_frame_number(self.output, frame))

    def to_json(self) -> dict:
        return {"ribs": list(self.ribs), "frames": list(self.frames), "output": self.output,
                "darc_args": list(self.darc_args), "tiles": self.tiles}

    @staticmethod
    def from_json(j: dict) -> "Sequence":
        return Sequence(tuple(j["ribs"]), tuple(j["frames"]), j["output"], tuple(j["darc_args"]), int(j.get("tiles", 1)))

    def differences(self, other: "Sequence") -> list[str]:
        """What differs from `other`, in words, for the message that refuses to mix sequences."""
        said = []
        for name in ("ribs", "frames", "output", "darc_args", "tiles"):
            mine, theirs = getattr(self, name), getattr(other, name)
            if mine != theirs:
                said.append(f"{name}: {_brief(theirs)} in the folder, {_brief(mine)} now")
        return said


def _brief(value) -> str:
    if isinstance(value, int):
        return str(value)
    if isinstance(value, tuple) and value and isinstance(value[0], int):
        return format_frame_list(list(value))
    return json.dumps(list(value) if isinstance(value, tuple) else value)


@dataclasses.dataclass
class Submission:
    number: int  # 1, 2, ... in the order they were made
    job_id: str  # Slurm's array job id
    frames: list[int]  # the frames it was asked to render
    tasks: int  # array tasks
    script: str  # relative to the folder
    submitted: str  # local time, ISO 8601


class FarmFolder:
    def __init__(self, path: Path):
        self.path = path.resolve()

    def file(self, relative: str) -> Path:
        return self.path / relative

    def log(self, frame: int) -> Path:
        return self.path / substitute_frame_number(LOG_PATTERN, frame)

    def stats(self, frame: int) -> Path:
        return self.path / substitute_frame_number(STATS_PATTERN, frame)

    def tile_image(self, frame: int, tile: Tile) -> Path:
        return self._tile_file(TILE_IMAGE_STEM, frame, tile, ".exr")

    def tile_log(self, frame: int, tile: Tile) -> Path:
        return self._tile_file(TILE_LOG_STEM, frame, tile, ".log")

    def tile_stats(self, frame: int, tile: Tile) -> Path:
        return self._tile_file(TILE_STATS_STEM, frame, tile, ".json")

    def tile_lock(self, frame: int) -> Path:
        return self.path / substitute_frame_number(TILE_IMAGE_STEM + ".lock", frame)

    def _tile_file(self, stem: str, frame: int, tile: Tile, extension: str) -> Path:
        return self.path / substitute_frame_number(f"{stem}.tile.{tile.label}{extension}", frame)

    def exists(self) -> bool:
        return (self.path / MANIFEST_NAME).is_file()

    def create(self, tiled: bool = False) -> None:
        for sub in ("tasks", "logs", "stats", "slurm") + (("tiles",) if tiled else ()):
            (self.path / sub).mkdir(parents=True, exist_ok=True)

    @contextlib.contextmanager
    def locked(self):
        """Held while a submission reads and rewrites the manifest, so that two submit commands
        started together cannot both submit the same missing frames."""
        with open(self.path / ".lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            yield

    def load(self) -> tuple[Sequence, list[Submission]]:
        manifest = self.path / MANIFEST_NAME
        try:
            j = json.loads(manifest.read_text())
            if j.get("version") not in READABLE_MANIFEST_VERSIONS:
                raise FarmFolderError(f"{manifest}: version {j.get('version')}, this darc-slurm reads "
                                      f"version {MANIFEST_VERSION}")
            return Sequence.from_json(j["sequence"]), [Submission(**s) for s in j["submissions"]]
        except FileNotFoundError:
            raise FarmFolderError(f"{self.path} is not a darc-slurm farm folder (no {MANIFEST_NAME}; "
                                  "darc-slurm submit makes one)") from None
        except (ValueError, KeyError, TypeError) as e:
            raise FarmFolderError(f"{manifest} is damaged ({e}); remove the folder to start over") from None

    def save(self, sequence: Sequence, submissions: list[Submission]) -> None:
        """Writes the manifest under a temporary name and renames it: never half a file."""
        document = {"version": MANIFEST_VERSION, "sequence": sequence.to_json(),
                    "submissions": [dataclasses.asdict(s) for s in submissions]}
        manifest = self.path / MANIFEST_NAME
        temporary = manifest.with_name(f"{MANIFEST_NAME}.tmp-{os.getpid()}")
        temporary.write_text(json.dumps(document, indent=2) + "\n")
        os.replace(temporary, manifest)
