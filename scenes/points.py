#!/usr/bin/env python3
"""Writes scenes/points.rib: a swirl of sub-pixel RI Points particles beside a tuft of curves,
over a ground plane that catches their shadows. The same output every run (a fixed seed).

    python3 scenes/points.py > scenes/points.rib
"""

import math
import random

PARTICLES = 4000
STRANDS = 60
# Particle widths in world units: at 320 x 240 and this camera a pixel is about 0.012 wide at
# the swirl, so the particles are 1/6 to 1/2 of a pixel across.
MIN_WIDTH, MAX_WIDTH = 0.002, 0.006


def main():
    rng = random.Random(11)
    out = []
    out.append("""# RI Points beside Curves: 4000 particles of sub-pixel size in a swirl, a tuft of 60 strands,
# a ground plane lit by a shadowing distant light. Written by points.py (in this folder).
#   darc scenes/points.rib -o points.exr                      (distance hider, the default)
#   darc scenes/points.rib --hider stochastic -o points-s.exr
Display "points.exr" "file" "rgba"
Format 320 240 1
PixelSamples 1 1
Projection "perspective" "fov" [35]
Translate 0 -0.3 4
Rotate -20 1 0 0
WorldBegin
  LightSource "ambientlight" 1 "intensity" [0.3]
  LightSource "distantlight" 2 "intensity" [1.1] "from" [1 2 -1.5] "to" [0 0 0] "string shadowname" ["raytrace"]
  Surface "matte"
  AttributeBegin
    Color [0.5 0.5 0.45]
    Polygon "P" [-2 0 -2  -2 0 2  2 0 2  2 0 -2]
  AttributeEnd""")
    P, widths, colours = [], [], []
    for i in range(PARTICLES):
        # Three arms of a rising swirl around the y axis.
        arm = i % 3
        s = rng.random()
        angle = arm * 2 * math.pi / 3 + s * 4.0 + rng.gauss(0, 0.12)
        radius = 0.15 + 0.75 * s + rng.gauss(0, 0.03)
        x, z = radius * math.cos(angle), radius * math.sin(angle)
        y = 0.25 + 0.5 * s + rng.gauss(0, 0.04)
        P.append(f"{x - 0.3:.4f} {y:.4f} {z:.4f}")
        widths.append(f"{rng.uniform(MIN_WIDTH, MAX_WIDTH):.4f}")
        warm = 1 - s
        colours.append(f"{0.9:.3f} {0.4 + 0.5 * warm:.3f} {0.2 + 0.6 * s:.3f}")
    out.append("  AttributeBegin")
    out.append('    Points "P" [' + "  ".join(P) + ']')
    out.append('      "width" [' + " ".join(widths) + ']')
    out.append('      "Cs" [' + "  ".join(colours) + ']')
    out.append("  AttributeEnd")
    nvertices, cp = [], []
    for i in range(STRANDS):
        bx, bz = 0.8 + rng.gauss(0, 0.08), 0.2 + rng.gauss(0, 0.08)
        lean_x, lean_z = rng.gauss(0, 0.15), rng.gauss(0, 0.15)
        height = rng.uniform(0.5, 0.8)
        nvertices.append("4")
        for k in range(4):
            t = k / 3
            cp.append(f"{bx + lean_x * t * t:.4f} {height * t:.4f} {bz + lean_z * t * t:.4f}")
    out.append("  AttributeBegin")
    out.append("    Color [0.25 0.18 0.1]")
    out.append('    Curves "cubic" [' + " ".join(nvertices) + '] "nonperiodic" "P" [' + "  ".join(cp) + ']')
    out.append('      "constantwidth" [0.006]')
    out.append("  AttributeEnd")
    out.append("WorldEnd")
    print("\n".join(out))


if __name__ == "__main__":
    main()
