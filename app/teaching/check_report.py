"""A check's results as text, as JSON and as JUnit XML (for a course's CI)."""
from __future__ import annotations

import xml.etree.ElementTree as ET

from app.model.escape import xml_chars
from app.teaching.checking import CaseResult, Divergence
from app.teaching.student import limits_text


def text_lines(results: list[CaseResult], file: str, against: str,
               limits: dict | None = None) -> list[str]:
    """PASS or FAIL per case with why, the student's traceback where there is one,
    then the count. ``limits`` (student.limits_record) adds the line on the limits."""
    lines = [f"checking {file} against {against}: {len(results)} cases"]
    if limits is not None:
        lines.append(limits_text(limits))
    for result in results:
        if result.passed:
            lines.append(f"PASS  {result.case.name}")
            continue
        lines.append(f"FAIL  {result.case.name}: {result.message()}")
        if result.outcome.kind == "exception":
            lines += ["      " + line for line in result.outcome.error.splitlines()]
    passed = sum(result.passed for result in results)
    lines.append(f"{passed} of {len(results)} cases pass")
    return lines


def _divergence(divergence: Divergence | None):
    if divergence is None:
        return None
    return {"step": divergence.step, "expected": divergence.expected, "got": divergence.got}


def as_json(results: list[CaseResult], file: str, against: str,
            limits: dict | None = None) -> dict:
    cases = [{"name": r.case.name, "args": list(r.case.args), "passed": r.passed,
              "outcome": r.outcome.kind, "error": r.outcome.error or None,
              "message": r.message() or None, "steps": len(r.outcome.steps),
              "reference_divergence": _divergence(r.reference),
              "exact_divergence": _divergence(r.exact), "exact_oracle": r.has_exact,
              "variables_compared": list(r.compared), "seconds": round(r.outcome.seconds, 3)}
             for r in results]
    passed = sum(r.passed for r in results)
    return {"file": file, "against": against, "limits": limits, "cases": cases,
            "passed": passed, "failed": len(results) - passed}


def junit_xml(results: list[CaseResult], file: str, against: str,
              limits: dict | None = None) -> bytes:
    """One testsuite, one testcase per case: a failure for wrong pixels, an error
    for code that raised, looped, crashed or yielded the wrong shape; the
    limits as the suite's property "limits". Names (a file may be called
    anything) pass through xml_chars, so the file always parses."""
    failures = sum(1 for r in results if r.outcome.ok and not r.passed)
    errors = sum(1 for r in results if not r.outcome.ok)
    seconds = sum(r.outcome.seconds for r in results)
    suites = ET.Element("testsuites", tests=str(len(results)), failures=str(failures),
                        errors=str(errors), time=f"{seconds:.3f}")
    suite = ET.SubElement(suites, "testsuite", name=xml_chars(f"{file} against {against}"),
                          tests=str(len(results)), failures=str(failures), errors=str(errors),
                          skipped="0", time=f"{seconds:.3f}")
    if limits is not None:
        properties = ET.SubElement(suite, "properties")
        ET.SubElement(properties, "property", name="limits", value=limits_text(limits))
    for result in results:
        case = ET.SubElement(suite, "testcase", classname=f"rasterlab.check.{against}",
                             name=xml_chars(result.case.name), time=f"{result.outcome.seconds:.3f}")
        if result.passed:
            continue
        tag = "failure" if result.outcome.ok else "error"
        detail = ET.SubElement(case, tag, message=result.message(),
                               type=result.outcome.kind if tag == "error" else "divergence")
        detail.text = result.outcome.error or result.message()
    ET.indent(suites)
    return ET.tostring(suites, encoding="utf-8", xml_declaration=True) + b"\n"
