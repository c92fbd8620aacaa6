"""The page plays an animation at no more than 7 pictures a second, in
headless Chromium: at the fastest speed its play loop goes at the run's
playback cap (carried in the page's data from app/render/flash_guard.py),
and a note beside the speed list says why; a run without animation frames
plays at the speed chosen, with no note."""
import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

from algorithms.core.steps import Vars
from app.model import shipped
from app.model.scene import load
from app.render import export as ex
from app.render import html
from tests.support.browser import open_page, start_browser

FASTEST = 8192


@pytest.fixture(scope="module")
def browser():
    driver = start_browser()
    yield driver
    driver.quit()


def written(tmp_path, name):
    scene = load(shipped.scene_path(name))
    trace = ex.record(scene)
    path = tmp_path / f"{name}.html"
    html.write_page(scene, trace, path, ex.ExportSettings().for_grid(trace.width, trace.height))
    return path, trace


def fewest_steps_between_pictures(trace) -> int:
    """From the records: the empty grid at step 0, then frame k complete one
    step before the Vars record of frame k + 1 (the last one step before the
    closing record)."""
    starts = [index for index, record in trace.records_of(Vars) if "frame" in record.values]
    complete = [0] + [start - 1 for start in starts[1:]] + [len(trace) - 2]
    return min(b - a for a, b in zip(complete, complete[1:]))


def play_fastest(browser, path):
    open_page(browser, path)
    Select(browser.find_element(By.ID, "speed")).select_by_value(str(FASTEST))
    browser.find_element(By.ID, "play").click()
    assert browser.execute_script("return window.rasterlab.playing()")
    speed = browser.execute_script("return window.rasterlab.playSpeed()")
    browser.find_element(By.ID, "play").click()   # pause
    return speed, browser.find_element(By.ID, "speed-note")


def test_the_fastest_speed_plays_an_animation_at_its_cap(browser, tmp_path):
    path, trace = written(tmp_path, "aa-motion-blur-jittered")
    cap = 7 * fewest_steps_between_pictures(trace)
    speed, note = play_fastest(browser, path)
    assert speed == cap < FASTEST
    assert note.is_displayed()
    assert note.text.startswith(f"Playing at most {cap} steps/s") and "3 times a second" in note.text
    Select(browser.find_element(By.ID, "speed")).select_by_value("64")
    assert not note.is_displayed()                        # below the cap: no note
    assert browser.execute_script("return window.rasterlab.playSpeed()") == 64


def test_a_run_without_animation_frames_plays_at_the_speed_chosen(browser, tmp_path):
    path, _ = written(tmp_path, "demo-bresenham")
    speed, note = play_fastest(browser, path)
    assert speed == FASTEST
    assert not note.is_displayed()
