"""Comparing a new image with its golden image as idiff does (OpenImageIO's
ImageBufAlgo.compare), and the verdict the thresholds give."""

from __future__ import annotations

import dataclasses

import OpenImageIO as oiio

from darc_regress.suite import Thresholds

PASS, WARN, FAIL, ERROR = "pass", "warn", "fail", "error"
VERDICTS = (PASS, WARN, FAIL, ERROR)


@dataclasses.dataclass
class Metrics:
    """ImageBufAlgo.compare's results. Errors are absolute differences per channel; mean and RMS
    are over every channel of every pixel; a pixel counts over a threshold when any channel is."""

    pixels: int
    mean_error: float
    rms_error: float
    max_error: float
    max_x: int
    max_y: int
    max_channel: str
    over_warn: int
    over_fail: int

    def percent(self, count: int) -> float:
        return 100.0 * count / self.pixels if self.pixels else 0.0


@dataclasses.dataclass
class Comparison:
    verdict: str  # PASS, WARN or FAIL (ERROR is decided before any comparison)
    message: str  # one paragraph: why this verdict, with the numbers
    metrics: Metrics | None  # None when the images could not be compared pixel by pixel


def _shape(spec: oiio.ImageSpec) -> str:
    return f"{spec.width}x{spec.height}, channels {','.join(spec.channelnames)}"


def compare_images(golden: oiio.ImageBuf, new: oiio.ImageBuf, t: Thresholds) -> Comparison:
    g, n = golden.spec(), new.spec()
    if (g.width, g.height, tuple(g.channelnames)) != (n.width, n.height, tuple(n.channelnames)):
        # compare() would quietly compare the overlap: a different shape is a failure itself.
        return Comparison(FAIL, f"the new image is {_shape(n)}; the golden image is {_shape(g)}", None)
    r = oiio.ImageBufAlgo.compare(golden, new, t.fail, t.warn)
    metrics = Metrics(
        pixels=g.width * g.height,
        mean_error=r.meanerror,
        rms_error=r.rms_error,
        max_error=r.maxerror,
        max_x=r.maxx,
        max_y=r.maxy,
        max_channel=g.channelnames[r.maxc] if 0 <= r.maxc < len(g.channelnames) else "?",
        over_warn=r.nwarn,
        over_fail=r.nfail,
    )
    return Comparison(*_verdict(metrics, t), metrics)


def _verdict(m: Metrics, t: Thresholds) -> tuple[str, str]:
    """idiff's rule: fail when more than failpercent % of the pixels are over `fail` or one pixel
    is over `hardfail`; otherwise warn by the same rule with the warn thresholds."""
    summary = (
        f"max error {m.max_error:.6g} at ({m.max_x}, {m.max_y}) channel {m.max_channel}; "
        f"mean {m.mean_error:.3g}, RMS {m.rms_error:.3g}; "
        f"{m.over_fail} pixels over fail {t.fail:g} ({m.percent(m.over_fail):.3g} %, allowed {t.failpercent:g} %), "
        f"{m.over_warn} over warn {t.warn:g} ({m.percent(m.over_warn):.3g} %, allowed {t.warnpercent:g} %)"
    )
    if m.over_fail > t.failpercent / 100.0 * m.pixels:
        return FAIL, f"{m.percent(m.over_fail):.3g} % of the pixels differ by more than fail {t.fail:g}: {summary}"
    if m.max_error > t.hardfail:
        return FAIL, f"a pixel differs by more than hardfail {t.hardfail:g}: {summary}"
    if m.over_warn > t.warnpercent / 100.0 * m.pixels:
        return WARN, f"{m.percent(m.over_warn):.3g} % of the pixels differ by more than warn {t.warn:g}: {summary}"
    if m.max_error > t.hardwarn:
        return WARN, f"a pixel differs by more than hardwarn {t.hardwarn:g}: {summary}"
    return PASS, summary


def read_image(path) -> tuple[oiio.ImageBuf | None, str]:
    """The image, read completely as float; or None and why not."""
    buf = oiio.ImageBuf(str(path))
    if not buf.read(0, 0, True, oiio.FLOAT):
        return None, f"cannot read {path}: {buf.geterror()}"
    return buf, ""
