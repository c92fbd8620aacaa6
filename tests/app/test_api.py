"""The Python API (``import rasterlab``): runs agree with independent oracles
and with the command line, everything it returns is plain Python data,
exports are valid files, check scores the shipped samples, bad input gets
the command's one line, and the notebook player works in a real browser."""
from __future__ import annotations

import json
import subprocess
import sys
import time

import pytest
from PIL import Image
from pypdf import PdfReader

import rasterlab
from algorithms.core.cases import LINE_CASES
from tests.support import ROOT
from tests.support.antialias_oracles import wu_oracle
from tests.support.bresenham import bresenham_run

SAMPLES = ROOT / "resources" / "students"
PLAIN = (bool, int, float, str, type(None))


@pytest.mark.parametrize("p, q", [((0, 0), (6, 2)), ((2, 3), (29, 14)), ((1, 1), (9, 1)),
                                  ((0, 0), (7, 7))])
def test_run_draws_the_textbook_bresenham_line(p, q):
    pixels, decisions = bresenham_run(p, q)
    result = rasterlab.run("line-bresenham", [p, q])
    assert result.pixels == pixels
    decided = [(s["pixel"], s["variables"]["d"], s["choice"]) for s in result.steps
               if s["choice"] is not None]
    assert decided == [(pixel, d, "E" if d <= 0 else "NE")
                       for pixel, d in zip(pixels[1:], decisions)]
    assert [s["step"] for s in result.steps] == list(range(len(result.steps)))
    dx, dy = q[0] - p[0], q[1] - p[1]
    last = decisions[-1]
    assert result.variables["d"] == last + (2 * dy if last <= 0 else 2 * (dy - dx))


@pytest.mark.parametrize("p, q", [((0, 0), (7, 3)), ((3, 12), (10, 1)), ((4, 4), (4, 10))])
def test_run_gives_the_pixels_and_coverage_of_wus_line(p, q):
    result = rasterlab.run("line-wu", [p, q], grid=(16, 16))
    assert list(zip(result.pixels, result.values)) == wu_oracle(p, q)


def _plain_data(value) -> bool:
    """Only Python's own types, at any depth: no numpy scalar, array or Fraction."""
    if isinstance(value, dict):
        return all(type(k) is str and _plain_data(v) for k, v in value.items())
    if type(value) in (list, tuple):
        return all(_plain_data(item) for item in value)
    return type(value) in PLAIN


@pytest.mark.parametrize("algorithm, points, options", [
    ("line-bresenham", [(0, 0), (9, 4)], {}),
    ("polygon-scanline", [[(1, 1), (12, 2), (6, 9)], [(5, 3), (8, 3), (6, 6)]], {}),
    ("triangle-bbox", [(1, 1), (12, 2), (6, 9)], {"colors": ["#ff0000", "#00ff00", "#0000ff"]}),
    ("circle-midpoint", [(10, 10)], {"radius": 5}),
    ("line-wu", [(0, 0), (9, 4)], {"endpoints": "gap"}),
])
def test_everything_a_run_gives_is_plain_data(algorithm, points, options):
    result = rasterlab.run(algorithm, points, **options)
    for value in (result.pixels, result.values, result.variables, result.options, result.steps,
                  result.grid, result.points, result.to_scene()):
        assert _plain_data(value)
        json.dumps(value)
    assert all(type(p) is tuple and len(p) == 2 for p in result.pixels)


def test_a_run_gives_what_run_json_and_run_steps_json_print(run_cli):
    args = ["polygon-scanline", "--points", "1,1", "12,2", "6,9", "--grid", "14,11"]
    printed = json.loads(run_cli("run", *args, "--json")[1])
    table = json.loads(run_cli("run", *args, "--steps", "--json")[1])
    result = rasterlab.run("polygon-scanline", [[(1, 1), (12, 2), (6, 9)]], grid=(14, 11))
    assert [list(p) for p in result.pixels] == printed["pixels"]
    assert (result.variables, result.options, list(result.grid), len(result.steps)) == \
        (printed["final"], printed["options"], printed["grid"], printed["steps"])
    keys = [column["key"] for column in table["columns"]]
    for step, row in zip(result.steps, table["rows"]):
        cells = dict(zip(keys, row))
        flat = {k: v for k, v in step.items() if k not in ("variables", "tables")}
        if isinstance(flat["pixel"], tuple):  # a pixel; a span's run is a dict in both
            flat["pixel"] = list(flat["pixel"])
        assert {**flat, **step["variables"], **step["tables"]} == \
            {k: v for k, v in cells.items() if v is not None or k in flat}


def test_open_scene_runs_a_shipped_scene_by_name():
    data = json.loads((ROOT / "resources" / "scenes" / "demo-bresenham.json").read_text())
    p, q = (tuple(point) for point in data["primitives"][0]["points"])
    result = rasterlab.open_scene("demo-bresenham")
    assert (result.algorithm, result.points) == (data["algorithm"], [p, q])
    assert result.grid == (data["grid"]["width"], data["grid"]["height"])
    assert result.pixels == bresenham_run(p, q)[0]


def test_a_saved_run_opens_as_the_same_run(tmp_path):
    result = rasterlab.run("polygon-scanline", [[(1, 1), (12, 2), (6, 9)]], grid=(14, 11),
                           fill_rule="nonzero")
    path = result.save(tmp_path / "fill.json")
    again = rasterlab.open_scene(path)
    assert (again.pixels, again.options, again.grid) == (result.pixels, result.options,
                                                         result.grid)
    assert json.loads(path.read_text())["options"] == {"fill_rule": "nonzero"}
    with pytest.raises(ValueError, match="exists; give force=True"):
        rasterlab.run("line-bresenham", [(0, 0), (3, 1)]).save(path)
    assert rasterlab.open_scene(path).algorithm == "polygon-scanline"
    rasterlab.run("line-bresenham", [(0, 0), (3, 1)]).save(path, force=True)
    assert rasterlab.open_scene(path).pixels == [(0, 0), (1, 0), (2, 1), (3, 1)]


# ------------------------------------------------------------------- export
@pytest.fixture(scope="module")
def short_run():
    return rasterlab.run("line-bresenham", [(0, 0), (6, 2)], grid=(8, 4))


def test_exports_are_valid_files(tmp_path, short_run):
    steps = len(short_run.steps)
    line = short_run.export(tmp_path / "a.gif")
    assert line.startswith(f"{tmp_path / 'a.gif'}: {steps} frames of ")
    with Image.open(tmp_path / "a.gif") as gif:
        assert (gif.format, gif.n_frames) == ("GIF", steps)
    short_run.export(tmp_path / "a.pdf", fps=2)
    assert len(PdfReader(tmp_path / "a.pdf").pages) == steps
    line = rasterlab.export(short_run, tmp_path / "a.html")
    page = (tmp_path / "a.html").read_text(encoding="utf-8")
    assert line.startswith(f"{tmp_path / 'a.html'}: an interactive page of {steps} steps")
    assert page.startswith("<!DOCTYPE html>") and page.rstrip().endswith("</html>")
    rasterlab.export(short_run, tmp_path / "frames", format="png")
    assert sorted(p.name for p in (tmp_path / "frames").glob("*.png")) == \
        [f"frame_{k:04d}.png" for k in range(steps)]


def test_export_takes_a_shipped_scene_by_name(tmp_path):
    line = rasterlab.export("demo-bresenham", tmp_path / "demo.gif", last=5)
    with Image.open(tmp_path / "demo.gif") as gif:
        assert gif.n_frames == 6
    assert line.startswith(f"{tmp_path / 'demo.gif'}: 6 frames")


@pytest.mark.parametrize("path, settings, message", [
    ("a.txt", {}, "a.txt: cannot tell the format; use a path ending in .gif"),
    ("a.png", {}, "a.png: cannot tell the format; use a path ending in .gif"),
    ("a", {"format": "jpeg"}, "format must be one of gif, mp4, webm, pdf, html, png, svg, got"),
    ("a.gif", {"colour": "red"}, "export has no setting 'colour' (settings: format, force,"),
    ("a.gif", {"fps": 0}, "frames per second must be 0.1 .. 50, got 0"),
    ("a.gif", {"last": 99}, "last 99: the run has steps 0 .. 8"),
    ("a.gif", {"overlays": "nope"}, "unknown overlay 'nope'"),
    ("no/a.gif", {}, "the folder"),
])
def test_a_bad_export_says_why_and_writes_nothing(tmp_path, short_run, path, settings, message):
    with pytest.raises(ValueError) as raised:
        short_run.export(tmp_path / path, **settings)
    assert message in str(raised.value) and "\n" not in str(raised.value)
    assert list(tmp_path.iterdir()) == []


# -------------------------------------------------------------------- check
def test_check_gives_the_correct_sample_full_score(run_cli):
    sample = SAMPLES / "bresenham_correct.py"
    result = rasterlab.check(sample, algorithm="line-bresenham")
    assert (result.score, result.passed, result.total) == (1.0, len(LINE_CASES), len(LINE_CASES))
    assert all(case["passed"] for case in result.cases) and _plain_data(result.cases)
    status, out, _ = run_cli("check", sample, "--against", "line-bresenham")
    assert status == 0 and str(result) + "\n" == out


def test_check_scores_the_off_by_one_sample_below_full():
    result = rasterlab.check(SAMPLES / "off_by_one.py", algorithm="line-bresenham",
                             cases=["random", 4], seed=3)
    failed = [case for case in result.cases if not case["passed"]]
    assert result.total == 4 and result.score == result.passed / 4 < 1
    assert all(case["reference_divergence"]["got"] == "the end" for case in failed)
    assert result.text.splitlines()[-1] == f"{result.passed} of 4 cases pass"


# ---------------------------------------------------------------- bad input
@pytest.mark.parametrize("call, argv", [
    (lambda: rasterlab.run("nope", [(0, 0), (1, 1)]),
     ["run", "nope", "--points", "0,0", "1,1"]),
    (lambda: rasterlab.run("line-bresenham", [(0, 0)]),
     ["run", "line-bresenham", "--points", "0,0"]),
    (lambda: rasterlab.run("line-bresenham", [(0, 0), (1, 1)], colour=1),
     ["run", "line-bresenham", "--points", "0,0", "1,1", "--set", "colour=1"]),
    (lambda: rasterlab.run("line-bresenham", [(0, 0), (1, 1)], symmetric="maybe"),
     ["run", "line-bresenham", "--points", "0,0", "1,1", "--set", "symmetric=maybe"]),
    (lambda: rasterlab.run("line-bresenham", [(0, 0), (40, 1)], grid=(10, 10)),
     ["run", "line-bresenham", "--points", "0,0", "40,1", "--grid", "10,10"]),
    (lambda: rasterlab.run("line-bresenham", [(0, 0), (1, 1)], grid=(0, 3)),
     ["run", "line-bresenham", "--points", "0,0", "1,1", "--grid", "0,3"]),
    (lambda: rasterlab.run("line-bresenham", [(0, 0), (1.5, 1)]),
     ["run", "line-bresenham", "--points", "0,0", "1.5,1"]),
    (lambda: rasterlab.open_scene("no-such-scene"), ["run", "--scene", "no-such-scene"]),
    (lambda: rasterlab.check(SAMPLES / "raises.py", algorithm="pipeline"),
     ["check", SAMPLES / "raises.py", "--against", "pipeline"]),
    (lambda: rasterlab.check(SAMPLES / "raises.py", algorithm="line-dda", cases="sometimes"),
     ["check", SAMPLES / "raises.py", "--against", "line-dda", "--cases", "sometimes"]),
], ids=["algorithm", "count", "option-name", "option-value", "outside", "grid", "whole",
        "scene", "check-family", "check-cases"])
def test_bad_input_raises_the_line_the_command_prints(run_cli, call, argv):
    status, out, err = run_cli(*argv)
    assert status == 2 and err.startswith("rasterlab: ") and err.count("\n") == 1
    with pytest.raises(ValueError) as raised:
        call()
    assert str(raised.value) == err[len("rasterlab: "):].rstrip("\n")


@pytest.mark.parametrize("call, message", [
    (lambda: rasterlab.run("line-bresenham", [1, 2]), "points: expected 2 points, each a pair"),
    (lambda: rasterlab.run("line-bresenham", [(0, 0), (1, 1)], step_cap=0),
     "step_cap must be a whole number 1 .. 50,000,000, got 0"),
    (lambda: rasterlab.run("line-bresenham", [(0, 0), (1, 1)], grid=(8.5, 4)),
     "grid must be two whole numbers, got (8.5, 4)"),
    (lambda: rasterlab.open_scene(3), "a scene is a shipped scene's name or a file, got 3"),
])
def test_bad_python_values_get_one_line(call, message):
    with pytest.raises(ValueError, match=r"^" + message.replace("(", r"\(").replace(")", r"\)")
                       .replace(".", r"\.")):
        call()


def test_a_capped_run_warns_and_says_so():
    with pytest.warns(RuntimeWarning, match="step cap"):
        result = rasterlab.run("line-bresenham", [(0, 0), (30, 9)], step_cap=5)
    assert result.truncated and len(result.steps) == 5


def test_the_command_does_not_load_the_api():
    probe = ("import sys, rasterlab; rasterlab.main(['list']); print('app.api' in sys.modules); "
             "rasterlab.run; print('app.api' in sys.modules, 'run' in dir(rasterlab))")
    done = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-2:] == ["False", "True True"]


# ------------------------------------------------------------ the notebook
def test_the_notebook_player_steps_in_a_browser(tmp_path, short_run):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from tests.support.browser import start_browser

    shown = short_run._repr_html_()
    assert "<script" not in shown  # the page is inside srcdoc, escaped: no script of the notebook's
    notebook = tmp_path / "notebook.html"
    notebook.write_text(f"<!DOCTYPE html><html><head><meta charset='utf-8'></head><body>"
                        f"<h1>Out[1]:</h1>{shown}</body></html>", encoding="utf-8")
    driver = start_browser()
    try:
        driver.get(notebook.as_uri())
        frame = driver.find_element(By.TAG_NAME, "iframe")
        assert frame.size["height"] >= 600
        driver.switch_to.frame(frame)
        _wait_until_ready(driver)
        shown_step = lambda: driver.find_element(By.ID, "stepno").get_attribute("data-step")  # noqa: E731
        current = lambda: driver.find_element(By.CSS_SELECTOR, "#code div.current").text  # noqa: E731
        assert shown_step() == "0"
        driver.find_element(By.ID, "forward").click()
        assert shown_step() == "1"
        driver.find_element(By.TAG_NAME, "body").send_keys(Keys.ARROW_RIGHT)
        assert shown_step() == "2"
        step = short_run.steps[2]
        assert current() == f"{step['line']}{step['code']}"
        driver.find_element(By.TAG_NAME, "body").send_keys(Keys.END)
        assert shown_step() == str(len(short_run.steps) - 1)
    finally:
        driver.quit()


def _wait_until_ready(driver, timeout: float = 20.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        ready, error = driver.execute_script(
            "return [document.body.dataset.ready || null, document.body.dataset.error || null]")
        assert error is None, f"the player failed: {error}"
        if ready:
            return
        time.sleep(0.05)
    raise AssertionError("the player in the iframe did not become ready")


def test_numpy_input_is_taken_as_python_numbers():
    import numpy as np
    result = rasterlab.run("circle-midpoint", np.array([[10, 10]]), radius=np.int64(4),
                           grid=np.array([24, 24]))
    assert result.pixels == rasterlab.run("circle-midpoint", [(10, 10)], radius=4,
                                          grid=(24, 24)).pixels
    assert _plain_data(result.points) and _plain_data(result.options)


def test_a_player_over_its_size_budget_shows_one_line(monkeypatch, short_run):
    from app.render import html
    monkeypatch.setattr(html, "SHORT_BUDGET", 1000)
    shown = short_run._repr_html_()
    assert shown.startswith("<p>the page would take ") and "<iframe" not in shown
