"""DIR/index.html: one page per run that opens from disk (relative links only, no scripts or
styles from elsewhere). For each test the golden, new and difference images side by side, the
metrics and the verdict. An inline script checks on load that every image loaded and writes the
result into #image-check, so a test (and a reader) can tell a complete page from a broken one."""

from __future__ import annotations

import html
import shlex
from pathlib import Path

from darc_regress.outcome import TestOutcome
from darc_regress.preview_images import DIFFERENCE_GAIN

_STYLE = """
body { font-family: sans-serif; margin: 1.5em; color: #222; }
table { border-collapse: collapse; }
td, th { padding: 0.15em 0.8em 0.15em 0; text-align: left; vertical-align: top; }
.verdict { font-weight: bold; padding: 0 0.4em; border-radius: 0.2em; color: white; }
.verdict.pass { background: #2a7d2a; } .verdict.warn { background: #b07a00; }
.verdict.fail { background: #b52020; } .verdict.error { background: #6a1b9a; }
section { border-top: 1px solid #ccc; margin-top: 1.2em; padding-top: 0.4em; }
.images { display: flex; gap: 1em; flex-wrap: wrap; }
figure { margin: 0; width: 288px; }
figure img { width: 100%; image-rendering: pixelated; background: black; display: block; }
.missing { width: 100%; aspect-ratio: 4 / 3; background: #eee; color: #777; display: flex;
           align-items: center; justify-content: center; }
.message { white-space: pre-wrap; font-family: monospace; }
pre { background: #f4f4f4; padding: 0.5em; overflow-x: auto; }
"""

# Runs on load: an image that failed to load has naturalWidth 0.
_IMAGE_CHECK = """
window.addEventListener('load', function () {
  var images = Array.prototype.slice.call(document.images);
  var broken = images.filter(function (i) { return !i.complete || i.naturalWidth === 0; });
  document.getElementById('image-check').textContent = broken.length
      ? 'broken: ' + broken.map(function (i) { return i.getAttribute('src'); }).join(', ')
      : 'all ' + images.length + ' images loaded';
});
"""


def _e(text) -> str:
    return html.escape(str(text))


def _verdict(v: str) -> str:
    return f'<span class="verdict {v}">{v}</span>'


def _figure(src: str | None, caption: str, missing: str) -> str:
    if src is None:
        body = f'<div class="missing">{_e(missing)}</div>'
    else:
        body = f'<a href="{_e(src)}"><img src="{_e(src)}" alt="{_e(caption)}"></a>'
    return f"<figure>{body}<figcaption>{_e(caption)}</figcaption></figure>"


def _metrics_table(o: TestOutcome) -> str:
    t, m = o.case.thresholds, o.metrics
    rows = []
    if m is not None:
        rows += [
            ("mean error", f"{m.mean_error:.6g}"),
            ("RMS error", f"{m.rms_error:.6g}"),
            ("max error", f"{m.max_error:.6g} at pixel ({m.max_x}, {m.max_y}), channel {m.max_channel}"),
            ("pixels over warn", f"{m.over_warn} of {m.pixels} ({m.percent(m.over_warn):.4g} %)"),
            ("pixels over fail", f"{m.over_fail} of {m.pixels} ({m.percent(m.over_fail):.4g} %)"),
        ]
    rows += [
        ("fail thresholds", f"fail {t.fail:g}, failpercent {t.failpercent:g} %, hardfail {t.hardfail:g}"),
        ("warn thresholds", f"warn {t.warn:g}, warnpercent {t.warnpercent:g} %, hardwarn {t.hardwarn:g}"),
        ("render time", f"{o.render.seconds:.2f} s"),
    ]
    return "<table class=\"metrics\">" + "".join(
        f"<tr><th>{_e(k)}</th><td>{_e(v)}</td></tr>" for k, v in rows
    ) + "</table>"


def _section(o: TestOutcome) -> str:
    name = o.case.name
    notes = "".join(f"<p>note: {_e(n)}</p>" for n in o.notes)
    figures = "".join((
        _figure(o.golden_png, "golden", "no golden image"),
        _figure(o.new_png, "new", "no new image"),
        _figure(o.difference_png, f"difference ×{DIFFERENCE_GAIN:g}", "no difference image"),
    ))
    log = f"$ {shlex.join(o.render.command)}\n{o.render.stderr}"
    return (
        f'<section id="test-{_e(name)}" class="test {o.verdict}">'
        f"<h2>{_e(name)} {_verdict(o.verdict)}</h2>"
        f'<p class="message">{_e(o.message)}</p>{notes}'
        f'<div class="images">{figures}</div>{_metrics_table(o)}'
        f"<details{' open' if o.failed else ''}><summary>darc command and stderr</summary>"
        f"<pre>{_e(log)}</pre></details></section>"
    )


def _index(outcomes: list[TestOutcome]) -> str:
    rows = []
    for o in outcomes:
        worst = "" if o.metrics is None else f"{o.metrics.max_error:.3g}"
        rows.append(
            f'<tr><td><a href="#test-{_e(o.case.name)}">{_e(o.case.name)}</a></td>'
            f"<td>{_verdict(o.verdict)}</td><td>{worst}</td><td>{o.render.seconds:.2f} s</td></tr>"
        )
    return "<table class=\"index\"><tr><th>test</th><th>verdict</th><th>max error</th><th>render</th></tr>" + "".join(rows) + "</table>"


def write_html(outcomes: list[TestOutcome], suite_name: str, summary: str, path: Path) -> None:
    title = f"darc-regress: {suite_name}"
    page = (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{_e(title)}</title>'
        f"<style>{_STYLE}</style></head><body><h1>{_e(title)}</h1>"
        f'<p id="summary">{_e(summary)}</p>'
        f'<p>Difference images show {DIFFERENCE_GAIN:g} × the largest channel difference of each pixel '
        "(sRGB-encoded grey); images are premultiplied colour over black. "
        f'Image check: <span id="image-check">did not run (JavaScript is off?)</span></p>'
        f"{_index(outcomes)}{''.join(_section(o) for o in outcomes)}"
        f"<script>{_IMAGE_CHECK}</script></body></html>\n"
    )
    path.write_text(page, encoding="utf-8")
