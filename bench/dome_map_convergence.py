#!/usr/bin/env python3
"""A mapped dome's noise against its sample count: a grey plane, a white and a red diffuse sphere
under a lat-long sky (a blue gradient over a brown ground and a small sun 200 times
brighter), rendered with PxrDomeLight's fixedSampleCount = 16, 64, 256 by both hiders at 1x1,
as RMSE and max error against stochastic 2x2 with 1024 samples (4096 per pixel), with render times measured in the
same run (best of 3).

Usage: bench/dome_map_convergence.py [build/darc] > table.md   (needs numpy and OpenImageIO's Python module)
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import OpenImageIO as oiio

DARC = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "build", "darc")

RIB = """Format 160 120 1
PixelSamples 1 1
PixelFilter "box" 1 1
Projection "perspective" "fov" [40]
Rotate -10 1 0 0
Translate 0 -1 6
WorldBegin
AttributeBegin
Rotate -90 1 0 0
Light "PxrDomeLight" "sky" "string lightColorMap" ["sky.exr"] "int fixedSampleCount" [{samples}]
AttributeEnd
Bxdf "PxrDiffuse" "ground" "color diffuseColor" [0.6 0.6 0.6]
Polygon "P" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]
AttributeBegin
Translate -1.2 1 0
Bxdf "PxrDiffuse" "white" "color diffuseColor" [0.8 0.8 0.8]
Sphere 1 -1 1 360
AttributeEnd
AttributeBegin
Translate 1.2 0.6 0.5
Bxdf "PxrDiffuse" "red" "color diffuseColor" [0.8 0.2 0.1]
Sphere 0.6 -0.6 0.6 360
AttributeEnd
WorldEnd
"""


def write_sky(path):
    w, h = 256, 128
    t = (np.arange(h) + 0.5) / h
    s = (np.arange(w) + 0.5) / w
    sky = np.zeros((h, w, 3), np.float32)
    upper = t < 0.5
    sky[upper] = (np.array([0.3, 0.5, 1.0]) * (1.0 - t[upper])[:, None])[:, None, :]
    sky[~upper] = [0.25, 0.2, 0.15]
    ss, tt = np.meshgrid(s, t)
    sky[(ss - 0.1) ** 2 * 4 + (tt - 0.25) ** 2 < 0.0008] = [200, 180, 150]
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(w, h, 3, "float"))
    out.write_image(sky)
    out.close()


def render(rib, out, hider, n, repeat=3):
    best = None
    for _ in range(repeat):
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
        write_sky(os.path.join(d, "sky.exr"))

        def rib_for(samples):
            path = os.path.join(d, f"sky{samples}.rib")
            with open(path, "w") as f:
                f.write(RIB.format(samples=samples))
            return path

        ref = os.path.join(d, "ref.exr")
        render(rib_for(1024), ref, "stochastic", 2, repeat=1)
        reference = rgb(ref)
        rows = []
        for samples in (16, 64, 256):
            rib = rib_for(samples)
            for hider in ("distance", "stochastic"):
                out = os.path.join(d, f"{hider}{samples}.exr")
                t = render(rib, out, hider, 1)
                err = rgb(out) - reference
                rows.append((samples, hider, t, float(np.sqrt(np.mean(err ** 2))), float(np.abs(err).max())))
        base = next(r[2] for r in rows if r[0] == 16 and r[1] == "distance")
        print("| fixedSampleCount | hider 1x1 | time s | time / distance 16 | RMSE vs stochastic 2x2 x 1024 | max error |")
        print("|---|---|---|---|---|---|")
        for samples, hider, t, rmse, mx in rows:
            print(f"| {samples} | {hider} | {t:.2f} | {t / base:.2f} | {rmse:.4f} | {mx:.3f} |")


if __name__ == "__main__":
    main()
