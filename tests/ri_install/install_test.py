#!/usr/bin/env python3
"""An external C program against an installed darc (issue 21's first target).

`cmake --install` of this build into a fresh prefix; then scenes/ri_example/tuft.c is compiled
twice, as users compile against a library: once with the flags `pkg-config darc` gives, once as a
CMake project with find_package(darc) and darc::ri. Each build renders the two frames in its own
process and writes the same requests as RIB; the darc command renders that RIB; every image must
equal the others bit for bit, and show the tuft.

Environment: DARC_BUILD_DIR (the build to install), DARC_SOURCE_DIR, DARC_BINARY.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

BUILD = os.environ["DARC_BUILD_DIR"]
SOURCE = os.environ["DARC_SOURCE_DIR"]
DARC = os.environ["DARC_BINARY"]
EXAMPLE = os.path.join(SOURCE, "scenes", "ri_example")


def run(args, **kw):
    done = subprocess.run(args, capture_output=True, text=True, **kw)
    if done.returncode != 0:
        sys.exit(f"install_test: {' '.join(args)} exited {done.returncode}\n{done.stdout}\n{done.stderr}")
    return done.stdout


def pixels(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        sys.exit(f"install_test: cannot read {path}: {oiio.geterror()}")
    data = image.read_image("float")
    image.close()
    return data


def main():
    with tempfile.TemporaryDirectory() as scratch:
        prefix = os.path.join(scratch, "prefix")
        run(["cmake", "--install", BUILD, "--prefix", prefix])
        libdirs = sorted({os.path.dirname(os.path.join(d, f)) for d, _, files in os.walk(prefix)
                          for f in files if f.startswith("libdarc.so")})
        pcdirs = sorted({d for d, _, files in os.walk(prefix) for f in files if f == "darc.pc"})
        if len(libdirs) != 1 or len(pcdirs) != 1:
            sys.exit(f"install_test: expected one libdarc.so and one darc.pc under {prefix}: {libdirs} {pcdirs}")
        if not os.path.exists(os.path.join(prefix, "include", "darc", "ri.h")):
            sys.exit("install_test: include/darc/ri.h is not installed")
        env = dict(os.environ, PKG_CONFIG_PATH=pcdirs[0], LD_LIBRARY_PATH=libdirs[0])

        # 1. pkg-config, the C compiler.
        flags = run(["pkg-config", "--cflags", "--libs", "darc"], env=env).split()
        pc_tuft = os.path.join(scratch, "tuft-pc")
        run(["cc", "-std=c11", "-Wall", "-Werror", os.path.join(EXAMPLE, "tuft.c"), *flags, "-o", pc_tuft])
        # 2. CMake, find_package(darc).
        cmake_build = os.path.join(scratch, "cmake-build")
        run(["cmake", "-S", EXAMPLE, "-B", cmake_build, f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_BUILD_TYPE=Release"])
        run(["cmake", "--build", cmake_build])
        cmake_tuft = os.path.join(cmake_build, "tuft")

        images = os.path.join(scratch, "images")
        os.mkdir(images)
        run([pc_tuft, os.path.join(images, "pc")], env=env, cwd=images)
        run([cmake_tuft, os.path.join(images, "cmake")], env=env, cwd=images)
        run([pc_tuft, os.path.join(images, "rib"), os.path.join(images, "tuft.rib")], env=env, cwd=images)
        run([DARC, "--quiet", "--trust-rib", "tuft.rib"], cwd=images)

        for frame in ("0001", "0002"):
            reference = pixels(os.path.join(images, f"rib.{frame}.exr"))
            alpha = reference[..., 3]
            if not 0.2 * alpha.size < alpha.sum() < alpha.size:
                sys.exit(f"install_test: frame {frame}: the RIB's image covers {alpha.sum():.1f} of {alpha.size} pixels")
            for way in ("pc", "cmake"):
                image = pixels(os.path.join(images, f"{way}.{frame}.exr"))
                if not np.array_equal(image, reference):
                    diff = np.abs(image - reference).max()
                    sys.exit(f"install_test: frame {frame}: the {way} build's image differs from the RIB's (max {diff})")
        print("install_test: the pkg-config and CMake builds render bitwise as the RIB they write")


if __name__ == "__main__":
    main()
