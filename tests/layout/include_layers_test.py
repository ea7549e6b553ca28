#!/usr/bin/env python3
"""The folders follow the data flow, and nothing in a lower stage includes a higher one.

Stages, lowest first (docs/architecture.md says why each is where it is):
  parser/ -> core/math/ -> core/footprint/ -> core/geometry/ -> core/accel/ -> core/scene/
  (core/scene/ris/ below core/scene/builder/) -> shading/ -> integrator/ -> app/ -> ri/ (the RI C
  binding) -> python/ (the Python module)
Inside core/geometry/, the families curves/, points/ and surfaces/ do not include each other
(what they share lives in footprint/ or math/), and surfaces/patches/ and surfaces/subdivision/
only include surfaces/ itself. Also: core/ has at most ten files at its top level.

Exit 0 when every include of parser/, core/, shading/, integrator/, app/, ri/ and python/ keeps the rule; else
the offending includes, one per line (file:line: includes X, which is stage N above).
"""
import os
import re
import sys

ROOT = os.environ.get("DARC_SOURCE_DIR") or os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

# (path prefix, stage) — the longest matching prefix decides.
STAGES = [
    ("parser/", 0),
    ("core/math/", 1),
    ("core/footprint/", 2),
    ("core/geometry/", 3),
    ("core/accel/", 4),
    ("core/scene/ris/", 5),
    ("core/scene/", 6),
    ("core/scene/builder/", 7),
    ("shading/", 8),
    ("integrator/", 9),
    ("app/", 10),
    ("ri/", 11),
    ("python/", 12),
]
GEOMETRY_FAMILIES = ["core/geometry/curves/", "core/geometry/points/", "core/geometry/surfaces/"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def stage_of(path):
    best = None
    for prefix, stage in STAGES:
        if path.startswith(prefix) and (best is None or len(prefix) > len(best[0])):
            best = (prefix, stage)
    return best


def family_of(path):
    for family in GEOMETRY_FAMILIES:
        if path.startswith(family):
            return family
    return None


def problems():
    found = []
    for top in ("parser", "core", "shading", "integrator", "app", "ri", "python"):
        for folder, _, files in os.walk(os.path.join(ROOT, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp", ".inc", ".def")):
                    continue
                path = os.path.relpath(os.path.join(folder, name), ROOT)
                own = stage_of(path)
                if own is None:
                    found.append(f"{path}: not in any stage (a file at core/'s top level?)")
                    continue
                with open(os.path.join(ROOT, path), encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = m.group(1)
                        theirs = stage_of(target)
                        if theirs is None:
                            continue  # tests/, bench/ or a system header written with quotes
                        if theirs[1] > own[1]:
                            found.append(f"{path}:{number}: includes {target}, which is stage {theirs[1]} "
                                         f"({theirs[0]}) above its own {own[1]} ({own[0]})")
                        a, b = family_of(path), family_of(target)
                        if a and b and a != b:
                            found.append(f"{path}:{number}: includes {target}: geometry families do not "
                                         f"include each other ({a} -> {b})")
    top_files = [n for n in os.listdir(os.path.join(ROOT, "core")) if os.path.isfile(os.path.join(ROOT, "core", n))]
    if len(top_files) > 10:
        found.append(f"core/ has {len(top_files)} files at its top level (at most 10): {sorted(top_files)}")
    return found


def main():
    found = problems()
    for p in found:
        print(p)
    if found:
        print(f"include_layers: {len(found)} include(s) break the stage order", file=sys.stderr)
        return 1
    print("include_layers: every include keeps the stage order")
    return 0


if __name__ == "__main__":
    sys.exit(main())
