"""One self-contained HTML report of a geardyn result folder.

``geardyn report RESULT_DIR [--out FILE]`` (the CLI) and ``write_report(result_dir, out=None)``
(Python) write one HTML file holding the run's headline numbers (summary.json ``results``), the
resolved configuration (summary.json ``config``) and interactive plotly.js figures of its tables:
zoom, pan, hover and toggle traces in any browser, with no network; a gear train's report also
holds its 3-D view with animated modes (view3d.py, three.js). plotly.js (MIT; its cartesian
bundle, the npm package ``plotly.js-cartesian-dist-min``: the scatter, bar and heatmap traces the
figures use, 1.3 MB against the full bundle's 4.8 MB, a third of the time to start in the browser)
and three.js are installed by ``scripts/setup.sh`` into ``.cache/npm`` and embedded
gzip-compressed (_embed.py), so the file can be mailed on its own (about 1.5-2 MB).

Where plotly.js is looked for, first found wins: ``$GEARDYN_PLOTLY_JS``; the package's own
``_assets/plotly-cartesian.min.js``;
``.cache/npm/node_modules/plotly.js-cartesian-dist-min/plotly-cartesian.min.js`` in a parent of
this file or of the working directory (a build tree inside the source tree); then a full bundle:
Debian's ``/usr/share/javascript/plotly/plotly.min.js`` (libjs-plotly) and python3-plotly's copy.
"""

import datetime
import html
import json
import math
import os
import pathlib
import sys
import tempfile

from . import _embed
from . import _report_figures as _figures
from . import view3d as _view3d
from ._units import suffix_unit

_NPM_PATH = pathlib.Path(".cache/npm/node_modules/plotly.js-cartesian-dist-min/plotly-cartesian.min.js")


def find_plotly_js():
    """The path of plotly.js (see the module doc for the search order); FileNotFoundError
    naming every place tried and how to install it when none has it."""
    extra = [pathlib.Path("/usr/share/javascript/plotly/plotly.min.js")]
    try:  # python3-plotly keeps a copy unless the distribution stripped it
        import plotly  # noqa: F401  (optional)

        extra.append(pathlib.Path(plotly.__file__).parent / "package_data" / "plotly.min.js")
    except ImportError:
        pass
    modules = pathlib.Path(".cache/npm/node_modules")
    relative = _NPM_PATH.relative_to(modules) if _NPM_PATH.is_relative_to(modules) else _NPM_PATH
    return _embed.first_found(
        "plotly.js", "GEARDYN_PLOTLY_JS", relative,
        lambda path: path.is_file() and path.stat().st_size > 100_000,
        "install it with `bash scripts/setup.sh --deps` (npm package plotly.js-cartesian-dist-min "
        "into .cache/npm) or set GEARDYN_PLOTLY_JS to a copy of plotly.js (any bundle with the "
        "scatter, bar and heatmap traces)", extra)


def _clean(value):
    """JSON-safe: NaN and infinities become null (plotly draws a gap)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    return value


def _script_json(value):
    """JSON for a <script> element: '</' is escaped so no string can close the element."""
    return json.dumps(_clean(value), allow_nan=False, separators=(",", ":")).replace("</", "<\\/")


# Units read from the ends of summary keys, as geardyn writes them (one parser: _units).
def _unit_of(key, parent_unit=""):
    """The unit of a summary key from its suffix ("max_p2p_force_n" -> "N", "torque_n_m" ->
    "N m"); a key without one (a mesh's name) takes its parent's ("mesh_force_n.stage1")."""
    unit = suffix_unit(key)
    if unit is None:
        return parent_unit
    return "°" if unit == "deg" else unit


def _format_number(value):
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:.6g}" if math.isfinite(value) else str(value)
    return str(value)


def headline_rows(summary, limit=60):
    """(name, value, unit) of the scalar results, two levels deep, in the order written; lists
    are shown by their length, strings over 40 characters (prose) left out. At most `limit`
    rows."""
    rows = [("command", summary.get("command", "?"), ""), ("status", summary.get("status", "?"), "")]

    def walk(prefix, table, depth, parent_unit=""):
        for key, value in table.items():
            if depth == 0 and key == "geometry":
                continue  # a train's parts, drawn by its 3-D view: not headline numbers
            name = f"{prefix}{key}"
            if isinstance(value, dict):
                if depth < 2:
                    walk(name + ".", value, depth + 1, _unit_of(key, parent_unit))
            elif isinstance(value, list):
                if value and not isinstance(value[0], (dict, list)) and len(value) <= 6:
                    rows.append((name, ", ".join(_format_number(v) for v in value),
                                 _unit_of(key, parent_unit)))
                else:
                    rows.append((name, f"{len(value)} entries", ""))
            elif isinstance(value, str) and len(value) > 40:
                continue  # prose (conventions, messages) is not a headline number
            elif value is not None:
                rows.append((name, _format_number(value), _unit_of(key, parent_unit)))

    walk("", summary.get("results", {}), 0)
    return rows[:limit]


def _config_text(config):
    try:
        from .run import to_toml

        return to_toml(config)
    except Exception:  # noqa: BLE001  (any trouble: the JSON is as faithful)
        return json.dumps(config, indent=2)


_STYLE = """
body{font-family:system-ui,sans-serif;margin:1.5em auto;max-width:1200px;color:#222;padding:0 1em}
h1{font-size:1.4em;margin-bottom:.2em} h2{font-size:1.1em;border-bottom:1px solid #ccc;margin-top:1.6em}
.meta{color:#555;font-size:.9em}
.headline{display:grid;grid-template-columns:repeat(auto-fill,minmax(370px,1fr));column-gap:2em;font-size:.85em}
.headline div{display:grid;grid-template-columns:1fr auto 3em;border-bottom:1px solid #eee;padding:1px 0}
.headline .num{text-align:right;font-family:monospace;padding-left:1em} .headline .unit{padding-left:.4em}
pre{background:#f6f6f6;padding:.8em;font-size:.8em;overflow:auto;max-height:30em}
.gd-figure{width:100%;height:480px} .caption{color:#555;font-size:.85em;margin:.2em 0 1.2em}
.warning{color:#a40}
"""

# plotly.js is unpacked and run after the 3-D view (when the page has one) has drawn its first
# frame. The figures on the first screen are drawn first (gdLib.times.screen: the page as a reader
# first sees it, the view's first frame when no figure is on it), then the others one at a time, each yielding to the browser so the page stays
# responsive; a figure scrolled to before its turn is drawn at once. The view's animation starts
# when every figure is drawn (gdLib.times.figures), so its frames do not hold up the figures.
_RENDER = """
var gdFigures, gdDivs, gdFirst;
(window.geardynView3d ? window.geardynView3d.mounted : Promise.resolve()).then(function () {
  gdLib.times.view = performance.now();
  gdFigures = JSON.parse(document.getElementById('gd-figures').textContent);
  gdDivs = gdFigures.map(function (f, i) {
    var div = document.getElementById('gd-figure-' + i);
    div.style.height = (f.height || 480) + 'px';
    return div;
  });
  gdFirst = gdDivs.map(function (d, i) { return i; }).filter(function (i) {
    var box = gdDivs[i].getBoundingClientRect();
    return box.bottom > 0 && box.top < window.innerHeight;
  });
  if (!gdFirst.length) gdLib.times.screen = performance.now();
  return gdLib.classic('gd-lib-plotly');
}).then(function () {
  gdLib.times.plotly = performance.now();
  function draw(i) {
    var div = gdDivs[i], f = gdFigures[i];
    if (!div.gdDrawn) {
      div.gdDrawn = Plotly.newPlot(div, f.data, f.layout, {responsive: true, displaylogo: false})
        .then(function () { div.setAttribute('data-rendered', '1'); gdLib.times['figure' + i] = performance.now(); });
    }
    return div.gdDrawn;
  }
  if ('IntersectionObserver' in window) {
    var seen = new IntersectionObserver(function (entries) {
      entries.forEach(function (e) { if (e.isIntersecting) draw(gdDivs.indexOf(e.target)); });
    }, {rootMargin: '200px'});
    gdDivs.forEach(function (d) { seen.observe(d); });
  }
  return Promise.all(gdFirst.map(draw)).then(function () {
    gdLib.times.screen = gdLib.times.screen || performance.now();
    return gdDivs.reduce(function (previous, d, i) {
      return previous.then(function () {
        return new Promise(function (resolve) { setTimeout(resolve, 0); }).then(function () { return draw(i); });
      });
    }, Promise.resolve());
  });
}).then(function () {
  gdLib.times.figures = performance.now();
  if (window.geardynView3d) window.geardynView3d.play();
});
"""


def render_html(summary, figures, plotly_js, title=None, view=None):
    """The report as one HTML string: `figures` are dicts with name, caption, data, layout;
    `view` the 3-D view's HTML fragment (view3d.view_section) or None."""
    title = title or summary.get("config", {}).get("title") or f"geardyn {summary.get('command', '')}"
    esc = html.escape
    parts = [
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">",
        f"<title>{esc(title)}</title><style>{_STYLE}</style>",
        f"<script>{_embed.loader_js()}</script></head><body>",
        f"<h1>{esc(title)}</h1>",
        f"<p class=\"meta\">geardyn {esc(str(summary.get('geardyn_version', '?')))} · "
        f"command <code>{esc(str(summary.get('command', '?')))}</code> · "
        f"status {esc(str(summary.get('status', '?')))} · run {esc(str(summary.get('created_utc', '?')))} · "
        f"configuration {esc(str(summary.get('config_file', '?')))}"
        + (f" · seed {esc(str(summary['seed']))}" if summary.get("seed") is not None else "")
        + (f" · wall time {summary['wall_time_s']:.3g} s"
           if isinstance(summary.get("wall_time_s"), (int, float)) else "") + "</p>",
    ]
    for warning in summary.get("warnings", []) or []:
        parts.append(f"<p class=\"warning\">warning: {esc(str(warning))}</p>")
    parts.append("<h2>Headline numbers</h2><div class=\"headline\">")
    for name, value, unit in headline_rows(summary):
        parts.append(f"<div><span>{esc(name)}</span><span class=\"num\">{esc(str(value))}</span>"
                     f"<span class=\"unit\">{esc(unit)}</span></div>")
    parts.append("</div>")
    if view:
        parts.append("<h2>3-D view</h2><script>window.geardynView3dWait = true;</script>"
                     + _view3d.page_parts() + view
                     + "<p class=\"caption\">The train as modelled (x along the shafts, z up): a click on "
                     "a mode in the list or the Campbell diagram animates it; drag to orbit, wheel to "
                     "zoom, right-drag to pan; hover a part for its body's name.</p>")
    if figures:
        parts.append("<h2>Figures</h2>")
    for i, figure in enumerate(figures):
        parts.append(f"<h3>{esc(figure['name'])}</h3><div class=\"gd-figure\" id=\"gd-figure-{i}\"></div>"
                     f"<p class=\"caption\">{esc(figure.get('caption', ''))}</p>")
    parts.append("<h2>Resolved configuration</h2>")
    parts.append(f"<pre>{esc(_config_text(summary.get('config', {})))}</pre>")
    parts.append(f"<p class=\"meta\">written {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M:%S} UTC "
                 "by geardyn.report; figures drawn with plotly.js (MIT licence)"
                 + (", the 3-D view with three.js (MIT licence)" if view else "") + ", embedded.</p>")
    payload = [{"data": f["data"], "layout": f["layout"], "height": f.get("height", 480)} for f in figures]
    parts.append(f"<script type=\"application/json\" id=\"gd-figures\">{_script_json(payload)}</script>")
    parts.append(_embed.packed_text("gd-lib-plotly", plotly_js))
    parts.append(f"<script>{_RENDER}</script></body></html>\n")
    return "".join(parts)


def write_report(results_dir, out=None):
    """Writes the HTML report of the result folder `results_dir` (it needs summary.json) to `out`
    (default: RESULTS_DIR/report.html), atomically; returns its path."""
    folder = pathlib.Path(results_dir)
    summary_path = folder / "summary.json"
    if not summary_path.is_file():
        raise FileNotFoundError(f"{summary_path}: no summary.json; is {folder} a geardyn result folder?")
    summary = json.loads(summary_path.read_text())
    figures = _figures.figures_of(folder, summary)
    view = _view3d.view_section(folder, summary) if summary.get("command") == "train" else None
    text = render_html(summary, figures, find_plotly_js().read_text(encoding="utf-8"), view=view)
    out = pathlib.Path(out) if out is not None else folder / "report.html"
    out.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix="." + out.name + ".tmp-", dir=out.parent)
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, out)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
    return out


def main(argv=None):
    import argparse

    parser = argparse.ArgumentParser(prog="geardyn report",
                                     description="One self-contained HTML report of a result folder.")
    parser.add_argument("results_dir", help="a folder written by a geardyn command (has summary.json)")
    parser.add_argument("--out", help="the HTML file to write (default RESULTS_DIR/report.html)")
    parser.add_argument("--quiet", action="store_true", help="do not print the path written")
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    try:
        path = write_report(args.results_dir, args.out)
    except json.JSONDecodeError as error:
        print(f"geardyn report: error: {args.results_dir}/summary.json is not valid JSON: {error}",
              file=sys.stderr)
        return 2
    except OSError as error:  # a missing table or plotly.js, an unwritable --out
        print(f"geardyn report: I/O error: {error}", file=sys.stderr)
        return 3
    if not args.quiet:
        print(f"report written: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
