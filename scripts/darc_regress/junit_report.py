"""DIR/junit.xml: one <testsuite>, one <testcase> per test, in the JUnit form CI systems read
(Jenkins, GitLab, GitHub actions). Verdicts fail and error both give a <failure> (type says which)
so every CI shows them as failed tests; warn passes, with the warning in <system-out>
(first line), before darc's command line and stderr."""

from __future__ import annotations

import shlex
import xml.etree.ElementTree as ET
from pathlib import Path

from darc_regress.comparison import ERROR, FAIL
from darc_regress.outcome import TestOutcome


def _system_out(o: TestOutcome) -> str:
    lines = [f"verdict: {o.verdict}: {o.message}", f"darc command: {shlex.join(o.render.command)}"]
    lines += [f"note: {n}" for n in o.notes]
    lines += ["darc stderr:", o.render.stderr.rstrip() or "(empty)"]
    return "\n".join(lines) + "\n"


def write_junit(outcomes: list[TestOutcome], suite_name: str, seconds: float, path: Path) -> None:
    suite = ET.Element(
        "testsuite",
        name=suite_name,
        tests=str(len(outcomes)),
        failures=str(sum(o.failed for o in outcomes)),
        errors="0",
        skipped="0",
        time=f"{seconds:.3f}",
    )
    for o in outcomes:
        case = ET.SubElement(
            suite, "testcase", name=o.case.name, classname=suite_name, time=f"{o.render.seconds:.3f}"
        )
        if o.verdict in (FAIL, ERROR):
            ET.SubElement(case, "failure", type=o.verdict, message=o.message).text = o.message
        ET.SubElement(case, "system-out").text = _system_out(o)
    ET.indent(suite)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)
