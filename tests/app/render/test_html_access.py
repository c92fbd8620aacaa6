"""The interactive page for every reader (WCAG 2.1 AA), in headless Chromium:
axe-core finds no violation in either theme, on a desktop and a phone, at
the first step and mid-run; the caption is a live region whose words follow
the keys; every control has a name; the focus is in sight and never trapped;
a dark system scheme opens the page dark, with text at 4.5:1; reduced
motion keeps the page from playing by itself."""
import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

from app.model.scene import Scene
from app.render import export as ex
from app.render import html
from tests.support import axe, record
from tests.support.browser import open_page, start_browser

P, Q = (1, 1), (12, 6)
SCENE = Scene(algorithm="line-bresenham", points=(P, Q), width=14, height=8,
              bookmarks=({"name": "first NE", "step": 3},))
TRACE = record("line-bresenham", [P, Q], grid=(14, 8))


@pytest.fixture(scope="module")
def browser():
    driver = start_browser()
    yield driver
    driver.quit()


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    path = tmp_path_factory.mktemp("page") / "demo.html"
    html.write_page(SCENE, TRACE, path, ex.ExportSettings().for_grid(14, 8))
    return path


def emulate(driver, **features):
    """Media features as the system would state them, e.g. prefers_color_scheme="dark"."""
    driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"features": [
        {"name": name.replace("_", "-"), "value": value} for name, value in features.items()]})


@pytest.fixture
def plain(browser):
    yield browser
    emulate(browser)
    browser.set_window_size(1400, 900)


@pytest.mark.parametrize("size", [(1280, 720), (390, 844)])
@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_axe_finds_no_violation_at_wcag_21_aa(page, plain, size, scheme):
    plain.set_window_size(*size)
    emulate(plain, prefers_color_scheme=scheme)
    open_page(plain, page)
    assert plain.execute_script("return window.rasterlab.theme()") == scheme
    for step in (0, 6):   # step 6 shows values that changed (bold, underlined)
        plain.execute_script(f"window.rasterlab.go({step})")
        results = axe.audit(plain)
        assert "error" not in results, results.get("error")
        assert results["version"] == axe.VERSION
        assert axe.summary(results) == {}, [(v["id"], v["help"]) for v in results["violations"]]
        assert results["passes"] > 10   # the rules ran (labels, contrast, names, ...)


def test_the_caption_reads_each_step_the_keys_move_to(page, plain):
    open_page(plain, page)
    caption = plain.find_element(By.ID, "caption")
    assert caption.get_attribute("aria-live") == "polite"
    words = html.step_words(TRACE, 0, len(TRACE) - 1)
    body = plain.find_element(By.TAG_NAME, "body")
    for key, step in ((Keys.ARROW_RIGHT, 1), (Keys.ARROW_RIGHT, 2), (Keys.END, len(TRACE) - 1),
                      (Keys.ARROW_LEFT, len(TRACE) - 2), (Keys.HOME, 0)):
        body.send_keys(key)
        assert caption.text == words[step]
    # From P = (1, 1) to Q = (12, 6): dx = 11, dy = 5, d0 = 2dy - dx = -1 (E), then
    # d = -1 + 2dy = 9 (NE), then 9 + 2(dy - dx) = -3 (E).
    assert words[1].startswith("step 1 of 13:") and "plot (1, 1)" in words[1]
    assert words[2] == "step 2 of 13: d = -1, at most 0, so E: plot (2, 1)"
    assert words[3] == "step 3 of 13: d = 9, above 0, so NE: plot (3, 2)"
    assert words[4] == "step 4 of 13: d = -3, at most 0, so E: plot (4, 2)"


def test_the_caption_is_silent_while_playing_and_speaks_where_play_stops(page, plain):
    open_page(plain, page)
    body = plain.find_element(By.TAG_NAME, "body")
    body.send_keys(" ")
    caption = plain.find_element(By.ID, "caption")
    assert plain.execute_script("return window.rasterlab.playing()")
    assert caption.get_attribute("aria-live") == "off"
    body.send_keys(" ")
    assert not plain.execute_script("return window.rasterlab.playing()")
    assert caption.get_attribute("aria-live") == "polite"
    step = plain.execute_script("return window.rasterlab.step()")
    assert caption.text == html.step_words(TRACE, 0, len(TRACE) - 1)[step]


def test_every_control_has_a_name(page, plain):
    open_page(plain, page)
    unnamed = plain.execute_script(
        "return [...document.querySelectorAll('button, input, select')].filter(e =>"
        " !(e.getAttribute('aria-label') || e.labels && e.labels.length && e.labels[0].textContent.trim()"
        "   || e.textContent.trim())).map(e => e.id)")
    assert unnamed == []
    assert plain.find_element(By.ID, "slider").get_attribute("aria-label") == "Step"
    assert plain.find_element(By.ID, "first").get_attribute("aria-label") == "First step"


def test_tab_walks_every_control_with_the_focus_in_sight_and_out_again(page, plain):
    open_page(plain, page)
    body = plain.find_element(By.TAG_NAME, "body")
    seen = []
    for _ in range(40):
        body.send_keys(Keys.TAB) if not seen else plain.switch_to.active_element.send_keys(Keys.TAB)
        focused = plain.execute_script(
            "const e = document.activeElement, s = getComputedStyle(e);"
            " return [e.id || e.tagName, s.outlineStyle, parseFloat(s.outlineWidth)]")
        if focused[0] == "BODY" or focused[0] in seen:
            break   # past the last control: the focus leaves the page, no trap
        assert focused[1] != "none" and focused[2] >= 2, focused   # a visible ring
        seen.append(focused[0])
    for control in ("fit", "theme", "first", "back", "play", "forward", "last", "slider", "speed",
                    "chapters", "show-primitive", "show-highlight", "steps"):
        assert control in seen
    assert seen.index("first") < seen.index("play") < seen.index("slider")


def test_the_keys_zoom_the_grid(page, plain):
    open_page(plain, page)
    zoom = "return window.rasterlab.axisLabels()[1].x - window.rasterlab.axisLabels()[0].x"
    before = plain.execute_script(zoom)
    plain.find_element(By.TAG_NAME, "body").send_keys("-")
    assert plain.execute_script(zoom) < before


def luminance(colour):
    channels = []
    for v in colour:
        v /= 255
        channels.append(v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4)
    return 0.2126 * channels[0] + 0.7152 * channels[1] + 0.0722 * channels[2]


def contrast(a, b):
    high, low = sorted((luminance(a), luminance(b)), reverse=True)
    return (high + 0.05) / (low + 0.05)


def test_a_dark_system_scheme_opens_the_page_dark_with_readable_text(page, plain):
    emulate(plain, prefers_color_scheme="dark")
    open_page(plain, page)
    plain.execute_script("window.rasterlab.go(6)")
    assert plain.execute_script("return window.rasterlab.theme()") == "dark"
    # Each text's colour against the background it sits on, as the browser computes them.
    pairs = plain.execute_script("""
        const rgb = s => s.match(/\\d+/g).slice(0, 3).map(Number);
        const back = e => { for (; e; e = e.parentElement) { const c = getComputedStyle(e).backgroundColor;
                            if (!c.endsWith(', 0)') && c !== 'transparent') return rgb(c); } return [255, 255, 255]; };
        return ['#title', '#summary', '#caption', '#code .no', '#code .current', '#vars th', '#vars td',
                '.changed', '#stepno', '#play', 'label', '#steptable td']
          .map(s => { const e = document.querySelector(s); return [s, rgb(getComputedStyle(e).color), back(e)]; });""")
    body_background = plain.execute_script("return getComputedStyle(document.body).backgroundColor")
    assert luminance([int(v) for v in body_background[4:-1].split(",")]) < 0.05   # dark indeed
    for selector, text, background in pairs:
        assert contrast(text, background) >= 4.5, (selector, text, background)
    emulate(plain, prefers_color_scheme="light")
    assert settles(plain, "window.rasterlab.theme() === 'light'")   # it follows a change


def test_reduced_motion_keeps_the_page_still(page, plain):
    autoplay = page.resolve().as_uri() + "#play"
    plain.get("about:blank")
    plain.get(autoplay)
    assert settles(plain, "document.body.dataset.ready === '1'")
    assert plain.execute_script("return window.rasterlab.playing()")   # #play plays on opening
    emulate(plain, prefers_reduced_motion="reduce")
    assert settles(plain, "!window.rasterlab.playing()")   # and stops when motion is reduced
    plain.get("about:blank")
    plain.get(autoplay)
    assert settles(plain, "document.body.dataset.ready === '1'")
    assert not plain.execute_script("return window.rasterlab.playing()")
    assert plain.execute_script("return window.rasterlab.step()") == 0
    plain.find_element(By.TAG_NAME, "body").send_keys(" ")   # a person may still play it
    assert plain.execute_script("return window.rasterlab.playing()")


def settles(driver, condition: str, tries: int = 200) -> bool:
    """Whether the page's ``condition`` (JavaScript) holds within ``tries``
    of the page's own 25 ms timer (media changes reach the page as events)."""
    for _ in range(tries):
        if driver.execute_script(f"return {condition}"):
            return True
        driver.execute_async_script("setTimeout(arguments[0], 25)")
    return False
