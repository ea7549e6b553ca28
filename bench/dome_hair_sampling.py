#!/usr/bin/env python3
"""Sampling a dome for hair: the demo tuft (chianghair, beta_m 0.2) under a constant dome with
ray-traced shadows, 160x160, distance hider, two threads, rendered by two darc binaries at 16, 64
and 256 dome samples, against the second binary at 1024 samples. Errors are over the hair's
pixels (alpha > 0.5 in a render without the floor) and over the rest. Made to compare a commit
with the one before it: issue 19's MIS (integrator/secondary_rays.cpp) was measured with
  git worktree add /tmp/old 43800c1 && (cd /tmp/old && cmake -S . -B build -G Ninja \
      -DCMAKE_BUILD_TYPE=Release && ninja -C build darc)
  bench/dome_hair_sampling.py /tmp/old/build/darc build/darc

Usage: bench/dome_hair_sampling.py BASE_DARC NEW_DARC   (prints a markdown table)
"""
import gzip
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import lookdev_images  # noqa: E402  (the demo tuft's lights and surfaces)

SIZE = 160


def scene(demo, samples, floor=True):
    dome = lookdev_images.DOME.replace("[64]", f"[{samples}]")
    text = lookdev_images.variant(demo, dome, lookdev_images.CHIANG)
    text = text.replace(f"Format {lookdev_images.SIZE} {lookdev_images.SIZE} 1", f"Format {SIZE} {SIZE} 1")
    if not floor:
        text = "\n".join(l for l in text.split("\n") if not l.startswith('Polygon "P" [-20 0 -20'))
    return text


def render(darc, rib_text, tmp, name):
    rib, exr = os.path.join(tmp, name + ".rib"), os.path.join(tmp, name + ".exr")
    with open(rib, "w") as f:
        f.write(rib_text)
    start = time.time()
    subprocess.run([darc, "-q", "--threads", "2", "-o", exr, rib], check=True)
    seconds = time.time() - start
    return oiio.ImageBuf(exr).get_pixels(oiio.FLOAT), seconds


def main():
    base, new = sys.argv[1], sys.argv[2]
    with gzip.open(os.path.join(os.path.dirname(HERE), "scenes", "demo", "hair.rib.gz"), "rt") as f:
        demo = f.read()
    with tempfile.TemporaryDirectory() as tmp:
        hair = render(new, scene(demo, 16, floor=False), tmp, "mask")[0][..., 3] > 0.5
        ref = render(new, scene(demo, 1024), tmp, "ref")[0][..., :3]
        print("| binary | dome samples | time s | hair RMSE | hair max error | elsewhere RMSE |")
        print("|---|---|---|---|---|---|")
        for label, darc in (("before", base), ("after", new)):
            for n in (16, 64, 256):
                img, seconds = render(darc, scene(demo, n), tmp, f"{label}{n}")
                d = img[..., :3] - ref
                print(f"| {label} | {n} | {seconds:.1f} | {np.sqrt((d[hair] ** 2).mean()):.5f} | "
                      f"{np.abs(d[hair]).max():.4f} | {np.sqrt((d[~hair] ** 2).mean()):.5f} |")


if __name__ == "__main__":
    main()
