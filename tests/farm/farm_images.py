"""How the farm tests compare a farm's image with the one a local darc run wrote: the same file but
for when it was written and how long the render took. Debian's python3 with OpenImageIO's bindings
(python3-openimageio)."""

from __future__ import annotations

from pathlib import Path

# The attributes that differ between two renders of the same frame: when the file was written
# (OpenImageIO's DateTime) and the render time (which a merged frame sums over its tiles).
# Everything else in the header must be equal.
WHEN_AND_HOW_LONG = ("DateTime", "renderTime")


def _header(spec) -> dict:
    formats = [str(f) for f in spec.channelformats] or [str(spec.format)] * spec.nchannels
    header = {"data window": (spec.x, spec.y, spec.width, spec.height),
              "display window": (spec.full_x, spec.full_y, spec.full_width, spec.full_height),
              "channels": tuple(spec.channelnames), "formats": tuple(formats)}
    header.update({a.name: a.value for a in spec.extra_attribs if a.name not in WHEN_AND_HOW_LONG})
    return header


def same_image(a_path: Path, b_path: Path) -> str:
    """'' when both images open with the same windows, channels, channel formats, attributes (but
    WHEN_AND_HOW_LONG) and pixels (every value equal: a half-float EXR read as float is exact);
    else what differs."""
    import OpenImageIO as oiio
    a, b = oiio.ImageBuf(str(a_path)), oiio.ImageBuf(str(b_path))
    for buf, path in ((a, a_path), (b, b_path)):
        if not buf.read(0, 0, True) or buf.has_error:
            return f"{path} does not open: {buf.geterror()}"
    header_a, header_b = _header(a.spec()), _header(b.spec())
    if header_a != header_b:
        differ = sorted(k for k in header_a.keys() | header_b.keys() if header_a.get(k) != header_b.get(k))
        return "; ".join(f"{k}: {header_a.get(k)!r} in {a_path.name}, {header_b.get(k)!r} in {b_path.name}"
                         for k in differ)
    result = oiio.ImageBufAlgo.compare(a, b, 0.0, 0.0)
    if result.nfail or result.maxerror != 0.0:
        return f"{result.nfail} pixels differ (max {result.maxerror} at {result.maxx},{result.maxy})"
    return ""
