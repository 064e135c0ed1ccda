"""`geardyn report` end to end: result folders of fast seed examples, one HTML report each,
opened in headless Chromium. A reader must see every figure drawn and the console must stay
silent; screenshots are kept under the build tree (BUILD/test-results/report/)."""

import base64
import gzip
import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import browser  # noqa: E402

CLI, SOURCE, OUT = browser.CLI, browser.SOURCE, browser.OUT

# example stem -> the figures its report must draw (by heading), one per command kind the
# report knows; all run in well under a second each.
CASES = {
    "hbm_saletti2025_100Nm": ["Forced response", "Periodic solutions"],
    "hbm_backlash_kahraman_singh": ["Forced response"],
    "stiffness_visnadi2021_spur": ["Mesh stiffness"],
    "simulate_gear_pair_backlash": ["Time history"],
    "geometry_rao2023_rig": ["Tooth profiles"],
    "ltca_visnadi2021_long_relief": ["Loaded tooth contact", "Harris map"],
    "stats_gelman2005_case1_a025": [],
    "rotor_rao2023_study": ["Study"],
    "spectrum_rao2023_table41_probes": ["Orbits", "Full spectra"],
    "rotor_visnadi2021_modal": ["Mode shapes"],
    "rotor_visnadi2021_campbell": ["Campbell diagram"],
    "rotor_visnadi2021_time": ["Time history"],
    "train_lin_parker1999": ["Modes", "Mode shapes"],
    "train_two_stage_reducer_stats": ["Mesh statistics"],
    "ltca_two_stage_reducer_stage1": ["Loaded tooth contact", "Harris map"],
}


def _run_example(stem):
    """The example's result folder: the example test's own (GEARDYN_EXAMPLE_RESULTS, set by
    ctest, which runs that test first: each example runs once in the suite), else a run here."""
    if os.environ.get("GEARDYN_EXAMPLE_RESULTS"):
        folder = pathlib.Path(os.environ["GEARDYN_EXAMPLE_RESULTS"]) / stem
        if (folder / "summary.json").is_file():
            return folder
    command = stem.split("_", 1)[0]
    folder = OUT / "runs" / stem
    done = subprocess.run([CLI, command, str(SOURCE / "examples" / f"{stem}.toml"), "--out", str(folder),
                           "--quiet", "--set", "output.plots=false"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return folder


@pytest.fixture(scope="module")
def reports():
    """{stem: report path}, written by the CLI's `geardyn report`."""
    written = {}
    for stem in CASES:
        folder = _run_example(stem)
        page = OUT / f"{stem}.html"
        done = subprocess.run([CLI, "report", str(folder), "--out", str(page)], capture_output=True,
                              text=True)
        assert done.returncode == 0, done.stderr
        assert str(page) in done.stdout
        written[stem] = page
    return written


@pytest.fixture(scope="module")
def chromium():
    yield from browser.session()


# Opened in the browser (each page parses 5 MB of plotly.js: 1-3 s on a loaded 2-core machine),
# one page per kind of figure: line rows (HBM, LTCA), log bars, orbits with equal axes and log
# spectra, FE mode-shape rows, train bars; the other reports are checked for their headings.
IN_BROWSER = ["hbm_saletti2025_100Nm", "ltca_visnadi2021_long_relief", "rotor_rao2023_study",
              "spectrum_rao2023_table41_probes", "rotor_visnadi2021_modal", "train_lin_parker1999",
              "train_two_stage_reducer_stats"]


def _headings(page):
    return re.findall(r"<h3>([^<]*)</h3><div class=\"gd-figure\"", page.read_text())


def test_every_report_has_the_figures_of_its_command(reports):
    for stem, page in reports.items():
        assert _headings(page) == CASES[stem], stem


def test_pages_render_every_figure_with_a_silent_console(reports, chromium):
    for stem in IN_BROWSER:
        page = reports[stem]
        seen = chromium.open(page)
        assert seen["containers"] == len(CASES[stem]), (stem, seen)
        assert seen["rendered"] == seen["containers"], (stem, seen)
        assert seen["drawn"] == seen["containers"], (stem, seen)
        assert all(n > 0 for n in seen["traces"]), (stem, seen)
        assert seen["console"] == [], (stem, seen["console"])
        chromium.screenshot(OUT / "screenshots" / f"{stem}.png")


def test_saletti_forced_response_shows_stable_and_unstable_branches(reports, chromium):
    chromium.open(reports["hbm_saletti2025_100Nm"])
    names = chromium.driver.execute_script(
        "return document.getElementById('gd-figure-0').data.map(t => t.name);")
    for sweep in ("up", "down"):
        assert f"sweep {sweep}, stable" in names and f"sweep {sweep}, unstable" in names, names
    assert "folds" in names and "Newmark (time integration)" in names
    # Drawn, not only declared: the unstable (dashed) traces have SVG paths with a dash array.
    dashed = chromium.driver.execute_script(
        "return Array.from(document.querySelectorAll('#gd-figure-0 .scatterlayer path.js-line'))"
        ".filter(p => (p.style.strokeDasharray || 'none') !== 'none').length;")
    assert dashed >= 2, dashed
    shot = chromium.screenshot(OUT / "screenshots" / "saletti_forced_response.png", "gd-figure-0")
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 20_000


def test_orbits_in_the_report_carry_keyphasor_marks(reports):
    assert "keyphasor (once per rev)" in reports["spectrum_rao2023_table41_probes"].read_text()


def test_report_is_self_contained(reports):
    text = reports["hbm_saletti2025_100Nm"].read_text()
    assert not re.search(r"<script[^>]+src=", text), "a script is loaded from elsewhere"
    assert not re.search(r"<link[^>]+href=\"https?:", text)
    packed = re.search(r'<script type="application/gzip-base64" id="gd-lib-plotly">([^<]*)</script>', text)
    assert packed, "plotly.js is not embedded"
    head = gzip.decompress(base64.b64decode(packed.group(1)))[:2_000].decode()
    assert re.search(r"plotly\.js \(cartesian - minified\) v\d", head), head[:200]
    assert "Resolved configuration" in text and "contact_stiffness" in text
    assert "Headline numbers" in text and "natural_frequency" in text


def test_cli_report_errors(tmp_path):
    missing = subprocess.run([CLI, "report", str(tmp_path / "nowhere")], capture_output=True, text=True)
    assert missing.returncode == 3 and "no such folder" in missing.stderr
    empty = subprocess.run([CLI, "report", str(tmp_path)], capture_output=True, text=True)
    assert empty.returncode == 2 and "no summary.json" in empty.stderr
    typo = subprocess.run([CLI, "reprot", str(tmp_path)], capture_output=True, text=True)
    assert typo.returncode == 2 and "did you mean report" in typo.stderr


def test_default_output_is_report_html_in_the_folder(reports):
    folder = _run_example("geometry_rao2023_rig")  # the example test's folder, or a run here
    done = subprocess.run([CLI, "report", str(folder), "--quiet"], capture_output=True, text=True)
    assert done.returncode == 0 and done.stdout == "", done.stderr
    assert (folder / "report.html").stat().st_size > 400_000  # plotly.js (cartesian) embedded


# The trace types of plotly.js's cartesian bundle (its README), the one the report embeds: a
# figure with another type would be drawn as a scatter, with a console warning.
CARTESIAN_TRACES = {"bar", "box", "contour", "heatmap", "histogram", "histogram2d",
                    "histogram2dcontour", "image", "pie", "scatter", "scatterternary", "violin"}


def test_every_figure_uses_the_embedded_bundles_traces(reports):
    for name, page in reports.items():
        figures = re.search(r'<script type="application/json" id="gd-figures">(.*?)</script>',
                            page.read_text(), re.S)
        types = {trace.get("type", "scatter") for f in json.loads(figures.group(1)) for trace in f["data"]}
        assert types <= CARTESIAN_TRACES, (name, types - CARTESIAN_TRACES)
