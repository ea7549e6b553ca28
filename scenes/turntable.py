#!/usr/bin/env python3
"""A camera orbit around the demo tuft (scenes/demo/hair.rib.gz), made with darc's Python module.

    PYTHONPATH=build/python python3 scenes/turntable.py out/turntable
        renders out/turntable.0001.exr ... out/turntable.0024.exr in this process
    PYTHONPATH=build/python python3 scenes/turntable.py out/turntable --rib out/turntable.rib
        writes the same requests as RIB (render it with: build/darc --trust-rib out/turntable.rib)

Options: --frames N (24), --res WIDTH HEIGHT (320 240), --demo FILE (the RIB whose strands are
orbited). The strands are the demo's `Curves` block, copied once into PREFIX-tuft.rib and read by
every frame with ReadArchive (darc parses it once for the run); lights and ground are the demo's.
"""
import argparse
import gzip
import os
import sys

import darc

HERE = os.path.dirname(os.path.abspath(__file__))


def tuft_block(demo):
    """The demo's attribute block that holds its Curves, as RIB text."""
    with gzip.open(demo, "rt") if demo.endswith(".gz") else open(demo) as f:
        text = f.read()
    at = text.find("Curves ")
    if at < 0:
        sys.exit(f"turntable: no Curves in {demo}")
    begin = text.rfind("AttributeBegin", 0, at)
    end = text.find("AttributeEnd", at)
    return text[begin:end + len("AttributeEnd")] + "\n"


def frame(ri, number, frames, prefix, size, tuft):
    ri.FrameBegin(number)
    ri.Format(size[0], size[1], 1)
    ri.Display(f"{prefix}.####.exr", "openexr", "rgba")
    ri.PixelSamples(1, 1)
    ri.PixelFilter("box", 1, 1)
    ri.Projection(ri.PERSPECTIVE, {ri.FOV: 30})
    ri.Translate(0, 0, 5.5)
    ri.Rotate(-25, 1, 0, 0)
    ri.Rotate(360.0 * (number - 1) / frames, 0, 1, 0)  # the orbit: the world turns under the camera
    ri.Translate(-0.45, -0.45, 0.3)
    ri.WorldBegin()
    ri.LightSource("ambientlight", {ri.INTENSITY: 0.08})
    spot = {"coneangle": 0.42, "conedeltaangle": 0.1, "string shadowname": "raytrace"}
    ri.LightSource("shadowspot", {ri.INTENSITY: 35, ri.FROM: [-2.5, 4.5, 2.5], ri.TO: [0.4, 0.2, -0.4], **spot})
    back = ri.LightSource("shadowspot", {ri.INTENSITY: 30, ri.FROM: [1, 3, -4], ri.TO: [0.4, 0.2, -0.4],
                                         "coneangle": 0.5, "conedeltaangle": 0.1, "string shadowname": "raytrace"})
    ri.AttributeBegin()
    ri.Color([0.6, 0.6, 0.58])
    ri.Surface("matte")
    ri.Illuminate(back, False)
    ri.Polygon(4, {ri.P: [-20, 0, -20, 20, 0, -20, 20, 0, 20, -20, 0, 20]})
    ri.AttributeEnd()
    ri.ReadArchive(tuft)
    ri.WorldEnd()
    ri.FrameEnd()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("prefix", help="images are PREFIX.####.exr")
    parser.add_argument("--rib", help="write RIB to this file instead of rendering")
    parser.add_argument("--frames", type=int, default=24)
    parser.add_argument("--res", type=int, nargs=2, default=[320, 240], metavar=("WIDTH", "HEIGHT"))
    parser.add_argument("--demo", default=os.path.join(HERE, "demo", "hair.rib.gz"))
    args = parser.parse_args()

    prefix = os.path.abspath(args.prefix)
    os.makedirs(os.path.dirname(prefix), exist_ok=True)
    tuft = prefix + "-tuft.rib"
    with open(tuft, "w") as f:
        f.write(tuft_block(args.demo))
    ri = darc.Ri()
    ri.Begin(args.rib if args.rib else ri.RENDER)
    for number in range(1, args.frames + 1):
        frame(ri, number, args.frames, prefix, args.res, tuft)
    ri.End()


if __name__ == "__main__":
    main()
