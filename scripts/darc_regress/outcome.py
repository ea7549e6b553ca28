"""One test from start to verdict: render, approve on request (--update), compare with the
golden image, write the report's PNGs."""

from __future__ import annotations

import dataclasses
import shlex
import shutil
from pathlib import Path

from darc_regress import comparison, preview_images
from darc_regress.comparison import ERROR, PASS, Metrics
from darc_regress.render import RenderResult, render
from darc_regress.suite import TestCase


@dataclasses.dataclass
class TestOutcome:
    case: TestCase
    verdict: str  # comparison.PASS, WARN, FAIL or ERROR
    message: str
    render: RenderResult
    metrics: Metrics | None = None
    approved: bool = False  # --update copied this render to the golden image
    # The report's PNGs, relative to the output folder; None where there is no such image.
    golden_png: str | None = None
    new_png: str | None = None
    difference_png: str | None = None
    notes: list[str] = dataclasses.field(default_factory=list)  # e.g. a PNG that failed to write

    @property
    def failed(self) -> bool:
        return self.verdict not in (PASS, comparison.WARN)


@dataclasses.dataclass(frozen=True)
class RunSettings:
    darc: Path
    out: Path  # the output folder; renders go to out/renders, PNGs to out/images
    threads: int  # darc's --threads for each render
    update_command: str  # the command line that approves tests, but for their names


RENDERS_FOLDER = "renders"
IMAGES_FOLDER = "images"


def run_test(case: TestCase, settings: RunSettings, approve: bool) -> TestOutcome:
    new_image = settings.out / RENDERS_FOLDER / f"{case.name}.exr"
    rendered = render(settings.darc, case, new_image, settings.threads)
    outcome = TestOutcome(case, ERROR, rendered.problem, rendered)
    new_buf = None
    if new_image.exists():
        new_buf, problem = comparison.read_image(new_image)
        if new_buf is None and not rendered.problem:
            outcome.message = problem
        if new_buf is not None:
            outcome.new_png = _png(outcome, new_buf, "new", preview_images.write_image_png, settings.out)
    if rendered.problem or new_buf is None:
        return outcome  # a failed render is never approved
    if approve:
        case.golden.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(new_image, case.golden)
        outcome.approved = True
    if not case.golden.exists():
        command = f"{settings.update_command} {shlex.quote(case.name)}"
        outcome.message = f"no golden image {case.golden}; to approve this render as the golden image, run: {command}"
        return outcome
    golden_buf, problem = comparison.read_image(case.golden)
    if golden_buf is None:
        outcome.message = problem
        return outcome
    outcome.golden_png = _png(outcome, golden_buf, "golden", preview_images.write_image_png, settings.out)
    result = comparison.compare_images(golden_buf, new_buf, case.thresholds)
    outcome.verdict, outcome.message, outcome.metrics = result.verdict, result.message, result.metrics
    if result.metrics is not None:
        outcome.difference_png = _png(
            outcome, (golden_buf, new_buf), "difference", preview_images.write_difference_png, settings.out
        )
    if outcome.approved:
        outcome.message = f"approved: this render is now {case.golden}; " + outcome.message
    return outcome


def _png(outcome: TestOutcome, image, kind: str, write, out: Path) -> str | None:
    relative = f"{IMAGES_FOLDER}/{outcome.case.name}.{kind}.png"
    images = image if isinstance(image, tuple) else (image,)
    problem = write(*images, out / relative)
    if problem:
        outcome.notes.append(problem)
        return None
    return relative
