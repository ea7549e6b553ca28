#!/usr/bin/python3
"""Draws the speed-against-error plot of a CSV that bench/speed_vs_error wrote: per scene, RMSE
(y) against render time (x) on log-log axes, one line per hider (or per contribution-threshold
sweep), with a legend. scripts/bench-speed-vs-error calls it after each run; it can redraw a
committed plot from its committed CSV without rendering anything.

    bench/plot_speed_vs_error.py CSV PNG [--svg SVG] [--scenes-label LABEL | --title TITLE]

Two CSV kinds, told apart by their header:
  settings  (speed-vs-error.csv, -640.csv, -secondary.csv): scene,hider,samples,seconds,rmse,...
            one line per scene and hider (distance, stochastic, embree), through its sample
            counts in increasing order
  sweep     (speed-vs-error-secondary-pruning.csv): scene,hider,samples,threshold,seconds,...,
            rmse_vs_reference,...: one line per scene, hider and sample count, through its
            contribution thresholds in increasing order (0, every secondary ray traced, first)

Colours: one per scene (matplotlib's "tab10", distinguishable for common colour-vision
deficiencies); solid lines and filled markers: the stochastic hider; dashed and hollow: the
distance hider; pale (the scene's colour halfway to white): the Embree peer.

Exit status 0 when the plot was written, 1 when the CSV cannot be read or holds nothing to plot
(nothing is written then) or an output cannot be written, 2 for bad arguments. Outputs are written under a temporary name and
renamed, so a failed run never leaves a half-written PNG.
"""

import argparse
import csv
import math
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

PROGRAM = "plot_speed_vs_error"

# The figure in pixels at FIGURE_DPI: the plot area and a legend column beside it; the size of
# the plots the report committed before (1180 x 720), so that docs/ pages keep their layout.
FIGURE_WIDTH_PX, FIGURE_HEIGHT_PX, FIGURE_DPI = 1180, 720, 100
# Right of this fraction of the figure's width is the legend: a report has up to six scenes of
# three hiders, 18 labels such as "transparent-hair stochastic".
PLOT_RIGHT_FRACTION = 0.72
# How much of the way to white the Embree peer's colour is (it is the same kind of method as the
# stochastic hider, drawn alike but paler).
EMBREE_PALENESS = 0.5
# Axes spanning fewer decades than the first get labels on some minor ticks (2, 3, 4, 6 times a
# decade), fewer than the second on all: a plot of one decade would otherwise show one number.
MINOR_LABEL_DECADES = (2, 0.5)
# Lines per scene in legend order: the methods a settings CSV can hold.
HIDER_ORDER = ("stochastic", "distance", "embree")

SETTINGS_COLUMNS = ("scene", "hider", "samples", "seconds", "rmse")
SWEEP_COLUMNS = ("scene", "hider", "samples", "threshold", "seconds", "rmse_vs_reference")


class CsvError(Exception):
    """A CSV that cannot be plotted; the message says where and why."""


@dataclass
class Series:
    scene: str
    hider: str
    label: str
    points: list = field(default_factory=list)  # (order key, seconds, rmse)


def read_rows(path: Path):
    """The header and the rows of `path` as dicts, with each row's line number."""
    try:
        with path.open(newline="") as f:
            reader = csv.reader(f)
            header = next(reader, None)
            if not header:
                raise CsvError(f"{path}: empty file (expected a header line)")
            rows = []
            for row in reader:
                if not row:
                    continue
                if len(row) != len(header):
                    raise CsvError(f"{path}:{reader.line_num}: {len(row)} fields, the header has {len(header)}")
                rows.append((reader.line_num, dict(zip(header, row))))
            return header, rows
    except OSError as e:
        raise CsvError(f"{path}: cannot read: {e.strerror}") from e
    except (csv.Error, UnicodeDecodeError) as e:
        raise CsvError(f"{path}: not a CSV file: {e}") from e


def number(path: Path, line: int, row: dict, column: str) -> float:
    try:
        value = float(row[column])
    except ValueError:
        raise CsvError(f"{path}:{line}: column '{column}' is not a number: '{row[column]}'") from None
    if not math.isfinite(value):
        raise CsvError(f"{path}:{line}: column '{column}' is not finite: '{row[column]}'")
    return value


def samples_label(samples_per_pixel: float) -> str:
    """'2x2' for 4 samples per pixel (the benchmark's N x N settings)."""
    n = math.isqrt(int(samples_per_pixel))
    return f"{n}x{n}" if n * n == samples_per_pixel else f"{samples_per_pixel:g} spp"


def read_series(path: Path):
    """The series of `path` in first-seen scene order, and whether it is a sweep CSV."""
    header, rows = read_rows(path)
    sweep = "threshold" in header
    needed = SWEEP_COLUMNS if sweep else SETTINGS_COLUMNS
    missing = [c for c in needed if c not in header]
    if missing:
        raise CsvError(f"{path}:1: no column {', '.join(repr(c) for c in missing)} "
                       f"(expected the header of bench/speed_vs_error's CSV: {','.join(needed)},...)")
    rmse_column = "rmse_vs_reference" if sweep else "rmse"
    series = {}
    for line, row in rows:
        samples = number(path, line, row, "samples")
        seconds = number(path, line, row, "seconds")
        rmse = number(path, line, row, rmse_column)
        if sweep:
            key = (row["scene"], row["hider"], samples)
            label = f"{row['scene']} {row['hider']} {samples_label(samples)}"
            order = number(path, line, row, "threshold")
        else:
            key = (row["scene"], row["hider"])
            label = f"{row['scene']} {row['hider']}"
            order = samples
        s = series.setdefault(key, Series(row["scene"], row["hider"], label))
        # A log axis has no place for a zero time or error (an image equal to its reference).
        if seconds > 0 and rmse > 0:
            s.points.append((order, seconds, rmse))
    plotted = [s for s in series.values() if s.points]
    if not plotted:
        raise CsvError(f"{path}: no row with a positive time and RMSE to plot")
    for s in plotted:
        s.points.sort()
    return plotted, sweep


def legend_order(series, sweep: bool):
    """Scenes in the order of the CSV; within one, stochastic, distance, embree (settings) or
    the CSV's order (sweeps)."""
    scenes = list(dict.fromkeys(s.scene for s in series))

    def key(s):
        rank = HIDER_ORDER.index(s.hider) if (not sweep and s.hider in HIDER_ORDER) else len(HIDER_ORDER)
        return scenes.index(s.scene), rank

    return sorted(series, key=key), scenes  # sorted() keeps the CSV's order among equal keys


def default_title(series, sweep: bool, scenes_label: str) -> str:
    if sweep:
        thresholds = sorted({p[0] for s in series for p in s.points})
        # "0, 0.0001 .. 0.1": zero (every ray traced) is no step of the logarithmic sweep.
        first = thresholds[:2] if thresholds[0] == 0 and len(thresholds) > 2 else thresholds[:1]
        span = ", ".join(f"{t:g}" for t in first) + (f" .. {thresholds[-1]:g}" if len(thresholds) > len(first) else "")
        return f"darc: contribution thresholds {span} along each line (RMSE against the reference)"
    styles = "solid: stochastic, dashed: distance"
    if any(s.hider == "embree" for s in series):
        styles += ", pale: Embree"
    scenes = f"{scenes_label} scenes; " if scenes_label else ""
    return f"darc: RMSE against render time ({scenes}{styles})"


def plain_log_labels(minor: bool):
    """A tick formatter for a log axis that writes plain numbers ("0.01", "1", "100"; "1e-05"
    far from 1) on the ticks matplotlib's LogFormatter would label: the decades, and minor ticks
    as MINOR_LABEL_DECADES says."""
    from matplotlib import ticker

    class PlainLogLabels(ticker.Formatter):
        def __init__(self):
            self.chooser = ticker.LogFormatter(labelOnlyBase=not minor, minor_thresholds=MINOR_LABEL_DECADES)

        def set_axis(self, axis):
            super().set_axis(axis)
            self.chooser.set_axis(axis)

        def set_locs(self, locs):
            self.chooser.set_locs(locs)

        def __call__(self, x, pos=None):
            return f"{x:g}" if self.chooser(x, pos) else ""

    return PlainLogLabels()


def draw(series, sweep: bool, title: str, outputs):
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    from matplotlib import pyplot as plt

    matplotlib.rcParams["svg.fonttype"] = "none"  # SVG text stays text: smaller, searchable
    matplotlib.rcParams["svg.hashsalt"] = "darc"  # the same SVG for the same CSV
    ordered, scenes = legend_order(series, sweep)
    palette = matplotlib.colormaps["tab10"].colors

    fig = plt.figure(figsize=(FIGURE_WIDTH_PX / FIGURE_DPI, FIGURE_HEIGHT_PX / FIGURE_DPI), dpi=FIGURE_DPI)
    ax = fig.add_axes((0.08, 0.09, PLOT_RIGHT_FRACTION - 0.08, 0.84))
    for s in ordered:
        color = palette[scenes.index(s.scene) % len(palette)]
        if s.hider == "embree":
            color = tuple(c + EMBREE_PALENESS * (1 - c) for c in color)
        dashed = s.hider == "distance"
        ax.plot([p[1] for p in s.points], [p[2] for p in s.points], label=s.label, color=color,
                linestyle="--" if dashed else "-", linewidth=1.4, marker="s", markersize=6,
                markerfacecolor="white" if dashed else color, markeredgecolor=color)
    ax.set_xscale("log")
    ax.set_yscale("log")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(plain_log_labels(minor=False))
        axis.set_minor_formatter(plain_log_labels(minor=True))
    ax.grid(True, which="major", color="0.78", linewidth=0.8)
    ax.grid(True, which="minor", color="0.92", linewidth=0.6)
    ax.set_axisbelow(True)
    ax.set_xlabel("render time (s)")
    ax.set_ylabel("RMSE against the reference (scene-linear RGBA)")
    ax.set_title(title, fontsize=12)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False, borderaxespad=0)
    try:
        for path in outputs:
            temp = path.with_name(path.name + ".tmp-plot" + path.suffix)  # .tmp-* is in .gitignore
            try:
                # No version or date in the file: the same CSV gives the same bytes.
                fig.savefig(temp, dpi=FIGURE_DPI,
                            metadata={"Software": None} if path.suffix == ".png" else {"Date": None})
                os.replace(temp, path)
            finally:
                temp.unlink(missing_ok=True)
    finally:
        plt.close(fig)


def main(argv) -> int:
    parser = argparse.ArgumentParser(prog=PROGRAM, description=__doc__.split("\n\n")[0])
    parser.add_argument("csv", type=Path, help="a CSV written by bench/speed_vs_error")
    parser.add_argument("png", type=Path, help="the plot to write")
    parser.add_argument("--svg", type=Path, help="also write the plot as SVG here")
    parser.add_argument("--title", help="the plot's title (default: what the lines show)")
    parser.add_argument("--scenes-label", default="",
                        help="the scenes measured, for the default title of a settings CSV ('640': '640 scenes')")
    args = parser.parse_args(argv)
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print(f"{PROGRAM}: error: needs matplotlib (Debian's python3-matplotlib: scripts/setup --bench)",
              file=sys.stderr)
        return 1
    try:
        series, sweep = read_series(args.csv)
    except CsvError as e:
        print(f"{PROGRAM}: error: {e}", file=sys.stderr)
        return 1
    outputs = [args.png] + ([args.svg] if args.svg else [])
    try:
        draw(series, sweep, args.title or default_title(series, sweep, args.scenes_label), outputs)
    except OSError as e:
        print(f"{PROGRAM}: error: cannot write {e.filename}: {e.strerror}", file=sys.stderr)
        return 1
    print(f"wrote {', '.join(str(p) for p in outputs)}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
