"""How `submit --tiles N` cuts a frame: N rows of the image, top to bottom, each rendered by darc
with --crop 0 1 YMIN YMAX into its own EXR in the farm folder, then merged into the frame's image
(tile_merge.py).

The crop windows are fractions, as RI CropWindow and prman -crop take them: darc-slurm need not
know a frame's resolution (Format, or --res among darc's options, may differ per frame). Row k of
N spans [k/N, (k+1)/N]. darc keeps the pixel rows ceil(H*ymin) to ceil(H*ymax - 1) (RI Spec 3.2,
integrator/render_frame.cpp), and both tiles beside a boundary read the same text, so the same
double b and the same product v = H*b: the upper tile ends before ceil(v - 1) + 1, the lower one
starts at ceil(v), and the two are equal because v - 1 is exact for v >= 1/2 (Sterbenz), which
holds for every boundary when N <= 2H. So the rows partition the image, no row twice or missing,
for any H of at least N/2. With N < H each row also keeps a pixel row (N = H may leave one
empty: 25 times 7/25 as a double is 7.000000000000001). darc's test
CropPixels.FractionRowsPartitionEveryResolution checks both for every H up to darc's largest
resolution and N up to 64. A row of no pixel is an error of darc's: the tile, and so the frame,
fails.

Rows, not a grid: a row keeps darc's scanline EXR whole-width, the merge is a concatenation, and
N rows of H pixels stay balanced as long as the frame's cost is spread over its height."""

from __future__ import annotations

import dataclasses

# The most tiles a frame may be cut into: far more than a farm gives one frame, and few enough
# that the tile labels stay short.
MAX_TILES = 999


@dataclasses.dataclass(frozen=True)
class Tile:
    number: int  # 1..count, top to bottom
    count: int

    @property
    def label(self) -> str:
        """The tile's number in file names, padded so that a frame's tiles sort in order."""
        return str(self.number).zfill(len(str(self.count)))

    def crop(self) -> tuple[str, str, str, str]:
        """darc's --crop xmin xmax ymin ymax for this row, as text. repr() of k/N is the shortest
        text that reads back as the same double, so both tiles beside a boundary see one value."""
        return "0", "1", _fraction(self.number - 1, self.count), _fraction(self.number, self.count)


def _fraction(k: int, n: int) -> str:
    if k == 0:
        return "0"
    if k == n:
        return "1"
    return repr(k / n)


def frame_tiles(count: int) -> list[Tile]:
    return [Tile(k, count) for k in range(1, count + 1)]
