#!/usr/bin/env python3
"""The Python module `darc` (python/darc_module.cpp), as a pipeline script uses it.

- The same scene (curves, a floor polygon, a sphere, two lights, two frames) given through
  darc.Ri rendered in this process, through darc.Ri written as RIB and rendered by the darc
  command, and as hand-written RIB rendered by the darc command: bitwise the same images.
- Parameter values as lists, tuples, float32 and float64 numpy arrays build the same scene.
- Errors reach a Python error handler with the script's own file and line; they do not raise.
- A Python procedural is called with its bound's area in pixels, inside an attribute block.

Run by ctest with PYTHONPATH=build/python and DARC_BINARY set (tests/CMakeLists.txt).
"""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import OpenImageIO as oiio

import darc

DARC = os.environ["DARC_BINARY"]

STRAND_P = [-0.6, -1, 0, -0.6, -0.6, 0.1, -0.5, -0.2, 0, -0.4, 0.2, -0.1, -0.2, 0.5, 0, 0, 0.8, 0,
            0.3, -1, 0, 0.3, -0.6, 0.1, 0.4, -0.2, 0, 0.5, 0.2, -0.1, 0.7, 0.5, 0, 0.9, 0.8, 0]
WIDTHS = [0.06, 0.05, 0.03, 0.01, 0.08, 0.06, 0.04, 0.02]


def emit_scene(ri, prefix, as_array=lambda v: v):
    for frame in (1, 2):
        ri.FrameBegin(frame)
        ri.Format(64, 48, 1)
        ri.Display(prefix + ".####.exr", "openexr", "rgba")
        ri.Projection(ri.PERSPECTIVE, {ri.FOV: 40})
        ri.Translate(0, 0, 5)
        ri.WorldBegin()
        ri.LightSource("distantlight", {ri.INTENSITY: 1.5, ri.FROM: [0, 1, -1], ri.TO: (0, 0, 0)})
        ri.LightSource("ambientlight", {ri.INTENSITY: 0.1})
        ri.AttributeBegin()
        ri.Color([0.8, 0.3, 0.2])
        ri.Surface("plastic", {ri.KD: 0.7})
        ri.Translate(0, -1, 0)
        ri.Rotate(-90, 1, 0, 0)
        ri.Polygon(4, {ri.P: as_array([-3, -3, 0, 3, -3, 0, 3, 3, 0, -3, 3, 0])})
        ri.AttributeEnd()
        ri.AttributeBegin()
        ri.Rotate(10 * frame, 0, 1, 0)
        ri.Basis(ri.BSPLINEBASIS, ri.BSPLINESTEP, ri.BSPLINEBASIS, ri.BSPLINESTEP)
        ri.Color((0.9, 0.8, 0.5))
        ri.Curves(ri.CUBIC, [6, 6], ri.NONPERIODIC, {ri.P: as_array(STRAND_P), ri.WIDTH: as_array(WIDTHS)})
        ri.AttributeEnd()
        ri.AttributeBegin()
        ri.Translate(1, 0, 0.5)
        ri.Sphere(0.5, -0.5, 0.5, 360)
        ri.AttributeEnd()
        ri.WorldEnd()
        ri.FrameEnd()


def scene_rib(prefix):
    numbers = lambda values: " ".join(repr(v) for v in values)
    rib = ""
    for frame in (1, 2):
        rib += f'FrameBegin {frame}\nFormat 64 48 1\nDisplay "{prefix}.####.exr" "openexr" "rgba"\n'
        rib += 'Projection "perspective" "fov" [40]\nTranslate 0 0 5\nWorldBegin\n'
        rib += 'LightSource "distantlight" 1 "intensity" [1.5] "from" [0 1 -1] "to" [0 0 0]\n'
        rib += 'LightSource "ambientlight" 2 "intensity" [0.1]\n'
        rib += 'AttributeBegin\nColor [0.8 0.3 0.2]\nSurface "plastic" "Kd" [0.7]\nTranslate 0 -1 0\n'
        rib += 'Rotate -90 1 0 0\nPolygon "P" [-3 -3 0 3 -3 0 3 3 0 -3 3 0]\nAttributeEnd\n'
        rib += f'AttributeBegin\nRotate {10 * frame} 0 1 0\nBasis "b-spline" 1 "b-spline" 1\nColor [0.9 0.8 0.5]\n'
        rib += f'Curves "cubic" [6 6] "nonperiodic" "P" [{numbers(STRAND_P)}] "width" [{numbers(WIDTHS)}]\n'
        rib += 'AttributeEnd\nAttributeBegin\nTranslate 1 0 0.5\nSphere 0.5 -0.5 0.5 360\nAttributeEnd\n'
        rib += 'WorldEnd\nFrameEnd\n'
    return rib


def pixels(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        raise AssertionError(f"cannot read {path}: {oiio.geterror()}")
    data = image.read_image("float")
    image.close()
    return data


def run_darc(folder, *args):
    done = subprocess.run([DARC, "--quiet", *args], cwd=folder, capture_output=True, text=True)
    if done.returncode != 0:
        raise AssertionError(f"darc {' '.join(args)} exited {done.returncode}: {done.stderr}")


class SameImageWhicheverWay(unittest.TestCase):
    def test_python_calls_render_bitwise_as_rib_text(self):
        with tempfile.TemporaryDirectory() as folder:
            ri = darc.Ri()
            ri.Begin(ri.RENDER)
            emit_scene(ri, os.path.join(folder, "inprocess"))
            ri.End()
            ri.Begin(os.path.join(folder, "written.rib"))
            emit_scene(ri, os.path.join(folder, "written"))
            ri.End()
            run_darc(folder, "--trust-rib", "written.rib")
            with open(os.path.join(folder, "hand.rib"), "w") as f:
                f.write(scene_rib("hand"))
            run_darc(folder, "hand.rib")
            for frame in ("0001", "0002"):
                hand = pixels(os.path.join(folder, f"hand.{frame}.exr"))
                self.assertGreater(hand[..., 3].sum(), 0.3 * 64 * 48)
                for way in ("inprocess", "written"):
                    other = pixels(os.path.join(folder, f"{way}.{frame}.exr"))
                    self.assertTrue(np.array_equal(hand, other), f"{way} frame {frame} differs from the RIB text")

    def test_lists_tuples_and_numpy_arrays_build_the_same_scene(self):
        with tempfile.TemporaryDirectory() as folder:
            images = {}
            for name, convert in (("list", list), ("tuple", tuple),
                                  ("f32", lambda v: np.asarray(v, dtype=np.float32)),
                                  ("f64", lambda v: np.asarray(v, dtype=np.float64)),
                                  ("f32_2d", lambda v: np.asarray(v, dtype=np.float32).reshape(-1, len(v) // 2))):
                ri = darc.Ri()
                ri.Begin()
                emit_scene(ri, os.path.join(folder, name), convert)
                ri.End()
                images[name] = pixels(os.path.join(folder, f"{name}.0002.exr"))
            for name, image in images.items():
                self.assertTrue(np.array_equal(image, images["list"]), name)


class CommandOptions(unittest.TestCase):
    def test_begin_takes_the_commands_options_after_darc(self):
        with tempfile.TemporaryDirectory() as folder:
            ri = darc.Ri()
            ri.Begin("darc --hider stochastic --pixel-samples 3 --res 16x12")
            emit_scene(ri, os.path.join(folder, "s"))
            ri.End()
            image = oiio.ImageInput.open(os.path.join(folder, "s.0001.exr"))
            spec = image.spec()
            image.close()
            self.assertEqual((spec.width, spec.height), (16, 12))
            self.assertEqual(spec.get_string_attribute("darc:hider"), "stochastic")
            self.assertEqual(spec.get_int_attribute("darc:spp"), 9)

    def test_a_bad_command_line_raises(self):
        with self.assertRaises(RuntimeError):
            darc.Ri().Begin("darc --no-such-option")


class Turntable(unittest.TestCase):
    def test_the_example_renders_as_the_rib_it_writes(self):
        script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes", "turntable.py")
        with tempfile.TemporaryDirectory() as folder:
            common = ["--frames", "2", "--res", "48", "36"]
            for args in (["inprocess"], ["written", "--rib", "written.rib"]):
                done = subprocess.run([sys.executable, script, os.path.join(folder, args[0]), *args[1:], *common],
                                      cwd=folder, capture_output=True, text=True)
                self.assertEqual(done.returncode, 0, done.stderr)
            run_darc(folder, "--trust-rib", "written.rib")
            first = pixels(os.path.join(folder, "inprocess.0001.exr"))
            self.assertGreater(first[..., 3].min(), 0.99)  # the ground fills the frame
            for number in ("0001", "0002"):
                self.assertTrue(np.array_equal(pixels(os.path.join(folder, f"inprocess.{number}.exr")),
                                               pixels(os.path.join(folder, f"written.{number}.exr"))), number)
            self.assertFalse(np.array_equal(first, pixels(os.path.join(folder, "inprocess.0002.exr"))))


class Errors(unittest.TestCase):
    def test_errors_reach_the_handler_with_the_scripts_line(self):
        with tempfile.TemporaryDirectory() as folder:
            seen = []
            ri = darc.Ri()
            ri.Begin(ri.RENDER)
            ri.ErrorHandler(lambda code, severity, message: seen.append((code, severity, message)))
            ri.Format(8, 8, 1)
            ri.Display(os.path.join(folder, "e.exr"), "openexr", "rgba")
            ri.WorldBegin()
            ri.Sides(3)  # an error: sides are 1 or 2
            line = sys._getframe().f_lineno - 1
            ri.WorldEnd()
            ri.End()
            errors = [s for s in seen if s[1] == ri.RIE_ERROR]
            self.assertEqual(len(errors), 1, seen)
            self.assertIn(f"{__file__}:{line}:1: error: Sides", errors[0][2])
            self.assertEqual(errors[0][0], 43)  # RIE_CONSISTENCY

    def test_a_call_without_begin_raises(self):
        with self.assertRaises(ValueError):
            darc.Ri().WorldBegin()


class Procedurals(unittest.TestCase):
    def test_a_python_procedural_expands_inside_an_attribute_block(self):
        with tempfile.TemporaryDirectory() as folder:
            calls = []

            def grow(data, detail):
                calls.append(detail)
                ri.Sphere(data, -data, data, 360)

            ri = darc.Ri()
            ri.Begin()
            ri.Format(32, 24, 1)
            ri.Display(os.path.join(folder, "p.exr"), "openexr", "rgba")
            ri.Projection(ri.PERSPECTIVE)
            ri.Translate(0, 0, 5)
            ri.WorldBegin()
            freed = []
            ri.Procedural(1.0, [-1, 1, -1, 1, -1, 1], grow, freed.append)
            ri.WorldEnd()
            ri.End()
            self.assertEqual(calls, [36.0])  # the box's near face: 6 x 6 pixels
            self.assertEqual(freed, [1.0])
            self.assertGreater(pixels(os.path.join(folder, "p.exr"))[12, 16, 3], 0.99)


if __name__ == "__main__":
    unittest.main()
