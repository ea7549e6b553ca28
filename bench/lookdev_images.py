#!/usr/bin/env python3
"""The lookdev report's images (issue 19, item 6): the demo tuft (scenes/demo/hair.rib.gz) with
the Chiang et al. 2016 fibre and with Kajiya-Kay, under its two shadowing spot lights, under a rect
light and under a dome with ray-traced shadows; distance hider, default settings, 240x240.
Writes docs/lookdev/*.png (8-bit previews through the OpenColorIO display transform) and prints
the markdown table that docs/lookdev.md holds, with each render's seconds.

Usage: bench/lookdev_images.py [build/darc] > /tmp/lookdev-table.md

The images and what they show are in docs/lookdev.md ("The demo tuft under three lights"): the
Chiang tuft is dark under the overhead rect light and the dome over the floor because a fibre sends
light back along the specular cone of its tangent (theta_i = -theta_o): a camera looking down at
near-vertical strands sees what comes from below the horizon, which the floor blocks, and neither
light bounced off the floor nor light scattered from strand to strand is traced.
"""
import gzip
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DARC = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "darc")
OUT = os.path.join(ROOT, "docs", "lookdev")
SIZE = 240

SPOTS = (
    'LightSource "ambientlight" 1 "intensity" [0.08]\n'
    'LightSource "shadowspot" 2 "intensity" [35] "from" [-2.5 4.5 2.5] "to" [0.4 0.2 -0.4] '
    '"coneangle" [0.42] "conedeltaangle" [0.1] "string shadowname" ["raytrace"]\n'
    'LightSource "shadowspot" 3 "intensity" [30] "from" [1 3 -4] "to" [0.4 0.2 -0.4] '
    '"coneangle" [0.5] "conedeltaangle" [0.1] "string shadowname" ["raytrace"]\n'
)
# A 2 x 2 rect light 3 above the tuft, turned to face down (Rotate 90 about x takes its own +z to
# world -y), a little to the upper left; light 3 stays declared (the floor's Illuminate 3 0 names it) but dark.
RECT = (
    "AttributeBegin\n"
    "Translate -1 3 1\n"
    "Rotate 90 1 0 0\n"
    "Scale 2 2 1\n"
    'LightSource "rectlight" 2 "intensity" [12] "string shadowname" ["raytrace"] "int nsamples" [16]\n'
    "AttributeEnd\n"
    "Illuminate 2 1\n"  # a light declared in an attribute block is off after it (RI Spec 3.2 §4.3)
    'LightSource "ambientlight" 3 "intensity" [0]\n'
)
DOME = (
    'LightSource "domelight" 2 "intensity" [0.9] "string shadowname" ["raytrace"] "int nsamples" [64]\n'
    'LightSource "ambientlight" 3 "intensity" [0]\n'
)
CHIANG = 'Surface "chianghair" "float beta_m" [0.2]'
KAJIYA = 'Surface "kajiyakay"'

RENDERS = [
    ("spots-chiang", "two spot lights", "chianghair", SPOTS, CHIANG),
    ("spots-kajiyakay", "two spot lights", "kajiyakay", SPOTS, KAJIYA),
    ("rect-chiang", "rect light", "chianghair", RECT, CHIANG),
    ("rect-kajiyakay", "rect light", "kajiyakay", RECT, KAJIYA),
    ("dome-chiang", "dome", "chianghair", DOME, CHIANG),
    ("dome-kajiyakay", "dome", "kajiyakay", DOME, KAJIYA),
]


def variant(text, lights, surface):
    text = text.replace("Format 480 480 1", f"Format {SIZE} {SIZE} 1")
    text = text.replace(SPOTS, lights)
    assert lights in text, "the demo's lights were not found"
    text = text.replace(CHIANG, surface)
    return text


def main():
    with gzip.open(os.path.join(ROOT, "scenes", "demo", "hair.rib.gz"), "rt") as f:
        demo = f.read()
    os.makedirs(OUT, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, light, shader, lights, surface in RENDERS:
            rib = os.path.join(tmp, name + ".rib")
            with open(rib, "w") as f:
                f.write(variant(demo, lights, surface))
            png = os.path.join(OUT, name + ".png")
            start = time.time()
            subprocess.run([DARC, "-q", "--threads", "2", "-o", os.path.join(tmp, name + ".exr"), "--preview", png, rib],
                           check=True)
            rows.append((name, light, shader, time.time() - start))
    print("| light | chianghair (Chiang et al. 2016) | kajiyakay (Kajiya-Kay) |")
    print("|---|---|---|")
    by = {(r[1], r[2]): r for r in rows}
    for light in ("two spot lights", "rect light", "dome"):
        c, k = by[(light, "chianghair")], by[(light, "kajiyakay")]
        print(f"| {light} | ![{c[0]}](lookdev/{c[0]}.png) {c[3]:.1f} s | ![{k[0]}](lookdev/{k[0]}.png) {k[3]:.1f} s |")


if __name__ == "__main__":
    main()
