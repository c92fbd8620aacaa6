"""What the installed program offers without a checkout: the shipped scenes by
name (`list --scenes`, `run --scene NAME`, `export NAME`, `worksheet NAME`),
the templates (`rasterlab template`) and `--version`. The expected names and
texts are read from the repository's own folders and pyproject.toml, not
from the code under test."""
from __future__ import annotations

import json
import re

import pytest

from tests.support import ROOT

SCENES = ROOT / "resources" / "scenes"
TEMPLATES = ROOT / "resources" / "templates"
NAMES = sorted(p.stem for p in SCENES.glob("*.json")) + sorted(
    f"rendering/{p.stem}" for p in (SCENES / "rendering").glob("*.json"))


FAMILIES = ("lines", "circles", "polygons", "fill", "triangles", "visibility", "antialias",
            "textures", "pipeline")


def test_list_scenes_names_every_shipped_file_family_by_family(run_cli):
    status, out, err = run_cli("list", "--scenes")
    assert status == 0 and err == ""
    rows = [line.split()[:2] for line in out.splitlines()]
    assert sorted(name for name, _ in rows) == sorted(NAMES)
    families = [family for _, family in rows]
    assert families == sorted(families, key=FAMILIES.index)
    assert dict(rows)["rendering/pipeline-cube"] == "pipeline"
    assert dict(rows)["polygon-star-evenodd"] == "polygons"
    status, out, _ = run_cli("list", "--scenes", "--json")
    listed = json.loads(out)
    assert [row["name"] for row in listed] == [name for name, _ in rows]
    assert all(row["description"] and row["family"] in FAMILIES for row in listed)
    demo = json.loads((SCENES / "demo-bresenham.json").read_text(encoding="utf-8"))
    assert next(r for r in listed if r["name"] == "demo-bresenham")["algorithm"] == demo["algorithm"]


@pytest.mark.parametrize("name", ["demo-bresenham", "demo-bresenham.json",
                                  "rendering/pipeline-cube", "polygon-star-evenodd"])
def test_a_shipped_scene_runs_by_name_as_by_path(run_cli, name):
    stem = name.removesuffix(".json")
    _, by_path, _ = run_cli("run", "--scene", SCENES / f"{stem}.json", "--json")
    status, by_name, err = run_cli("run", "--scene", name, "--json")
    assert status == 0 and err == ""
    assert by_name == by_path


def test_an_unknown_scene_name_is_one_line(run_cli):
    status, out, err = run_cli("run", "--scene", "no-such-scene")
    assert (status, out) == (2, "")
    assert err.count("\n") == 1 and "no-such-scene" in err and "cannot read" in err


def test_export_and_worksheet_take_a_name(run_cli, tmp_path):
    status, _, err = run_cli("export", "demo-bresenham", "--gif", tmp_path / "a.gif")
    assert status == 0, err
    assert (tmp_path / "a.gif").read_bytes()[:6] == b"GIF89a"
    status, out, err = run_cli("worksheet", "demo-bresenham", "--out", tmp_path / "sheet",
                               "--format", "csv")
    assert status == 0, err
    assert (tmp_path / "sheet" / "worksheet.csv").is_file()


def test_version_is_the_declared_one(run_cli):
    declared = re.search(r'^version\s*=\s*"([^"]+)"', (ROOT / "pyproject.toml").read_text(),
                         re.MULTILINE).group(1)
    with pytest.raises(SystemExit) as done:
        run_cli("--version")
    assert done.value.code == 0
    status, out, _ = run_cli("--version", child=True)
    assert (status, out) == (0, f"rasterlab {declared}\n")


def test_template_lists_and_prints_every_template(run_cli):
    status, out, err = run_cli("template")
    assert status == 0 and err == ""
    programs = sorted(p.name for p in TEMPLATES.iterdir() if p.suffix in (".c", ".cpp", ".js"))
    assert programs == ["line.c", "line.cpp", "line.js"]
    assert [line.split()[0] for line in out.splitlines()] == sorted(
        p.stem for p in TEMPLATES.glob("*.py")) + programs
    for path in TEMPLATES.glob("*.py"):
        status, out, _ = run_cli("template", path.stem)
        assert status == 0 and out == path.read_text(encoding="utf-8")
    for name in programs:
        status, out, _ = run_cli("template", name)
        assert status == 0 and out == (TEMPLATES / name).read_text(encoding="utf-8")


def test_template_out_writes_and_keeps_an_existing_file(run_cli, tmp_path):
    target = tmp_path / "mine.py"
    status, out, _ = run_cli("template", "fill", "--out", target)
    assert status == 0 and "mine.py" in out
    assert target.read_bytes() == (TEMPLATES / "fill.py").read_bytes()
    target.write_text("# my work\n")
    status, _, err = run_cli("template", "line", "--out", target)
    assert status == 2 and "--force" in err and err.count("\n") == 1
    assert target.read_text() == "# my work\n"
    status, _, _ = run_cli("template", "line", "--out", target, "--force")
    assert status == 0 and target.read_bytes() == (TEMPLATES / "line.py").read_bytes()


@pytest.mark.parametrize("argv, says", [(["template", "lines"], "no template 'lines'"),
                                        (["template", "--out", "x.py"], "needs a template NAME")])
def test_template_refuses_bad_input_in_one_line(run_cli, tmp_path, argv, says):
    status, out, err = run_cli(*argv)
    assert (status, out) == (2, "") and says in err and err.count("\n") == 1
