"""The interactive page, in a real browser (headless Chromium, network off):
its step counter, highlighted pseudo-code line and the canvas colours at
the plotted cells follow the trace; it asks nothing of the network; runs
stay within the size budget; bad requests are refused in one line."""
import numpy as np
import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from app.model.scene import Scene, save
from app.render import export as ex
from app.render import html
from tests.support import record
from tests.support.browser import open_page, start_browser

P, Q = (1, 1), (12, 6)
SCENE = Scene(algorithm="line-bresenham", points=(P, Q), width=14, height=8,
              bookmarks=({"name": "first NE", "step": 3},))


@pytest.fixture(scope="module")
def browser():
    driver = start_browser()
    yield driver
    driver.quit()


def page_state(driver):
    return driver.execute_script(
        "return [window.rasterlab.step(), document.getElementById('stepno').dataset.step,"
        " [...document.querySelectorAll('#code div')].findIndex(d => d.classList.contains('current')),"
        " performance.getEntriesByType('resource').length]")


def expected_colours(scene, index):
    """Cell colours of frame ``index`` as the export draws them (the GIF's)."""
    renderer = ex.FrameRenderer(scene, ex.ExportSettings(scale=16, primitive=False,
                                                        highlight=False, panel="none"))
    return renderer.cells(index)


def test_the_page_steps_with_the_keys_as_the_trace_says(tmp_path, browser):
    page = tmp_path / "demo.html"
    html.write_page(SCENE, record("line-bresenham", [P, Q], grid=(14, 8)), page,
                    ex.ExportSettings().for_grid(14, 8))
    trace = record("line-bresenham", [P, Q], grid=(14, 8))
    open_page(browser, page)
    body = browser.find_element(By.TAG_NAME, "body")
    for k in range(1, 6):
        body.send_keys(Keys.ARROW_RIGHT)
        step, shown, line, requests = page_state(browser)
        assert (step, int(shown), line) == (k, k, trace.step(k).line)
        assert requests == 0
    body.send_keys(Keys.END)
    step, shown, line, _ = page_state(browser)
    browser.execute_script("window.rasterlab.show(false, false)")
    last = len(trace) - 1
    assert (step, int(shown), line) == (last, last, trace.step(last).line)
    colours = expected_colours(SCENE, last)
    for x, y in [tuple(p) for p in trace.written().pixels.tolist()] + [(0, 7), (13, 0)]:
        got = browser.execute_script(f"return window.rasterlab.cellColour({x}, {y})")
        assert got == colours[y, x].tolist(), (x, y)


def test_a_span_fill_page_draws_what_the_export_draws(tmp_path, browser):
    scene = Scene(algorithm="polygon-scanline", points=(((1, 1), (12, 2), (6, 9)),
                                                        ((5, 3), (8, 3), (6, 6))),
                  width=14, height=11, origin="top-left")
    page = tmp_path / "fill.html"
    trace = record("polygon-scanline", [list(c) for c in scene.points], grid=(14, 11))
    html.write_page(scene, trace, page, ex.ExportSettings().for_grid(14, 11))
    open_page(browser, page)
    browser.execute_script("window.rasterlab.show(false, false)")
    middle = len(trace) // 2
    browser.execute_script(f"window.rasterlab.go({middle})")
    tables = browser.execute_script("return document.getElementById('tables').textContent")
    assert "AET" in tables and "ymax" in tables
    for index in (middle, len(trace) - 1):
        browser.execute_script(f"window.rasterlab.go({index})")
        colours = expected_colours(scene, index)
        for y in range(11):
            for x in range(14):
                got = browser.execute_script(f"return window.rasterlab.cellColour({x}, {y})")
                assert got == colours[y, x].tolist(), (index, x, y)


def test_a_100000_step_run_stays_within_its_size_budget(tmp_path):
    scene = Scene(algorithm="flood-fill", points=(((1, 1), (318, 3), (160, 318)),),
                  width=320, height=320)
    trace = ex.record(scene)
    assert len(trace) > 100_000 * 0.95
    size = html.write_page(scene, trace, tmp_path / "big.html", ex.ExportSettings())
    assert size == (tmp_path / "big.html").stat().st_size <= html.page_budget(len(trace))


def test_a_million_step_flood_fill_stays_within_its_size_budget(tmp_path):
    scene = Scene(algorithm="flood-fill", points=(((1, 1), (1000, 3), (500, 1000)),),
                  width=1024, height=1024)
    trace = ex.record(scene)
    assert len(trace) >= 1_000_000
    size = html.write_page(scene, trace, tmp_path / "big.html", ex.ExportSettings())
    assert size <= html.page_budget(len(trace)) == 5 * 2 ** 20


def test_a_page_over_its_budget_is_refused_without_force(tmp_path, run_cli, monkeypatch):
    scene = tmp_path / "s.json"
    save(SCENE, scene)
    monkeypatch.setattr(html, "SHORT_BUDGET", 1000)
    status, out, err = run_cli("export", scene, "--html", tmp_path / "a.html")
    assert status == 2 and out == "" and err.count("\n") == 1 and "--force" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.json"]
    status, out, err = run_cli("export", scene, "--html", tmp_path / "a.html", "--force")
    assert status == 0 and (tmp_path / "a.html").stat().st_size > 1000


def test_an_unwritable_page_gets_one_line_and_no_file(tmp_path, run_cli):
    scene = tmp_path / "s.json"
    save(SCENE, scene)
    status, out, err = run_cli("export", scene, "--html", tmp_path / "no" / "a.html")
    assert status == 2 and err.count("\n") == 1 and "a.html" in err


def test_the_page_needs_nothing_from_outside():
    text = html.TEMPLATE.read_text()
    assert "default-src 'none'" in text
    for outside in ("http://", "https://", "src=", "@import", "url("):
        assert outside not in text.replace("http://www.w3.org", "")


def test_exact_numbers_show_the_weights_and_m_as_fractions(tmp_path, browser):
    # Weights at pixel (1, 0) of (0,0) (4,0) (0,4): its centre (3/2, 1/2) gives
    # alpha = 1 - 3/8 - 1/8 = 1/2, beta = x/4 = 3/8, gamma = y/4 = 1/8 (worked by hand).
    points = ((0, 0), (4, 0), (0, 4))
    scene = Scene(algorithm="triangle-cramer", points=points, width=6, height=6)
    trace = record("triangle-cramer", list(points), grid=(6, 6))
    step = next(i for i in range(len(trace))
                if trace.step(i).pixel == (1, 0) and "beta" in trace.variables_at(i))
    page = tmp_path / "weights.html"
    html.write_page(scene, trace, page, ex.ExportSettings(numbers="exact").for_grid(6, 6))
    open_page(browser, page)
    browser.execute_script(f"window.rasterlab.go({step})")
    shown = browser.execute_script("return document.getElementById('vars').textContent")
    assert "1/2" in shown and "3/8" in shown and "1/8" in shown, shown
    # Bresenham's m = dy/dx of the line on show: (1,1)->(12,6) is 5/11.
    page = tmp_path / "line.html"
    trace = record("line-bresenham", [P, Q], grid=(14, 8))
    html.write_page(SCENE, trace, page, ex.ExportSettings(numbers="exact").for_grid(14, 8))
    open_page(browser, page)
    browser.execute_script("window.rasterlab.go(3)")
    assert "5/11" in browser.execute_script("return document.getElementById('vars').textContent")


def write_demo(tmp_path, grid=(14, 8)):
    page = tmp_path / "demo.html"
    trace = record("line-bresenham", [P, Q], grid=grid)
    html.write_page(SCENE, trace, page, ex.ExportSettings().for_grid(*grid))
    return page, trace


def rect(driver, selector):
    return driver.execute_script(
        f"const r = document.querySelector('{selector}').getBoundingClientRect();"
        " return [r.left, r.top, r.right, r.bottom];")


@pytest.fixture
def phone(browser):
    browser.set_window_size(390, 844)
    yield browser
    browser.set_window_size(1400, 900)


def test_a_phone_gets_one_column(tmp_path, phone):
    page, _ = write_demo(tmp_path)
    open_page(phone, page)
    width = phone.execute_script("return document.documentElement.clientWidth")
    view, code, caption = (rect(phone, s) for s in ("#view", "#code", "#caption"))
    assert view[2] - view[0] >= 0.9 * width  # the grid takes the page's width
    assert code[1] >= view[3]  # the pseudo-code comes below the grid
    # The caption overlaps neither the pseudo-code nor the grid.
    assert caption[1] >= code[3] or caption[3] <= code[1]
    assert caption[1] >= view[3]
    assert phone.execute_script("return document.documentElement.scrollWidth") <= width


def test_the_grid_has_axis_coordinates(tmp_path, browser):
    page, _ = write_demo(tmp_path)
    open_page(browser, page)
    labels = browser.execute_script("return window.rasterlab.axisLabels()")
    xs = [label for label in labels if label["axis"] == "x"]
    ys = [label for label in labels if label["axis"] == "y"]
    assert [label["value"] for label in xs] == list(range(14))  # 14 columns, room for each
    assert [label["value"] for label in ys] == list(range(8))
    view = browser.execute_script("return [document.getElementById('grid').clientWidth,"
                                  " document.getElementById('grid').clientHeight]")
    assert all(0 <= label["x"] <= view[0] and 0 <= label["y"] <= view[1] for label in labels)
    # Each x label sits under its column, left to right; y counts up the page (y up).
    assert [label["x"] for label in xs] == sorted(label["x"] for label in xs)
    assert [label["y"] for label in ys] == sorted((label["y"] for label in ys), reverse=True)
    step = xs[1]["x"] - xs[0]["x"]
    assert all(abs(b["x"] - a["x"] - step) < 0.01 for a, b in zip(xs, xs[1:]))


def test_the_keys_work_after_the_speed_list_and_in_either_case(tmp_path, browser):
    page, _ = write_demo(tmp_path)
    open_page(browser, page)
    speed = browser.find_element(By.ID, "speed")
    chosen = speed.get_attribute("value")
    browser.execute_script("document.getElementById('speed').focus()")
    speed.send_keys(Keys.ARROW_RIGHT)
    speed.send_keys(Keys.ARROW_RIGHT)
    assert browser.execute_script("return window.rasterlab.step()") == 2
    assert speed.get_attribute("value") == chosen  # the list kept its speed
    body = browser.find_element(By.TAG_NAME, "body")
    theme = browser.execute_script("return window.rasterlab.theme()")
    body.send_keys("T")  # as the docs write it: Shift+T
    assert browser.execute_script("return window.rasterlab.theme()") != theme
    shown = browser.execute_script("return [document.getElementById('show-primitive').checked,"
                                   " document.getElementById('show-highlight').checked]")
    body.send_keys("I")
    body.send_keys("O")
    assert browser.execute_script("return [document.getElementById('show-primitive').checked,"
                                  " document.getElementById('show-highlight').checked]") == \
        [not shown[0], not shown[1]]


def test_stepping_on_a_phone_keeps_the_grid_in_sight(tmp_path, phone):
    page, _ = write_demo(tmp_path)
    open_page(phone, page)
    body = phone.find_element(By.TAG_NAME, "body")
    for _ in range(6):
        body.send_keys(Keys.ARROW_RIGHT)
    assert phone.execute_script("return window.scrollY") == 0
