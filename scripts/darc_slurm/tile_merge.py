"""Merges the tiles of a frame cut with --tiles (tiles.py) into the frame's image: the rows'
pixels one below the other, in the format darc writes (EXR: RGBA half, Z float), with the
attributes of the tiles, so that the image is the one darc writes rendering the frame whole.

The tiles hold the same pixels as the whole frame's render (darc renders a crop bitwise as the
same rectangle of the whole image: integrator/film.h), so the merge only copies values: half
values read as float and written back as half are exact.

Attributes: those of the first tile (Software, darc:hider, darc:spp, compression, the colour
space, ...), with the merged data window, but for these:
    renderTime     the sum of the tiles' render times (what the frame cost on the farm); a
                   single darc run records its own wall time, different on every run anyway
    DateTime       when the merged file was written (OpenImageIO's, as in every file darc writes)
    darc:errors    the scene errors of the tile that records the most (darc:first_error with it):
                   every tile reads the whole RIB, so they record the frame's errors alike

Who merges: the array task of every tile tries after its render, under the frame's lock
(DIR/tiles/frame.NNNN.lock), and the one that finds every tile rendered merges; the others leave
it. The last tile to be written always finds the others there, so a frame is merged as soon as it
can be, with no job waiting in the queue (a dependent job, --dependency=afterok, would wait for
every task of the array, and stay queued forever when one fails). A task killed between its
tile and the merge leaves the frame "all tiles done, not merged": the next submission merges it.

The image appears atomically (written under a temporary name, then renamed), and the tiles are
removed once it is there: a merged frame keeps only its image (and the tiles' logs and stats)."""

from __future__ import annotations

import contextlib
import fcntl
import os
import signal
from pathlib import Path

from darc_slurm.farm_folder import FarmFolder, Sequence
from darc_slurm.tiles import Tile, frame_tiles

try:
    import numpy
    import OpenImageIO as oiio
except ImportError:  # python3-openimageio and python3-numpy (scripts/setup installs them)
    oiio = None

ERROR_COUNT_ATTRIBUTE = "darc:errors"  # integrator/image_writer.h
FIRST_ERROR_ATTRIBUTE = "darc:first_error"
RENDER_TIME_ATTRIBUTE = "renderTime"
DATE_TIME_ATTRIBUTE = "DateTime"


class MergeError(Exception):
    """Tiles that cannot be merged (exit code 1): unreadable, or not the rows of one image."""


@contextlib.contextmanager
def _locked(path: Path):
    with open(path, "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield


def _exit_on_signal(signum, _frame) -> None:
    raise SystemExit(128 + signum)


@contextlib.contextmanager
def _removed_on_failure(path: Path):
    """Removes `path` if the block fails or SIGTERM stops it (scancel while merging)."""
    previous = signal.signal(signal.SIGTERM, _exit_on_signal)
    try:
        yield
    except BaseException:
        path.unlink(missing_ok=True)
        raise
    finally:
        signal.signal(signal.SIGTERM, previous)


class _TileImage:
    """One tile's header and pixels (as float: exact for darc's half and float channels)."""

    def __init__(self, tile: Tile, path: Path):
        reader = oiio.ImageInput.open(str(path))
        if reader is None:
            raise MergeError(f"tile {tile.number} ({path}) does not open: {oiio.geterror()}")
        try:
            self.spec = reader.spec()
            self.pixels = reader.read_image(0, 0, 0, self.spec.nchannels, oiio.FLOAT)
            if self.pixels is None:
                raise MergeError(f"tile {tile.number} ({path}): {reader.geterror()}")
        finally:
            reader.close()
        self.tile, self.path = tile, path

    def errors(self) -> int:
        return int(self.spec.getattribute(ERROR_COUNT_ATTRIBUTE) or 0)


def _layout(spec) -> tuple:
    """What every tile of a frame must share: the display window, channels and their formats."""
    formats = tuple(str(f) for f in spec.channelformats) or (str(spec.format),) * spec.nchannels
    return (spec.full_x, spec.full_y, spec.full_width, spec.full_height, tuple(spec.channelnames), formats)


def _check_rows(tiles: list[_TileImage]) -> None:
    """The tiles' data windows must be whole-width rows that cover the display window top to bottom,
    one after the other."""
    first = tiles[0].spec
    y = first.full_y
    for t in tiles:
        s = t.spec
        if _layout(s) != _layout(first):
            raise MergeError(f"tile {t.tile.number} ({t.path}) is not of the same image as tile 1: display window, "
                             f"channels or formats {_layout(s)} against {_layout(first)}")
        if s.x != s.full_x or s.width != s.full_width or s.y != y:
            raise MergeError(f"tile {t.tile.number} ({t.path}) has the data window x {s.x}-{s.x + s.width - 1}, "
                             f"y {s.y}-{s.y + s.height - 1}: expected the whole width from row {y} (does the RIB "
                             "or a darc option crop the frame?)")
        y += s.height
    if y != first.full_y + first.full_height:
        raise MergeError(f"the tiles end at row {y - 1}, the image at row {first.full_y + first.full_height - 1}")


def _merged_spec(tiles: list[_TileImage]):
    spec = oiio.ImageSpec(tiles[0].spec)
    spec.x, spec.y, spec.width, spec.height = spec.full_x, spec.full_y, spec.full_width, spec.full_height
    spec.erase_attribute(DATE_TIME_ATTRIBUTE)  # OpenImageIO writes the time of the merge instead
    spec.attribute(RENDER_TIME_ATTRIBUTE, float(sum(t.spec.getattribute(RENDER_TIME_ATTRIBUTE) or 0.0 for t in tiles)))
    with_errors = max(tiles, key=lambda t: t.errors())
    if with_errors.errors() > 0:
        spec.attribute(ERROR_COUNT_ATTRIBUTE, with_errors.errors())
        spec.attribute(FIRST_ERROR_ATTRIBUTE, with_errors.spec.getattribute(FIRST_ERROR_ATTRIBUTE) or "")
    return spec


def _write_atomically(image: Path, spec, pixels) -> None:
    # The extension stays last: OpenImageIO chooses the format by it (as darc's own temporary names).
    temporary = image.with_name(f"{image.stem}.tmp-{os.getpid()}{image.suffix}")
    with _removed_on_failure(temporary):
        out = oiio.ImageOutput.create(str(temporary))
        if out is None:
            raise MergeError(f"cannot write {image}: {oiio.geterror()}")
        ok = out.open(str(temporary), spec) and out.write_image(pixels)
        error = out.geterror()
        ok = out.close() and ok
        if not ok:
            raise MergeError(f"cannot write {image}: {error or out.geterror()}")
        os.replace(temporary, image)


def merge_tiles(folder: FarmFolder, sequence: Sequence, frame: int) -> str:
    """Merges frame `frame`'s tiles into its image when every tile is there; returns what was done,
    in words. Raises MergeError when the tiles cannot be merged, OSError when the image cannot be
    written."""
    if oiio is None:
        raise MergeError("merging tiles needs OpenImageIO's and numpy's Python modules (python3-openimageio, "
                         "python3-numpy: scripts/setup installs them)")
    image = sequence.image(frame)
    with _locked(folder.tile_lock(frame)):
        paths = [(tile, folder.tile_image(frame, tile)) for tile in frame_tiles(sequence.tiles)]
        waiting = [tile.number for tile, path in paths if not path.exists()]
        if waiting:
            if image.exists() and len(waiting) == len(paths):
                return f"frame {frame}: {image} is there already (its tiles were merged)"
            return (f"frame {frame}: {len(paths) - len(waiting)} of {len(paths)} tiles rendered; the task of the last "
                    "one merges them")
        tiles = [_TileImage(tile, path) for tile, path in paths]
        _check_rows(tiles)
        _write_atomically(image, _merged_spec(tiles), numpy.concatenate([t.pixels for t in tiles], axis=0))
        for _, path in paths:
            path.unlink()
    return f"frame {frame}: merged {len(paths)} tiles into {image}"
