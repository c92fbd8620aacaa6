"""A real browser for the interactive page's tests: Debian's Chromium
(scripts/setup.sh --test installs it) or, where it is absent, the Chrome that
Selenium finds with its driver (as on CI's Windows and macOS machines);
headless, with the network off."""
from __future__ import annotations

import os
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

CHROMIUM, DRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"


def start_browser():
    options = webdriver.ChromeOptions()
    debian = os.path.exists(CHROMIUM) and os.path.exists(DRIVER)
    if debian:
        options.binary_location = CHROMIUM
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--window-size=1400,900", "--force-device-scale-factor=1"):
        options.add_argument(argument)
    driver = webdriver.Chrome(service=Service(DRIVER if debian else None), options=options)
    driver.set_network_conditions(offline=True, latency=0, download_throughput=0,
                                  upload_throughput=0)
    return driver


def open_page(driver, path, timeout: float = 20.0):
    """Load the page and wait until its player says it is ready (or failed)."""
    driver.get(path.resolve().as_uri())
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        state = driver.execute_script(
            "return [document.body.dataset.ready || null, document.body.dataset.error || null]")
        if state[0] or state[1]:
            assert state[1] is None, f"the page failed: {state[1]}"
            return
        time.sleep(0.05)
    raise AssertionError("the page did not become ready")
