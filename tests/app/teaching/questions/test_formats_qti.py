"""The QTI 2.1 writer, checked against a schema check written from the IMS
specifications (no package on the registries this project uses ships the
IMS XSD files): "IMS Question & Test Interoperability Assessment Test,
Section, and Item Information Model v2.1" (the content model of
assessmentItem, its declarations, interactions, response processing and
modal feedback: the required attributes and the order of the children) and
"IMS Content Packaging v1.1.4" (manifest: metadata, organizations,
resources; a resource's files). A small evaluator of the response
processing used here then scores typed answers."""
from __future__ import annotations

import io
import zipfile
import xml.etree.ElementTree as ET
from posixpath import dirname, join, normpath

from app.teaching.questions import qti
from tests.support import question_bank as qb

QTI = "{http://www.imsglobal.org/xsd/imsqti_v2p1}"
CP = "{http://www.imsglobal.org/xsd/imscp_v1p1}"
MANY = 10 ** 6
# element: (required attributes, [(child, least, most)] in the order the
# schema gives, or None where the content is XHTML-like flow).
ITEM_RULES = {
    "assessmentItem": ({"identifier", "title", "adaptive", "timeDependent"}, [
        ("responseDeclaration", 0, MANY), ("outcomeDeclaration", 0, MANY),
        ("templateDeclaration", 0, MANY), ("templateProcessing", 0, 1), ("stylesheet", 0, MANY),
        ("itemBody", 0, 1), ("responseProcessing", 0, 1), ("modalFeedback", 0, MANY)]),
    "responseDeclaration": ({"identifier", "cardinality"}, [
        ("defaultValue", 0, 1), ("correctResponse", 0, 1), ("mapping", 0, 1),
        ("areaMapping", 0, 1)]),
    "outcomeDeclaration": ({"identifier", "cardinality"}, [
        ("defaultValue", 0, 1), ("matchTable", 0, 1), ("interpolationTable", 0, 1)]),
    "defaultValue": (set(), [("value", 1, MANY)]),
    "correctResponse": (set(), [("value", 1, MANY)]),
    "mapping": (set(), [("mapEntry", 1, MANY)]),
    "mapEntry": ({"mapKey", "mappedValue"}, []),
    "itemBody": (set(), None),
    "choiceInteraction": ({"responseIdentifier", "shuffle", "maxChoices"}, [
        ("prompt", 0, 1), ("simpleChoice", 1, MANY)]),
    "simpleChoice": ({"identifier"}, None),
    "textEntryInteraction": ({"responseIdentifier"}, []),
    "img": ({"src", "alt"}, []),
    "responseCondition": (set(), [("responseIf", 1, 1), ("responseElseIf", 0, MANY),
                                  ("responseElse", 0, 1)]),
    "equal": ({"toleranceMode"}, None),
    "modalFeedback": ({"outcomeIdentifier", "showHide", "identifier"}, None),
    "table": (set(), [("caption", 0, 1), ("col", 0, MANY), ("colgroup", 0, MANY),
                      ("thead", 0, 1), ("tfoot", 0, 1), ("tbody", 1, MANY)]),
}
MANIFEST_RULES = {
    "manifest": ({"identifier"}, [("metadata", 0, 1), ("organizations", 1, 1),
                                  ("resources", 1, 1)]),
    "resources": (set(), [("resource", 0, MANY)]),
    "resource": ({"identifier", "type"}, [("metadata", 0, 1), ("file", 0, MANY),
                                         ("dependency", 0, MANY)]),
    "file": ({"href"}, []),
}
# Inline and block content the items use (QTI's XHTML subset).
FLOW = {"p", "br", "img", "div", "table", "thead", "tbody", "tr", "th", "td",
        "choiceInteraction", "textEntryInteraction"}


def problems(element: ET.Element, ns: str, rules: dict, where: str = "") -> list[str]:
    """What breaks ``rules`` in ``element`` and below, one line each."""
    name = element.tag.removeprefix(ns)
    where = f"{where}/{name}"
    if not element.tag.startswith(ns):
        return [f"{where}: not in the namespace {ns}"]
    found = []
    required, children = rules.get(name, (set(), None))
    found += [f"{where}: no {key}" for key in sorted(required - set(element.attrib))]
    if name == "equal" and element.get("toleranceMode") != "exact" and not element.get(
            "tolerance"):
        found.append(f"{where}: a tolerance mode without tolerance")
    if children is not None:
        found += _order_problems([c.tag.removeprefix(ns) for c in element], children, where)
    elif name in ("itemBody", "modalFeedback", "simpleChoice"):
        found += [f"{where}: {c.tag} is not flow content" for c in element
                  if c.tag.removeprefix(ns) not in FLOW]
    for child in element:
        found += problems(child, ns, rules, where)
    return found


def _order_problems(names: list[str], model: list, where: str) -> list[str]:
    position = 0
    for child, least, most in model:
        count = 0
        while position < len(names) and names[position] == child:
            position, count = position + 1, count + 1
        if not least <= count <= most:
            return [f"{where}: {count} {child} (from {least} to {most})"]
    return [f"{where}: {names[position]} out of place"] if position < len(names) else []


def package(bank) -> zipfile.ZipFile:
    archive = zipfile.ZipFile(io.BytesIO(qti.zip_bytes(bank)))
    manifest = ET.fromstring(archive.read("imsmanifest.xml"))
    assert problems(manifest, CP, MANIFEST_RULES) == []
    for resource in manifest.iter(f"{CP}resource"):
        assert resource.get("type") == "imsqti_item_xmlv2p1"
        held = [file.get("href") for file in resource.iter(f"{CP}file")]
        assert resource.get("href") in held and set(held) <= set(archive.namelist())
        item = ET.fromstring(archive.read(resource.get("href")))
        assert problems(item, QTI, ITEM_RULES) == []
        for image in item.iter(f"{QTI}img"):  # every picture shown is in the package
            assert normpath(join(dirname(resource.get("href")), image.get("src"))) in held
    return archive


def items(bank) -> list[ET.Element]:
    archive = package(bank)
    return [ET.fromstring(archive.read(name)) for name in sorted(archive.namelist())
            if name.startswith("items/") and name.endswith(".xml")]


def score(item: ET.Element, response: str) -> float:
    """SCORE after ``response``, by the QTI 2.1 meaning of the processing
    used here: equal (exact, or absolute tolerance), match, gt, mapResponse."""
    declaration = item.find(f"{QTI}responseDeclaration")
    base = declaration.get("baseType")
    correct = declaration.findtext(f"{QTI}correctResponse/{QTI}value")

    def value(expression):
        tag = expression.tag.removeprefix(QTI)
        if tag == "variable":
            return float(response) if base == "float" else response
        if tag == "correct":
            return float(correct) if base == "float" else correct
        if tag == "baseValue":
            return float(expression.text)
        if tag == "mapResponse":
            mapping = declaration.find(f"{QTI}mapping")
            for entry in mapping:
                same = (entry.get("mapKey") == response if entry.get("caseSensitive") == "true"
                        else entry.get("mapKey").lower() == response.lower())
                if same:
                    return float(entry.get("mappedValue"))
            return float(mapping.get("defaultValue", "0"))
        left, right = (value(operand) for operand in expression)
        if tag == "equal" and expression.get("toleranceMode") == "absolute":
            return abs(left - right) <= float(expression.get("tolerance").split()[0])
        return {"equal": left == right, "match": left == right, "gt": left > right}[tag]

    condition = item.find(f"{QTI}responseProcessing/{QTI}responseCondition/{QTI}responseIf")
    if value(condition[0]):
        return float(condition.findtext(f"{QTI}setOutcomeValue/{QTI}baseValue"))
    return float(item.findtext(f"{QTI}outcomeDeclaration/{QTI}defaultValue/{QTI}value"))


def test_every_kind_of_answer_has_its_interaction_and_scores_typed_answers():
    found = items(qb.bank())
    kinds = [(i.find(f"{QTI}responseDeclaration").get("baseType"),
              next(iter(i.find(f"{QTI}itemBody").iter(f"{QTI}choiceInteraction")), None)
              is not None) for i in found[:6]]
    assert kinds == [("float", False)] * 4 + [("string", False), ("identifier", True)]
    integer, quarter, third, coverage, pixel, choice = found[:6]
    assert (score(integer, "-3"), score(integer, "-3.0"), score(integer, "-2.999")) == (1, 1, 0)
    assert (score(quarter, "-0.75"), score(quarter, "-0.7")) == (1, 0)
    assert (score(third, "0.333"), score(third, "0.3333"), score(third, "0.33")) == (1, 1, 0)
    assert (score(coverage, "0.286"), score(coverage, "0.2847"), score(coverage, "0.29")) == (
        1, 0, 0)
    assert [score(pixel, typed) for typed in ("(2, 1)", "(2,1)", "2, 1", "(1, 2)")] == [1, 1, 1, 0]
    right = choice.findtext(f"{QTI}responseDeclaration/{QTI}correctResponse/{QTI}value")
    labels = {c.get("identifier"): c.text for c in choice.iter(f"{QTI}simpleChoice")}
    assert labels[right] == "NE" and list(labels.values()) == ["E", "NE", "neither"]
    assert (score(choice, right), score(choice, "C1")) == (1, 0)


def test_the_picture_is_in_the_package_and_the_feedback_holds_the_worked_steps():
    archive = package(qb.bank())
    _, png = qb.scene_and_picture()
    assert archive.read("items/q0001.png") == png
    item = ET.fromstring(archive.read("items/q0001.xml"))
    feedback = item.find(f"{QTI}modalFeedback")
    rows = [["".join(cell.itertext()) for cell in row] for row in feedback.iter(f"{QTI}tr")]
    assert rows == qb.worked_cells(qb.WORKED)
    shown = item.findtext(f"{QTI}responseProcessing/{QTI}setOutcomeValue/{QTI}baseValue")
    assert shown == feedback.get("identifier") and feedback.get("showHide") == "show"


def test_titles_name_the_student_in_a_bank_of_several():
    titles = [i.get("title") for i in items(qb.per_student())]
    assert titles[0] == "[s1/a:b] Bresenham: d after step 2 (#1)"
    assert titles[3].startswith("[s2] ")
    assert items(qb.bank())[0].get("title") == "Bresenham: d after step 2 (#1)"


def test_awkward_text_comes_back_as_written():
    short, choice = items(qb.bank())[6:8]
    assert short.get("title") == qb.as_written("Awkward " + qb.AWKWARD)
    body = short.find(f"{QTI}itemBody/{QTI}p")
    assert "".join(body.itertext()) == qb.as_written("Type " + qb.AWKWARD)
    assert score(short, "x*y {z}: =1") == 1 and score(short, "<A&B>") == 1
    assert score(short, "xy {z}: =1") == 0  # no wildcard in QTI's mapping
    assert [c.text for c in choice.iter(f"{QTI}simpleChoice")] == ["=1 <b>", "~2 {c}",
                                                                   "#3 : &d;"]


def test_the_schema_check_finds_children_out_of_order_and_missing_attributes():
    item = items(qb.bank())[0]
    feedback = item.find(f"{QTI}modalFeedback")
    item.remove(feedback)
    item.insert(0, feedback)
    del item.attrib["adaptive"]
    found = problems(item, QTI, ITEM_RULES)
    assert "/assessmentItem: no adaptive" in found
    assert any("out of place" in line or "from 0 to" in line for line in found)
