"""The 8-bit PNG copies the HTML report shows: the golden image, the new image and their
amplified difference."""

from __future__ import annotations

from pathlib import Path

import OpenImageIO as oiio

# The difference image shows DIFFERENCE_GAIN x the largest absolute channel difference of each
# pixel (alpha included), as grey, through the same sRGB encoding as the images: a difference of
# 0.01 shows as sRGB 0.35, one of 0.1 or more as white. Strong enough to find a one-pixel change
# on black, weak enough that the size of a difference still shows.
DIFFERENCE_GAIN = 10.0


def _colour(buf: oiio.ImageBuf) -> oiio.ImageBuf:
    """R, G, B (premultiplied, so this is the image over black); a one-channel image as grey."""
    names = buf.spec().channelnames
    if all(c in names for c in ("R", "G", "B")):
        return oiio.ImageBufAlgo.channels(buf, ("R", "G", "B"))
    return oiio.ImageBufAlgo.channels(buf, (0, 0, 0))


def _write_png(linear: oiio.ImageBuf, path: Path) -> str:
    """Scene-linear to sRGB, 8 bits; returns an error message or ''."""
    display = oiio.ImageBufAlgo.colorconvert(linear, "linear", "sRGB")
    if display.has_error or not display.write(str(path), oiio.UINT8):
        return f"cannot write {path}: {display.geterror() or oiio.geterror()}"
    return ""


def write_image_png(buf: oiio.ImageBuf, path: Path) -> str:
    return _write_png(_colour(buf), path)


def write_difference_png(golden: oiio.ImageBuf, new: oiio.ImageBuf, path: Path) -> str:
    """For images of the same shape only (the caller checks)."""
    difference = oiio.ImageBufAlgo.absdiff(golden, new)
    largest = oiio.ImageBufAlgo.maxchan(difference)
    amplified = oiio.ImageBufAlgo.mul(largest, DIFFERENCE_GAIN)
    grey = oiio.ImageBufAlgo.clamp(oiio.ImageBufAlgo.channels(amplified, (0, 0, 0)), 0.0, 1.0)
    return _write_png(grey, path)
