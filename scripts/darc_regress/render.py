"""Running darc on one test's RIB file, and reading what the image says about scene errors."""

from __future__ import annotations

import dataclasses
import subprocess
import time
from pathlib import Path

import OpenImageIO as oiio

from darc_regress.suite import TestCase


@dataclasses.dataclass
class RenderResult:
    command: list[str]
    exit_code: int | None  # None: stopped at the timeout
    stderr: str
    seconds: float
    image: Path  # the new image; exists only when darc wrote it
    problem: str = ""  # why the render counts as an error; empty when it succeeded


def _has_option(args: tuple[str, ...], option: str) -> bool:
    return any(a == option or a.startswith(option + "=") for a in args)


def darc_command(darc: Path, case: TestCase, image: Path, threads: int) -> list[str]:
    """--quiet and -o are ours; --threads only when the test's own args do not set it (CLI11
    rejects an option given twice)."""
    command = [str(darc), "--quiet"]
    if not _has_option(case.args, "--threads"):
        command += ["--threads", str(threads)]
    return command + list(case.args) + ["-o", str(image), str(case.rib.resolve())]


def _scene_errors(image: Path) -> str:
    """darc:errors (int) and darc:first_error (string), written by darc into images rendered
    from scenes with errors; absent attributes mean no errors."""
    reader = oiio.ImageInput.open(str(image))
    if reader is None:
        return f"cannot read the new image {image}: {oiio.geterror()}"
    try:
        count = reader.spec().getattribute("darc:errors")
        first = reader.spec().getattribute("darc:first_error")
    finally:
        reader.close()
    if count is None or int(count) <= 0:
        return ""
    return f"the image has darc:errors = {int(count)}" + (f": {first}" if first else "")


def _last_lines(text: str, count: int = 5) -> str:
    lines = [line for line in text.strip().splitlines() if line.strip()]
    return "\n".join(lines[-count:])


def render(darc: Path, case: TestCase, image: Path, threads: int) -> RenderResult:
    """Renders `case` into `image`, with the suite folder as the working directory (so relative
    ReadArchive and Display names resolve as they do for the suite's author)."""
    command = darc_command(darc, case, image, threads)
    image.unlink(missing_ok=True)
    start = time.monotonic()
    try:
        done = subprocess.run(
            command, cwd=case.rib.resolve().parent, stdin=subprocess.DEVNULL, capture_output=True,
            text=True, errors="replace", timeout=case.timeout,
        )
        exit_code, stderr = done.returncode, done.stderr
    except subprocess.TimeoutExpired as e:
        exit_code = None
        stderr = e.stderr.decode(errors="replace") if isinstance(e.stderr, bytes) else (e.stderr or "")
    except OSError as e:  # darc missing or not executable
        exit_code, stderr = 127, f"cannot run {command[0]}: {e}"
    result = RenderResult(command, exit_code, stderr, time.monotonic() - start, image)
    if exit_code is None:
        result.problem = f"darc did not finish within {case.timeout:g} s (the test's timeout)"
    elif exit_code != 0:
        result.problem = f"darc exited with code {exit_code}"
        if stderr.strip():
            result.problem += ":\n" + _last_lines(stderr)
    elif not image.exists():
        result.problem = f"darc exited with 0 but wrote no image {image}"
    else:
        result.problem = _scene_errors(image)
    return result
