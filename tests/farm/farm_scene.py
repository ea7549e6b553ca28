"""The frame sequence the farm tests render: 64x48, a plastic sphere moving left to right in front
of a fan of 40 hair strands that turns a little each frame, lit by a distant light. Each frame
renders in a fraction of a second, except `slow_frame` (16x16 pixel samples instead of 2x2, a
couple of seconds on one core), which gives a test the time to stop a task while it renders."""

from __future__ import annotations

import math
from pathlib import Path

STRANDS = 40
FAST_SAMPLES, SLOW_SAMPLES = 2, 16


def _strands() -> str:
    points = []
    for i in range(STRANDS):
        a = 2 * math.pi * i / STRANDS
        points += [0, 0, 0.8,
                   0.6 * math.cos(a), 0.6 * math.sin(a), 0.5,
                   1.2 * math.cos(a + 0.3), 1.2 * math.sin(a + 0.3), 0.2,
                   1.8 * math.cos(a + 0.5), 1.8 * math.sin(a + 0.5), 0]
    return (f'  Curves "cubic" [{" ".join(["4"] * STRANDS)}] "nonperiodic"\n'
            f'    "P" [{" ".join(f"{v:.4f}" for v in points)}] "constantwidth" [0.03]\n')


def frame_rib(frame: int, frames: int, samples: int, extra_world: str = "") -> str:
    x = -1.5 + 3.0 * (frame - 1) / max(frames - 1, 1)
    return f"""FrameBegin {frame}
Display "frame.{frame:04d}.exr" "file" "rgba"
Format 64 48 1
PixelSamples {samples} {samples}
Projection "perspective" "fov" [40]
Translate 0 0 5
WorldBegin
LightSource "ambientlight" 1 "intensity" [0.2]
LightSource "distantlight" 2 "intensity" [1.0] "from" [-1 1 -2] "to" [0 0 0]
AttributeBegin
  Surface "plastic"
  Color [0.2 0.4 0.9]
  Translate {x:.4f} 0 0
  Sphere 0.6 -0.6 0.6 360
AttributeEnd
AttributeBegin
  Surface "hair"
  Color [0.9 0.6 0.3]
  Rotate {frame * 7} 0 0 1
{_strands()}AttributeEnd
{extra_world}WorldEnd
FrameEnd
"""


def write_sequence_rib(path: Path, frames: int, slow_frame: int | None = None,
                       broken_frame: int | None = None) -> None:
    """Frames 1..frames in one RIB file. `broken_frame` has a scene error (an unknown basis): darc
    renders it without that request, records darc:errors in the image and exits with 3."""
    text = ""
    for f in range(1, frames + 1):
        extra = 'Basis "bsline" 1 "bsline" 1\n' if f == broken_frame else ""
        text += frame_rib(f, frames, SLOW_SAMPLES if f == slow_frame else FAST_SAMPLES, extra)
    path.write_text(text)
