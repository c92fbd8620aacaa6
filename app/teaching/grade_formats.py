"""A class's results (batch.Graded) in the formats graders read, each
written from the one model:

    text_line     one line per submission, as it finishes
    gradescope    Gradescope's results.json (gradescope-autograders.readthedocs.io, "specs")
    prairielearn  PrairieLearn's external grader results.json (docs "externalGrading",
                  "Grading results"), under its 1 MB limit
    coderunner    Moodle CodeRunner's combinator template grader JSON (CodeRunner
                  documentation, "Combinator-template grading")
    junit_xml     JUnit XML: one testsuite per student, named by the id
    csv_bytes     one row per student
    as_json       every submission and case, for a script

Whatever the student's code wrote (messages, prints) passes through
escape.foreign_text, and is capped per case at CASE_OUTPUT; what goes into
HTML through escape.html_text, into XML through escape.xml_chars and into
CSV through escape.csv_row.
"""
from __future__ import annotations

import csv
import io
import json
import xml.etree.ElementTree as ET

from app.model.escape import csv_row, foreign_text, html_text, xml_chars
from app.teaching import grade_pictures

CASE_OUTPUT = 4000          # characters of a case's prints in a format
PRAIRIELEARN_LIMIT = 1 << 20  # bytes: PrairieLearn's limit on results.json
CSV_HEADER = ("id", "passed", "failed", "score", "max_score", "first_failing_case", "seconds")


def number(value: float):
    """A score as JSON shows it: 3, not 3.0; 2.5 as it is."""
    return int(value) if float(value).is_integer() else round(value, 4)


def printed(case) -> str:
    """What the student's code printed in a case, capped."""
    return foreign_text(case.output.rstrip(), CASE_OUTPUT)


def case_text(case) -> str:
    """A case's message and, capped, what the student's code printed."""
    lines = [foreign_text(case.message())] if not case.passed else ["passed"]
    if case.output.strip():
        lines += ["printed:", printed(case)]
    return "\n".join(lines)


def summary(graded) -> str:
    return (f"{graded.passed} of {len(graded.cases)} cases pass; "
            f"{number(graded.score)} of {number(graded.max_score)} points")


# ------------------------------------------------------------------- text
def text_line(graded) -> str:
    """One line per submission: PASS or FAIL, the id, the counts, the first failure."""
    verdict = "PASS" if graded.failed == 0 else "FAIL"
    line = (f"{verdict}  {foreign_text(graded.id)}: {graded.passed}/{len(graded.cases)} cases, "
            f"{number(graded.score)}/{number(graded.max_score)} points, {graded.seconds:.1f} s")
    first = graded.first_failing()
    if first is not None:
        line += f"; first failing: {first.name}: {foreign_text(first.message())}"
    if graded.skipped:
        line += f" ({graded.skipped} cases not run after time-outs)"
    return line.replace("\n", " ")


def counted(count: int, noun: str) -> str:
    return f"{count} {noun}" + ("" if count == 1 else "s")


def totals_line(results: list, seconds: float) -> str:
    passing = sum(graded.failed == 0 for graded in results)
    return (f"{counted(len(results), 'submission')}: {passing} pass every case, "
            f"{len(results) - passing} fail some; {seconds:.1f} s")


# ------------------------------------------------------------- gradescope
def gradescope(graded, against: str) -> dict:
    """Gradescope's results.json: the total score and one test per case."""
    tests = [{"name": case.name, "score": number(case.points),
              "max_score": number(case.max_points),
              "status": "passed" if case.passed else "failed",
              "output": case_text(case), "visibility": "visible"}
             for case in graded.cases]
    return {"score": number(graded.score), "execution_time": round(graded.seconds, 3),
            "output": f"{against}: {summary(graded)}", "output_format": "text",
            "tests": tests}


# ----------------------------------------------------------- prairielearn
def prairielearn(graded, plan, against: str) -> dict:
    """PrairieLearn's results.json: score in [0, 1], one test per case, and
    the first failing case's pixels as a PNG; outputs are shortened, then
    the picture dropped, until the file is under PRAIRIELEARN_LIMIT."""
    score = graded.score / graded.max_score if graded.max_score else float(graded.failed == 0)
    result = {"gradable": True, "score": round(score, 6),
              "message": f"{against}: {summary(graded)}", "output": "",
              "tests": [{"name": case.name, "points": number(case.points),
                         "max_points": number(case.max_points),
                         "message": "passed" if case.passed else foreign_text(case.message()),
                         "output": printed(case)} for case in graded.cases]}
    diff = grade_pictures.difference(graded, plan)
    if diff is not None:
        result["images"] = [{"label": f"{diff.name}: {grade_pictures.LEGEND}",
                             "url": grade_pictures.png_data_uri(diff)}]
    if _size(result) >= PRAIRIELEARN_LIMIT:
        for test in result["tests"]:
            test["output"] = test["output"][:200]
    if _size(result) >= PRAIRIELEARN_LIMIT:
        result.pop("images", None)
    return result


def _size(value) -> int:
    return len(json.dumps(value).encode("utf-8"))


# ------------------------------------------------------------- coderunner
def coderunner(graded, plan, against: str) -> dict:
    """CodeRunner's combinator grader outcome: the fraction, a result table
    (its first row the header; "iscorrect" shown as a tick or a cross) and
    feedback HTML after it carrying an SVG of the first failing case's pixels."""
    fraction = graded.score / graded.max_score if graded.max_score else float(graded.failed == 0)
    rows = [["iscorrect", "Test", "Expected", "Got"]]
    for case in graded.cases:
        expected, got = _expected_got(case)
        rows.append([int(case.passed), case.name, expected, got])
    epilogue = f"<p>{html_text(against)}: {html_text(summary(graded))}</p>"
    diff = grade_pictures.difference(graded, plan)
    if diff is not None:
        epilogue += (f"<p>{html_text(diff.name)}: {html_text(grade_pictures.LEGEND)}</p>"
                     + grade_pictures.svg(diff))
    return {"fraction": round(fraction, 6), "testresults": rows, "epiloguehtml": epilogue}


def _expected_got(case) -> tuple[str, str]:
    result = case.result
    if case.passed:
        return "", "passed"
    divergence = result.reference or result.exact
    if divergence is not None:
        return (f"step {divergence.step}: {divergence.expected}",
                f"step {divergence.step}: {divergence.got}")
    return "a result", foreign_text(case.message())


# ------------------------------------------------------------ junit / csv
def junit_xml(results: list, against: str, isolation: str | None = None) -> bytes:
    """JUnit XML with one testsuite per student, named by the id, and a
    testcase per case: failure for wrong pixels, error for code that
    raised, looped or crashed, skipped for cases not run after time-outs;
    the capped prints as each case's system-out."""
    counts = [_counts(graded) for graded in results]
    suites = ET.Element("testsuites", tests=str(sum(len(g.cases) for g in results)),
                        failures=str(sum(c[0] for c in counts)),
                        errors=str(sum(c[1] for c in counts)),
                        time=f"{sum(g.seconds for g in results):.3f}")
    for graded, (failures, errors, skipped) in zip(results, counts):
        suite = ET.SubElement(suites, "testsuite", name=xml_chars(graded.id),
                              tests=str(len(graded.cases)), failures=str(failures),
                              errors=str(errors), skipped=str(skipped),
                              time=f"{graded.seconds:.3f}")
        properties = ET.SubElement(suite, "properties")
        named = {"file": str(graded.submission.path), "against": against,
                 "score": str(number(graded.score)), "max_score": str(number(graded.max_score))}
        if isolation is not None:
            named["isolation"] = isolation
        for name, value in named.items():
            ET.SubElement(properties, "property", name=name, value=xml_chars(value))
        for case in graded.cases:
            _testcase(suite, case, against)
    ET.indent(suites)
    return ET.tostring(suites, encoding="utf-8", xml_declaration=True) + b"\n"


def _counts(graded) -> tuple[int, int, int]:
    skipped = graded.skipped
    failures = sum(1 for c in graded.cases if c.result.outcome.ok and not c.passed)
    errors = graded.failed - failures - skipped
    return failures, errors, skipped


def _testcase(suite, case, against: str) -> None:
    element = ET.SubElement(suite, "testcase", classname=f"rasterlab.check.{against}",
                            name=xml_chars(case.name), time=f"{case.seconds:.3f}")
    message = xml_chars(foreign_text(case.message()))
    if case.skipped:
        ET.SubElement(element, "skipped", message=message)
    elif not case.passed:
        outcome = case.result.outcome
        tag = "failure" if outcome.ok else "error"
        detail = ET.SubElement(element, tag, message=message,
                               type="divergence" if outcome.ok else outcome.kind)
        detail.text = xml_chars(foreign_text(outcome.error or case.message()))
    if case.output:
        ET.SubElement(element, "system-out").text = xml_chars(
            foreign_text(case.output, CASE_OUTPUT))


def csv_bytes(results: list) -> bytes:
    """One row per student: id, cases passed and failed, score, most points,
    the first failing case's name and the seconds its grading took."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_HEADER)
    for graded in results:
        first = graded.first_failing()
        writer.writerow(csv_row([foreign_text(graded.id), graded.passed, graded.failed,
                                 number(graded.score), number(graded.max_score),
                                 "" if first is None else first.name,
                                 f"{graded.seconds:.2f}"]))
    return out.getvalue().encode("utf-8")


def as_json(results: list, against: str, limits: dict | None = None,
            isolation: str | None = None) -> dict:
    """Every submission and case as plain data."""
    return {"against": against, "limits": limits, "isolation": isolation,
            "submissions": [
                {"id": foreign_text(g.id), "file": str(g.submission.path), "passed": g.passed,
                 "failed": g.failed, "score": number(g.score), "max_score": number(g.max_score),
                 "seconds": round(g.seconds, 3),
                 "cases": [{"name": c.name, "kind": c.kind, "passed": c.passed,
                            "points": number(c.points), "max_points": number(c.max_points),
                            "outcome": c.result.outcome.kind,
                            "message": foreign_text(c.message()) or None,
                            "output": foreign_text(c.output, CASE_OUTPUT),
                            "seconds": round(c.seconds, 3)} for c in g.cases]}
                for g in results]}
