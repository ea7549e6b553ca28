#!/usr/bin/env python3
"""Texture aliasing on a receding checkerboard: the distance hider at 1x1 with lookups filtered by
the footprint against the stochastic hider's N x N point-sampled lookups, as RMSE and max error
against stochastic 16x16, with render times measured in the same run (best of 3).

Usage: bench/texture_aliasing.py [build/darc] > table.md   (needs oiiotool, maketx, numpy, OIIO)
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import OpenImageIO as oiio

DARC = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "build", "darc")

RIB = """Format {w} {h} 1
PixelSamples 1 1
PixelFilter "box" 1 1
Projection "perspective" "fov" [50]
Rotate -15 1 0 0
Translate 0 -1 1
WorldBegin
LightSource "ambientlight" 1 "intensity" [1]
Surface "paintedplastic" "texturename" ["checker.tx"] "Kd" [0] "Ks" [0]
Polygon "P" [-20 0 0  20 0 0  20 0 60  -20 0 60] "st" [0 0  10 0  10 15  0 15]
WorldEnd
"""


def render(rib, out, hider, n):
    best = None
    for _ in range(3):
        t0 = time.perf_counter()
        subprocess.run([DARC, rib, "-o", out, "--hider", hider, "--pixel-samples", str(n), "--threads", "1"],
                       check=True, capture_output=True)
        t = time.perf_counter() - t0
        best = t if best is None else min(best, t)
    return best


def rgb(path):
    return oiio.ImageBuf(path).get_pixels(oiio.FLOAT)[:, :, :3]


def main():
    with tempfile.TemporaryDirectory() as d:
        subprocess.run(["oiiotool", "--pattern", "checker:width=16:height=16:color1=0.1,0.1,0.1:color2=0.9,0.9,0.9",
                        "256x256", "3", "-d", "float", "-o", os.path.join(d, "checker.exr")], check=True)
        subprocess.run(["maketx", "-o", os.path.join(d, "checker.tx"), os.path.join(d, "checker.exr"),
                        "--wrap", "periodic"], check=True, capture_output=True)
        print("| image | render | time s | time / distance 1x1 | RMSE vs stochastic 16x16 | max error |")
        print("|---|---|---|---|---|---|")
        for w, h in ((160, 120), (320, 240)):
            rib = os.path.join(d, f"plane{w}.rib")
            with open(rib, "w") as f:
                f.write(RIB.format(w=w, h=h))
            ref = os.path.join(d, f"ref{w}.exr")
            render(rib, ref, "stochastic", 16)
            r = rgb(ref)
            runs = [("distance", 1), ("stochastic", 1), ("stochastic", 2), ("stochastic", 4), ("stochastic", 8)]
            base = None
            for hider, n in runs:
                out = os.path.join(d, f"{hider}{n}_{w}.exr")
                t = render(rib, out, hider, n)
                base = base or t
                e = rgb(out) - r
                print(f"| {w}x{h} | {hider} {n}x{n} | {t:.3f} | {t / base:.2f} | {np.sqrt((e ** 2).mean()):.4f} | "
                      f"{np.abs(e).max():.3f} |")


if __name__ == "__main__":
    main()
