"""`rasterlab questions`: the list, byte-for-byte repeats of a seed, and
bad input refused in one line with exit status 2."""
import pytest

import rasterlab
from app.model.scene import Scene
from app.teaching.questions import registry


def files_of(folder):
    return {path.name: path.read_bytes() for path in sorted(folder.iterdir())}


def test_list_names_every_template(run_cli):
    status, out, _ = run_cli("questions", "--list")
    assert status == 0
    for template in registry.TEMPLATES.values():
        assert any(line.split()[:2] == [template.name, template.family]
                   for line in out.splitlines())


@pytest.mark.parametrize("fmt", ["md", "pdf"])
def test_the_same_seed_gives_the_same_bytes(run_cli, tmp_path, fmt):
    args = ["questions", "line-bresenham-ne", "fill-edge-entry", "circle-midpoint-d",
            "--count", "3", "--format", fmt]
    assert run_cli(*args, "--seed", "12", "--out", tmp_path / "a")[0] == 0
    assert run_cli(*args, "--seed", "12", "--out", tmp_path / "b")[0] == 0
    assert run_cli(*args, "--seed", "13", "--out", tmp_path / "c")[0] == 0
    first = files_of(tmp_path / "a")
    assert first == files_of(tmp_path / "b")
    assert first[f"key.{fmt}"] != files_of(tmp_path / "c")[f"key.{fmt}"]


def test_per_student_writes_a_group_per_id(run_cli, tmp_path):
    ids = tmp_path / "ids.csv"
    ids.write_text("id\nann\nbob\n", encoding="utf-8")
    status, out, _ = run_cli("questions", "fill-aet", "--per-student", ids, "--format", "md",
                             "--out", tmp_path / "out")
    assert status == 0 and "2 group(s)" in out
    sheet = (tmp_path / "out" / "questions.md").read_text(encoding="utf-8")
    assert "Student: ann" in sheet and "Student: bob" in sheet


@pytest.mark.parametrize("args, message", [
    (["no-such-template"], "no question template 'no-such-template'"),
    (["fill-aet", "--count", "0"], "--count 0"),
    (["fill-aet", "--count", "501"], "--count 501"),
    (["fill-aet", "--count", "two"], "not a whole number"),
    (["fill-aet", "--seed", "-1"], "--seed -1"),
    (["fill-aet", "--per-student", "missing.csv"], "cannot be read"),
])
def test_bad_input_is_refused_in_one_line(run_cli, tmp_path, args, message):
    status, out, err = run_cli("questions", *args, "--format", "md", "--out", tmp_path / "out")
    assert status == 2 and message in err and err.count("\n") == 1
    assert not (tmp_path / "out").exists()


def test_a_file_it_did_not_write_needs_force(run_cli, tmp_path):
    (tmp_path / "key.md").write_text("my notes", encoding="utf-8")
    args = ["questions", "fill-aet", "--format", "md", "--out", tmp_path]
    status, _, err = run_cli(*args)
    assert status == 2 and "--force" in err
    assert run_cli(*args, "--force")[0] == 0


def test_the_python_api_gives_the_same_question():
    q = rasterlab.question("line-bresenham-d", 5)
    assert q == rasterlab.question("line-bresenham-d", 5) and q.text and q.answer.text
    run = rasterlab.run("line-bresenham", [(1, 1), (9, 4)])
    assert "P = (1, 1), Q = (9, 4)" in rasterlab.question("line-bresenham-pixel", 0, run).text
    scene = Scene(algorithm="circle-midpoint", points=((7, 5),), options={"radius": 4})
    assert rasterlab.question("circle-octant-pixels", 0, scene).scene == scene
    with pytest.raises(ValueError, match="questions --list"):
        rasterlab.question("nope", 1)
    assert "question" in rasterlab.__all__


@pytest.fixture(scope="module")
def every_template_bank():
    """One variant of every template, drawn once for the format tests below."""
    from app.teaching.questions import bank
    return bank.draw(list(registry.TEMPLATES), 1, 5)


def test_every_template_in_moodle_xml(every_template_bank, tmp_path):
    import xml.etree.ElementTree as ET
    from app.teaching.questions import writers
    from app.teaching.questions.model import CHOICE, NUMERICAL, SHORT
    writers.WRITERS["moodle-xml"](every_template_bank, tmp_path / "bank.xml")
    root = ET.parse(tmp_path / "bank.xml").getroot()
    asked = [q for q in root.findall("question") if q.get("type") != "category"]
    questions = every_template_bank.groups[0][1]
    kinds = {NUMERICAL: "numerical", SHORT: "shortanswer", CHOICE: "multichoice"}
    assert [q.get("type") for q in asked] == [kinds[q.answer.kind] for q in questions]
    for element, question in zip(asked, questions):
        right = [a for a in element.findall("answer") if a.get("fraction") == "100"]
        assert right, question.template
        if question.answer.kind == SHORT:  # the key's own text is accepted
            assert question.answer.text in [a.findtext("text") for a in right]
        assert element.find("generalfeedback/text").text  # the worked steps


@pytest.mark.parametrize("fmt", ["qti", "gift", "prairielearn"])
def test_every_template_in_the_other_formats(run_cli, tmp_path, fmt):
    out = tmp_path / ("bank" if fmt == "prairielearn" else f"bank.{fmt}")
    status, said, _ = run_cli("questions", *registry.TEMPLATES, "--seed", "5",
                              "--format", fmt, "--out", out)
    assert status == 0 and f"{len(registry.TEMPLATES)} questions" in said
    if fmt == "prairielearn":
        folders = sorted(p.name for p in (out / "questions").iterdir())
        assert folders == sorted(registry.TEMPLATES)
    elif fmt == "qti":
        import zipfile
        names = zipfile.ZipFile(out).namelist()
        assert "imsmanifest.xml" in names
        assert sum(name.endswith(".xml") and name.startswith("items/") for name in names) \
            == len(registry.TEMPLATES)
    else:
        text = out.read_text(encoding="utf-8")
        assert text.count("::") >= 2 * len(registry.TEMPLATES)
