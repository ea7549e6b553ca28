#!/usr/bin/env python3
"""A RunProgram generator: a square patch of grass blades as cubic Bezier Curves.

    Procedural "RunProgram" ["grass.py" "COUNT SEED [SIZE [HEIGHT]]"] [bound]

The renderer writes one request per line on standard input, "detail data" (RI Spec 3.2,
RiProcRunProgram); for each, this writes the RIB of the patch to standard output and ends it with
the byte \\377. It runs until its input ends, so it serves any number of requests.

The patch is SIZE x SIZE (default 2) on the y = 0 plane, centred at the origin; blades grow along
+y up to HEIGHT (default 0.5) and lean by at most 0.6 HEIGHT, so the bound
[-(SIZE/2 + 0.6 HEIGHT) (SIZE/2 + 0.6 HEIGHT) 0 HEIGHT -(...) (...)] holds them. The same data
gives the same blades. The detail (the bound's area on screen, in pixels) is not used: the count
is the one asked for. Python's standard library only.
"""

import math
import random
import sys

TERMINATOR = b"\377"
# Blade width at the root and the tip, in object space (the tip is not 0: a width of 0 draws nothing).
ROOT_WIDTH = 0.012
TIP_WIDTH = 0.002
# How far a blade tip leans, as a fraction of the blade's height.
MAX_LEAN = 0.6


def parse_data(data):
    fields = data.split()
    if not 2 <= len(fields) <= 4:
        raise ValueError(f'expected "COUNT SEED [SIZE [HEIGHT]]", found "{data}"')
    count, seed = int(fields[0]), int(fields[1])
    size = float(fields[2]) if len(fields) > 2 else 2.0
    height = float(fields[3]) if len(fields) > 3 else 0.5
    if count < 0 or size <= 0 or height <= 0:
        raise ValueError(f"COUNT must be >= 0 and SIZE, HEIGHT > 0, found {data}")
    return count, seed, size, height


def blade(rng, size, height):
    """The four control points of one blade, its root and tip widths, and its colour."""
    x = rng.uniform(-size / 2, size / 2)
    z = rng.uniform(-size / 2, size / 2)
    h = height * rng.uniform(0.5, 1.0)
    angle = rng.uniform(0, 2 * math.pi)
    lean = h * MAX_LEAN * rng.uniform(0.2, 1.0)
    dx, dz = math.cos(angle) * lean, math.sin(angle) * lean
    # The blade rises straight, then bends over: the lean grows with the square of the height.
    points = [(x + dx * t * t, h * t, z + dz * t * t) for t in (0.0, 1 / 3, 2 / 3, 1.0)]
    # The tip's lean shortens its rise, so that the blade keeps its length.
    tip_x, _, tip_z = points[3]
    points[3] = (tip_x, math.sqrt(h * h - lean * lean), tip_z)  # lean < h: MAX_LEAN < 1
    green = rng.uniform(0.35, 0.7)
    colour = (green * rng.uniform(0.3, 0.6), green, green * rng.uniform(0.1, 0.3))
    return points, colour


def patch_rib(data):
    count, seed, size, height = parse_data(data)
    if count == 0:
        return ""
    rng = random.Random(seed)
    points, widths, colours = [], [], []
    for _ in range(count):
        cvs, colour = blade(rng, size, height)
        points.extend(f"{c:.5f}" for p in cvs for c in p)
        widths.extend((f"{ROOT_WIDTH}", f"{TIP_WIDTH}"))
        colours.extend(f"{c:.4f}" for c in colour)
    return (
        'Basis "bezier" 3 "bezier" 3\n'
        f'Curves "cubic" [{" ".join(["4"] * count)}] "nonperiodic"\n'
        f'  "P" [{" ".join(points)}]\n'
        f'  "width" [{" ".join(widths)}]\n'
        f'  "uniform color Cs" [{" ".join(colours)}]\n'
    )


def main():
    out = sys.stdout.buffer
    for line in sys.stdin:
        detail, _, data = line.strip().partition(" ")
        try:
            float(detail)
            rib = patch_rib(data)
        except ValueError as e:
            print(f"grass.py: {e}", file=sys.stderr)
            return 1
        out.write(rib.encode("ascii"))
        out.write(TERMINATOR)
        out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
