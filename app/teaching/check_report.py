"""A check's results as text, as JSON and as JUnit XML (for a course's CI)."""
from __future__ import annotations

import xml.etree.ElementTree as ET

from app.model.escape import foreign_text, xml_chars
from app.teaching.checking import CaseResult, Divergence
from app.teaching.student import limits_text


PRINTED_LINES = 20  # of a failed case's prints, in the text report


def text_lines(results: list[CaseResult], file: str, against: str,
               limits: dict | None = None, isolation: str | None = None) -> list[str]:
    """PASS or FAIL per case with why, the student's traceback and prints
    where there are any, then the count. ``limits`` (student.limits_record)
    adds the line on the limits, ``isolation`` the one on the isolation."""
    lines = head_lines(file, against, len(results), limits, isolation)
    for result in results:
        lines += case_lines(result)
    return lines + [tail_line(results)]


def head_lines(file: str, against: str, count: int, limits: dict | None = None,
               isolation: str | None = None) -> list[str]:
    """The report's first lines: what is checked, the limits, the isolation."""
    lines = [f"checking {foreign_text(file)} against {against}: {count} cases"]
    if limits is not None:
        lines.append(limits_text(limits))
    if isolation is not None:
        lines.append(isolation)
    return lines


def case_lines(result: CaseResult) -> list[str]:
    """One case: PASS, or FAIL with why, the traceback and the prints."""
    if result.passed:
        return [f"PASS  {result.case.name}"]
    lines = [f"FAIL  {result.case.name}: {result.message()}"]
    if result.outcome.kind == "exception":
        lines += ["      " + line for line in result.outcome.error.splitlines()]
    return lines + printed_lines(result.outcome.output)


def tail_line(results: list[CaseResult]) -> str:
    return f"{sum(result.passed for result in results)} of {len(results)} cases pass"


def printed_lines(output: str) -> list[str]:
    """A case's prints under its FAIL line, the first PRINTED_LINES of them."""
    printed = output.rstrip().splitlines()
    if not printed:
        return []
    more = len(printed) - PRINTED_LINES
    return (["      printed:"] + ["      | " + line for line in printed[:PRINTED_LINES]]
            + ([f"      | ... {more:,} more lines"] if more > 0 else []))


def _divergence(divergence: Divergence | None):
    if divergence is None:
        return None
    return {"step": divergence.step, "where": divergence.where, "expected": divergence.expected,
            "got": divergence.got, "explanation": foreign_text(divergence.why) or None}


def as_json(results: list[CaseResult], file: str, against: str,
            limits: dict | None = None, isolation: str | None = None) -> dict:
    cases = [{"name": r.case.name, "args": list(r.case.args), "passed": r.passed,
              "outcome": r.outcome.kind, "error": r.outcome.error or None,
              "message": r.message() or None, "steps": len(r.outcome.steps),
              "reference_divergence": _divergence(r.reference),
              "exact_divergence": _divergence(r.exact), "exact_oracle": r.has_exact,
              "variables_compared": list(r.compared), "output": r.outcome.output,
              "seconds": round(r.outcome.seconds, 3)}
             for r in results]
    passed = sum(r.passed for r in results)
    return {"file": foreign_text(file), "against": against, "limits": limits,
            "isolation": isolation, "cases": cases,
            "passed": passed, "failed": len(results) - passed}


def junit_xml(results: list[CaseResult], file: str, against: str,
              limits: dict | None = None, isolation: str | None = None) -> bytes:
    """One testsuite, one testcase per case: a failure for wrong pixels, an error
    for code that raised, looped, crashed or yielded the wrong shape, the
    student's prints as its system-out; the limits and the isolation as the
    suite's properties. Every text (a file may be called anything, a
    student's message say anything) passes through xml_chars, so the file
    always parses."""
    failures = sum(1 for r in results if r.outcome.ok and not r.passed)
    skipped = sum(1 for r in results if r.outcome.kind == "skipped")
    errors = sum(1 for r in results if not r.outcome.ok) - skipped
    seconds = sum(r.outcome.seconds for r in results)
    suites = ET.Element("testsuites", tests=str(len(results)), failures=str(failures),
                        errors=str(errors), time=f"{seconds:.3f}")
    suite = ET.SubElement(suites, "testsuite", name=xml_chars(f"{file} against {against}"),
                          tests=str(len(results)), failures=str(failures), errors=str(errors),
                          skipped=str(skipped), time=f"{seconds:.3f}")
    named = {"limits": None if limits is None else limits_text(limits), "isolation": isolation}
    if any(value is not None for value in named.values()):
        properties = ET.SubElement(suite, "properties")
        for name, value in named.items():
            if value is not None:
                ET.SubElement(properties, "property", name=name, value=value)
    for result in results:
        case = ET.SubElement(suite, "testcase", classname=f"rasterlab.check.{against}",
                             name=xml_chars(result.case.name), time=f"{result.outcome.seconds:.3f}")
        if result.outcome.kind == "skipped":
            ET.SubElement(case, "skipped", message=xml_chars(result.outcome.error))
        elif not result.passed:
            tag = "failure" if result.outcome.ok else "error"
            detail = ET.SubElement(case, tag, message=xml_chars(result.message()),
                                   type=result.outcome.kind if tag == "error" else "divergence")
            detail.text = xml_chars(result.outcome.error or result.message())
        if result.outcome.output:
            ET.SubElement(case, "system-out").text = xml_chars(result.outcome.output)
    ET.indent(suites)
    return ET.tostring(suites, encoding="utf-8", xml_declaration=True) + b"\n"
