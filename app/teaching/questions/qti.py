"""A question bank as QTI 2.1 items in an IMS Content Package (a zip), the
form Canvas's "QTI .zip file" import and other QTI tools read.

``imsmanifest.xml`` lists one resource per question (type
``imsqti_item_xmlv2p1``): ``items/qNNNN.xml`` and its picture
``items/qNNNN.png``, shown by an ``img``. CHOICE is a ``choiceInteraction``;
NUMERICAL a ``textEntryInteraction`` of baseType float, scored by ``equal``
with ``toleranceMode`` absolute (lms.tolerance) or exact; SHORT one of
baseType string, scored by ``mapResponse`` over the canonical text and its
other spellings. A ``modalFeedback`` always shows the worked steps once
answered. In a bank of several students, each title starts with the
student's id. The same bank gives the same bytes (fixed zip dates).
"""
from __future__ import annotations

import io
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

from app.model import escape
from app.model.files import Output, check_outputs, not_ours, write_atomically
from app.teaching.questions import lms
from app.teaching.questions.model import CHOICE, NUMERICAL, SHORT, Bank, Question

QTI = "http://www.imsglobal.org/xsd/imsqti_v2p1"
QTI_XSD = "http://www.imsglobal.org/xsd/qti/qtiv2p1/imsqti_v2p1.xsd"
CP = "http://www.imsglobal.org/xsd/imscp_v1p1"
CP_XSD = "http://www.imsglobal.org/xsd/imscp_v1p1.xsd"
XSI = "http://www.w3.org/2001/XMLSchema-instance"
ZIP_DATE = (1980, 1, 1, 0, 0, 0)  # the earliest a zip holds: no time of writing
FEEDBACK = "WORKED"  # the identifier of the worked steps' modalFeedback
sub = ET.SubElement


def outputs(bank: Bank, path) -> list[Output]:
    """What ``write`` writes, for the output policy (app/model/files.py)."""
    return [Output("--out", Path(path), foreign=not_ours("zip"))]


def write(bank: Bank, path: Path, force: bool = False) -> list[Path]:
    """Write ``bank`` as a zip to ``path`` (whole or not at all); the files
    written. OutputRefused (one line) when the policy refuses the file."""
    check_outputs(outputs(bank, path), force=force)
    write_atomically(Path(path), zip_bytes(bank))
    return [Path(path)]


def zip_bytes(bank: Bank) -> bytes:
    """The package: the manifest, and per question its item and picture."""
    files = {}
    entries = lms.questions(bank)
    named = len(bank.groups) > 1 or any(group for group, _ in bank.groups)
    for number, (group, question) in enumerate(entries, 1):
        stem = f"items/q{number:04d}"
        title = f"[{group}] {question.title}" if named else question.title
        files[f"{stem}.xml"] = _xml(item(question, f"q{number:04d}", title))
        if question.picture:
            files[f"{stem}.png"] = question.picture
    files["imsmanifest.xml"] = _xml(manifest(bank, files))
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        for name in sorted(files):
            info = zipfile.ZipInfo(name, ZIP_DATE)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            archive.writestr(info, files[name])
    return out.getvalue()


def manifest(bank: Bank, files: dict) -> ET.Element:
    root = ET.Element("manifest", {"xmlns": CP, "identifier": f"RASTERLAB-BANK-{int(bank.seed)}",
                                            f"{{{XSI}}}schemaLocation": f"{CP} {CP_XSD}"})
    metadata = sub(root, "metadata")
    sub(metadata, "schema").text = "QTIv2.1 Package"
    sub(metadata, "schemaversion").text = "1.0.0"
    sub(root, "organizations")
    resources = sub(root, "resources")
    for name in sorted(files):
        if not name.endswith(".xml"):
            continue
        stem = name[:-len(".xml")]
        resource = sub(resources, "resource", {
            "identifier": f"R-{stem.split('/')[-1]}", "type": "imsqti_item_xmlv2p1",
            "href": name})
        for held in (name, f"{stem}.png"):
            if held in files:
                sub(resource, "file", href=held)
    return root


def item(question: Question, identifier: str, title: str) -> ET.Element:
    """The assessmentItem of ``question``, its elements in the order the QTI
    2.1 schema gives: declarations, itemBody, responseProcessing, modalFeedback."""
    root = ET.Element("assessmentItem", {
        "xmlns": QTI, "identifier": identifier, "title": escape.xml_chars(title),
        "adaptive": "false", "timeDependent": "false",
        f"{{{XSI}}}schemaLocation": f"{QTI} {QTI_XSD}"})
    root.append(_response_declaration(question))
    score = sub(root, "outcomeDeclaration", identifier="SCORE", cardinality="single",
                baseType="float")
    sub(sub(score, "defaultValue"), "value").text = "0"
    sub(root, "outcomeDeclaration", identifier="FEEDBACK", cardinality="single",
        baseType="identifier")
    root.append(_body(question, identifier))
    root.append(_processing(question))
    feedback = sub(root, "modalFeedback", outcomeIdentifier="FEEDBACK", showHide="show",
                   identifier=FEEDBACK, title="Worked steps")
    _html_into(feedback, lms.worked_html(question.worked))
    return root


def _response_declaration(question: Question) -> ET.Element:
    answer = question.answer
    base = {NUMERICAL: "float", SHORT: "string", CHOICE: "identifier"}[answer.kind]
    declaration = ET.Element("responseDeclaration", {
        "identifier": "RESPONSE", "cardinality": "single", "baseType": base})
    correct = sub(declaration, "correctResponse")
    value = sub(correct, "value")
    if answer.kind == NUMERICAL:
        value.text = lms.decimal_text(answer)
    elif answer.kind == CHOICE:
        value.text = f"C{answer.value + 1}"
    else:
        value.text = escape.xml_chars(answer.value)
        mapping = sub(declaration, "mapping", defaultValue="0")
        for spelling in dict.fromkeys((answer.value, *answer.also)):
            sub(mapping, "mapEntry", mapKey=escape.xml_chars(spelling), mappedValue="1",
                caseSensitive="false")
    return declaration


def _body(question: Question, identifier: str) -> ET.Element:
    answer = question.answer
    body = ET.Element("itemBody")
    picture = f"{identifier}.png" if question.picture else None
    _html_into(body, lms.question_html(question, picture=picture))
    if answer.kind == CHOICE:
        interaction = sub(body, "choiceInteraction", responseIdentifier="RESPONSE",
                          shuffle="true", maxChoices="1")
        for index, choice in enumerate(answer.choices, 1):
            sub(interaction, "simpleChoice", identifier=f"C{index}").text = \
                escape.xml_chars(choice)
    else:
        line = sub(body, "p")
        sub(line, "textEntryInteraction", responseIdentifier="RESPONSE", expectedLength="16")
    return body


def _processing(question: Question) -> ET.Element:
    answer = question.answer
    processing = ET.Element("responseProcessing")
    condition = sub(sub(processing, "responseCondition"), "responseIf")
    if answer.kind == NUMERICAL:
        tolerance = lms.tolerance(answer)
        test = sub(condition, "equal", toleranceMode="absolute" if tolerance else "exact")
        if tolerance:
            test.set("tolerance", f"{tolerance:g}")
        sub(test, "variable", identifier="RESPONSE")
        sub(test, "correct", identifier="RESPONSE")
    elif answer.kind == CHOICE:
        test = sub(condition, "match")
        sub(test, "variable", identifier="RESPONSE")
        sub(test, "correct", identifier="RESPONSE")
    else:
        test = sub(condition, "gt")
        sub(test, "mapResponse", identifier="RESPONSE")
        sub(test, "baseValue", baseType="float").text = "0"
    _set(condition, "SCORE", "float", "1")
    _set(processing, "FEEDBACK", "identifier", FEEDBACK)
    return processing


def _set(parent: ET.Element, outcome: str, base: str, value: str) -> None:
    setting = sub(parent, "setOutcomeValue", identifier=outcome)
    sub(setting, "baseValue", baseType=base).text = value


def _html_into(parent: ET.Element, html: str) -> None:
    """Append the elements of ``html`` (well-formed: lms.py escapes all text)
    to ``parent``."""
    parent.extend(list(ET.fromstring(f"<div>{escape.xml_chars(html)}</div>")))


def _xml(root: ET.Element) -> bytes:
    ET.indent(root)
    return ET.tostring(root, encoding="utf-8", xml_declaration=True) + b"\n"
