"""Save resources/screenshot-axe.png: the interactive page of the shipped
Bresenham demo in headless Chromium, with the result of axe-core's WCAG 2.1
A and AA rules (tests/support/axe.py) printed over it. The audits run first,
in the light and the dark theme, at the first step and mid-run; the printed
box is added to the page only afterwards, from those results.

    python scripts/screenshot_axe.py [OUT.png]
"""
from __future__ import annotations

import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from app.model import shipped  # noqa: E402
from app.model.scene import load  # noqa: E402
from app.render import export as exporting  # noqa: E402
from app.render import html  # noqa: E402
from tests.support import axe  # noqa: E402
from tests.support.browser import open_page, start_browser  # noqa: E402

SIZE = (1280, 720)


def audits(driver, page, steps) -> list[str]:
    """One line per theme and step audited: violations and rules passed."""
    lines = []
    for scheme in ("light", "dark"):
        driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"features": [
            {"name": "prefers-color-scheme", "value": scheme}]})
        open_page(driver, page)
        for step in steps:
            driver.execute_script(f"window.rasterlab.go({step})")
            found = axe.audit(driver)
            broken = ", ".join(f"{rule} x{count}" for rule, count in axe.summary(found).items())
            lines.append(f"{scheme:5} theme, step {step:2}: {broken or 'no violations'}; "
                         f"{found['passes']} rules passed, {len(found['incomplete'])} "
                         "to check by hand")
    return lines


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else ROOT / "resources" / "screenshot-axe.png"
    scene = load(shipped.scene_path("demo-bresenham"))
    trace = exporting.record(scene)
    middle = len(trace) // 2
    with tempfile.TemporaryDirectory() as folder:
        page = Path(folder) / "demo.html"
        html.write_page(scene, trace, page, exporting.ExportSettings())
        driver = start_browser()
        try:
            driver.set_window_size(*SIZE)
            lines = audits(driver, page, (0, middle))
            driver.execute_script("""
                const box = document.createElement('pre');
                box.textContent = arguments[0];
                Object.assign(box.style, {position: 'fixed', left: '16px', bottom: '16px',
                  margin: 0, padding: '10px 14px', background: '#101317', color: '#e6eaef',
                  font: '13px/1.45 "DejaVu Sans Mono", monospace', border: '2px solid #9aa4b0',
                  borderRadius: '6px', zIndex: 10});
                document.body.appendChild(box);""",
                f"axe-core {axe.VERSION}, rules tagged {', '.join(axe.WCAG21_AA)}\n"
                + "\n".join(lines))
            driver.execute_cdp_cmd("Emulation.setDeviceMetricsOverride", {
                "width": SIZE[0], "height": SIZE[1], "deviceScaleFactor": 1, "mobile": False})
            driver.save_screenshot(str(out))
        finally:
            driver.quit()
    print(f"{out}: " + "; ".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
