"""A headless Chromium (Debian's chromium + chromium-driver, driven by Debian's
python3-selenium) that opens report pages and says what a reader would see: console messages,
how many plot containers rendered, and a screenshot."""

import os
import pathlib
import shutil
import tempfile
import time

# Where the tests find the executable and the sources, and write their pages and screenshots.
CLI = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
BUILD = pathlib.Path(os.environ.get("GEARDYN_BUILD_DIR", pathlib.Path(CLI).resolve().parents[1]))
OUT = BUILD / "test-results" / "report"

CHROMIUM = os.environ.get("GEARDYN_CHROMIUM", "/usr/bin/chromium")
CHROMEDRIVER = os.environ.get("GEARDYN_CHROMEDRIVER", "/usr/bin/chromedriver")

# Counted in the page: every plot container, those plotly.js finished (data-rendered, set by
# the report when Plotly.newPlot resolved) and those holding an SVG or canvas.
_COUNT = """
const divs = Array.from(document.querySelectorAll('.gd-figure'));
const views = Array.from(document.querySelectorAll('.gd-view3d'));
return {containers: divs.length, views: views.length,
        views_rendered: views.filter(d => d.getAttribute('data-rendered') === '1').length,
        rendered: divs.filter(d => d.getAttribute('data-rendered') === '1').length,
        drawn: divs.filter(d => d.querySelector('svg.main-svg, canvas')).length,
        traces: divs.map(d => (d.data || []).length)};
"""


def missing():
    """Why the browser cannot run here, or None."""
    for path in (CHROMIUM, CHROMEDRIVER):
        if not shutil.which(path):
            return f"{path} not found: install Debian's chromium and chromium-driver (scripts/setup.sh --deps)"
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "python3-selenium is not installed (scripts/setup.sh --deps)"
    return None


def session(**size):
    """A Browser for a test module (a generator for a pytest fixture): skipped when Chromium is
    missing and GEARDYN_SKIP_BROWSER_TESTS=1, an error naming what is missing otherwise."""
    import pytest

    why = missing()
    if why and os.environ.get("GEARDYN_SKIP_BROWSER_TESTS") == "1":
        pytest.skip(why)
    assert why is None, why + " (or set GEARDYN_SKIP_BROWSER_TESTS=1)"
    browser = Browser(**size)
    yield browser
    browser.close()


def page_messages(log):
    """The console messages of the page: all but the GL driver's performance notes, which
    software WebGL (SwiftShader) prints when the compositor reads a canvas back
    ("GL Driver Message (OpenGL, Performance, ...): GPU stall due to ReadPixels") and which say
    nothing about the page."""
    return [f"{e['level']}: {e['message']}" for e in log
            if "GL Driver Message (OpenGL, Performance" not in e["message"]]


class Browser:
    def __init__(self, width=1280, height=1500):
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service

        self._profile = tempfile.mkdtemp(prefix="geardyn-chromium-")
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     f"--window-size={width},{height}", f"--user-data-dir={self._profile}",
                     "--hide-scrollbars", "--force-device-scale-factor=1",
                     "--enable-unsafe-swiftshader"):  # WebGL (the 3-D view) in software
            options.add_argument(flag)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        self.driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)

    def open(self, path, timeout=600.0):
        """Loads the page and waits until every plot container and 3-D view rendered (or
        `timeout` s: long enough for a busy machine, it returns as soon as they are drawn);
        returns {containers, rendered, drawn, traces, views, views_rendered,
        console: [messages]}."""
        self.driver.get(pathlib.Path(path).resolve().as_uri())
        deadline = time.monotonic() + timeout
        while True:
            counts = self.driver.execute_script(_COUNT)
            done = counts["rendered"] == counts["containers"] and counts["views_rendered"] == counts["views"]
            if done or time.monotonic() > deadline:
                break
            time.sleep(0.1)
        counts["console"] = page_messages(self.driver.get_log("browser"))
        return counts

    def page_console(self):
        """The page's console messages since the last look (page_messages)."""
        return page_messages(self.driver.get_log("browser"))

    def screenshot(self, path, element_id=None):
        """A PNG of the page's viewport, or of one element (scrolled into view)."""
        path = pathlib.Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        if element_id:
            from selenium.webdriver.common.by import By

            element = self.driver.find_element(By.ID, element_id)
            self.driver.execute_script("arguments[0].scrollIntoView({block: 'center'});", element)
            element.screenshot(str(path))
        else:
            self.driver.save_screenshot(str(path))
        return path

    def close(self):
        self.driver.quit()
        shutil.rmtree(self._profile, ignore_errors=True)
