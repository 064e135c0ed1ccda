"""The result of an in-process analysis: ``geardyn.run(...)`` returns a :class:`Result`.

A Result holds the compiled result (tables as columns in C++ memory) and shows them as numpy
arrays without a copy (read-only views whose base keeps the result alive), as pandas DataFrames
with the unit of every column in ``df.attrs["units"]``, and as the ``summary.json`` document the
command-line tool would write (``summary``). Nothing is written to disk unless asked
(``save(folder)``).

>>> import geardyn
>>> r = geardyn.run("geometry", {"pinion": {"teeth": 25, "module": 3e-3, "face_width": 0.02},
...                              "gear": {"teeth": 30, "module": 3e-3, "face_width": 0.02}})
>>> round(r.results["contact_ratio_transverse"], 4)
1.6326
"""

import html
import json
import pathlib
import tempfile

from ._units import column_units

__all__ = ["Result", "html_card"]

# The numbers each command's repr shows first: (label, JSON pointer into results, unit).
_HEADLINES = {
    "geometry": [("contact ratio (transverse)", "/contact_ratio_transverse", ""),
                 ("centre distance", "/centre_distance", "m"),
                 ("mesh frequency", "/mesh_frequency", "Hz")],
    "stiffness": [("contact ratio", "/geometry/contact_ratio_transverse", ""),
                  ("mesh frequency", "/geometry/mesh_frequency", "Hz")],
    "simulate": [("mean mesh force", "/mesh_force/mean", "N"),
                 ("mesh force peak to peak", "/mesh_force/peak_to_peak", "N"),
                 ("dynamic factor", "/dynamic_factor", ""),
                 ("contact loss fraction", "/contact_loss_fraction", "")],
    "hbm": [("points", "/points", ""), ("peak p2p", "/peak/p2p", "m"),
            ("at frequency", "/peak/frequency", "Hz"),
            ("natural frequency", "/natural_frequency", "Hz")],
    "rotor": [("mesh frequency", "/frequencies/mesh_hz", "Hz"),
              ("pinion speed", "/frequencies/pinion_hz", "Hz")],
    "stats": [("mean excitation ratio R", "/mean_excitation/ratio", "")],
    "spectrum": [("sample rate", "/sample_rate", "Hz")],
    "identify": [("mesh stiffness", "/mesh_stiffness/value", "N/m")],
    "ltca": [],
    "train": [("input speed", "/kinematics/input_speed_rpm", "rpm"),
              ("output torque", "/kinematics/output_torque_n_m", "N m"),
              ("lowest natural frequency", "/modal/lowest_frequency_hz", "Hz")],
}


def _pointer(document, pointer):
    node = document
    for part in pointer.strip("/").split("/"):
        if isinstance(node, dict) and part in node:
            node = node[part]
        else:
            return None
    return node


def headline_of(command, results):
    """{label [unit]: value} of the numbers a ``command``'s result shows first."""
    out = {}
    for label, pointer, unit in _HEADLINES.get(command, []):
        value = _pointer(results, pointer)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            out[f"{label} [{unit}]" if unit else label] = value
    return out


class Result:
    """One analysis's result, in memory.

    - ``command``, ``status`` ("ok" or the solver's status), ``ok``, ``wall_time_s``
    - ``summary``: the summary.json document (version, resolved configuration, seed, status,
      warnings, results); ``results``: its headline numbers; ``warnings``
    - ``tables``: the table names; ``table(name)``: {column: numpy array} (no copy);
      ``to_pandas(name=None)``: a DataFrame, units in ``.attrs["units"]``
    - ``report_text``: what the CLI prints; ``save(folder)``: the CLI's result folder;
      ``plot(folder)``: the CLI's PNG plots in ``folder``; ``report(out=None)``: the HTML report
    - ``view3d()``: a train's 3-D view with animated modes (an HTML page); Jupyter shows it
      inline (``_repr_html_``)
    """

    def __init__(self, native):
        self._native = native
        self._summary = None
        self._units = {}

    @property
    def summary(self):
        """The summary.json document (made on first access)."""
        if self._summary is None:
            self._summary = json.loads(self._native.summary_json())
        return self._summary

    # --- what the run was -------------------------------------------------------------
    @property
    def command(self):
        return self._native.command

    @property
    def status(self):
        return self._native.status

    @property
    def ok(self):
        """True unless the numerical method failed (then ``status`` says how)."""
        return not self._native.numerical_failure

    @property
    def wall_time_s(self):
        return self._native.wall_time_s

    @property
    def results(self):
        return self.summary.get("results", {})

    @property
    def warnings(self):
        return list(self._native.warnings)

    @property
    def errors(self):
        return list(self._native.errors)

    @property
    def report_text(self):
        return self._native.report

    @property
    def headline(self):
        """{label [unit]: value} of the numbers the repr shows."""
        return headline_of(self.command, self.results)

    # --- tables --------------------------------------------------------------------------
    @property
    def tables(self):
        """The table names ("time_response", ...), as the CSV files without ".csv"."""
        return [n[:-4] if n.endswith(".csv") else n for n in self._native.table_names]

    def table(self, name=None):
        """A table as {column: numpy array}: read-only views of the result's memory (text
        columns as lists of str). ``name`` defaults to the first table."""
        return self._native.columns(self._table_name(name))

    def units(self, name=None):
        """{column: unit} of a table ("" for dimensionless, None for text)."""
        name = self._table_name(name)
        if name not in self._units:
            self._units[name] = column_units(self, name, self.table(name))
        return self._units[name]

    def to_pandas(self, name=None):
        """A table as a pandas DataFrame (numeric columns share the result's memory where
        pandas allows). ``df.attrs["units"]`` maps each column to its unit; column names
        already carry it where the CSV files do (``base_radius_m``)."""
        import pandas as pd

        name = self._table_name(name)
        frame = pd.DataFrame(self.table(name), copy=False)
        frame.attrs["units"] = self.units(name)
        frame.attrs["table"] = name
        frame.attrs["command"] = self.command
        return frame

    def _table_name(self, name):
        names = self.tables
        if not names:
            raise LookupError(f"the {self.command} result has no tables")
        if name is None:
            return names[0]
        name = name[:-4] if name.endswith(".csv") else name
        if name not in names:
            import difflib

            close = difflib.get_close_matches(name, names, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise KeyError(f"no table {name!r}{hint}; the {self.command} result has "
                           f"{', '.join(names)}")
        return name

    # --- files ---------------------------------------------------------------------------
    def save(self, folder):
        """Writes the result folder the CLI would write (tables and summary.json, no plots);
        returns its path."""
        self._native.save(str(folder))
        return pathlib.Path(folder)

    def plot(self, folder):
        """Writes the result to ``folder`` and draws the CLI's plots there as PNG files
        (geardyn.plot); returns what the plot function returns."""
        import inspect

        from . import plot as plots

        self.save(folder)
        fe = self.command == "rotor" and "model" in self.summary.get("config", {})
        if fe:
            from .plot_fe_rotor import plot_rotor_fe as function
        else:
            function = getattr(plots, f"plot_{self.command}")
        if "save" in inspect.signature(function).parameters:  # plot functions returning Figures
            return function(str(folder), save=True)
        return function(str(folder))

    def report(self, out=None, folder=None):
        """The interactive HTML report of this result (geardyn.report.write_report), written
        to ``out``. The result folder it is made from goes to ``folder`` when given, else to a
        temporary folder that is removed afterwards (then ``out`` is required)."""
        try:
            from .report import write_report
        except ImportError as error:
            raise NotImplementedError("geardyn.report is not available in this build") from error
        if folder is not None:
            self.save(folder)
            return write_report(str(folder), out)
        if out is None:
            raise ValueError("out: give the HTML file to write (or a folder to keep the results)")
        with tempfile.TemporaryDirectory(prefix="geardyn-report-") as work:
            self.save(work)
            return write_report(work, out)

    # --- display -------------------------------------------------------------------------
    def __repr__(self):
        lines = [f"<geardyn {self.command} result: status {self.status}, "
                 f"{self.wall_time_s:.3g} s, tables {', '.join(self.tables) or '(none)'}>"]
        lines += [line for line in self.report_text.splitlines() if line.strip()]
        return "\n".join(lines)

    def view3d(self):
        """The 3-D view of a gear train's result (geardyn.view3d: its parts, animated modes and
        Campbell diagram) as a standalone HTML page, or None when the result has nothing to
        draw (not a train, or no modes)."""
        if self.command != "train" or "geometry" not in self.results:
            return None
        from . import view3d

        with tempfile.TemporaryDirectory(prefix="geardyn-view3d-") as work:
            self.save(work)
            return view3d.view_page(work, self.summary)

    def _repr_html_(self):
        return html_card(self, self.report_text)


def html_card(result, report_text=""):
    """Jupyter's view of a result (Result or FolderResult): command, status, wall time, the
    headline numbers with units, a train's 3-D view in an iframe, the CLI's lines, the tables."""
    rows = "".join(f"<tr><td>{html.escape(k)}</td><td>{v:.6g}</td></tr>"
                   for k, v in result.headline.items())
    status = html.escape(str(result.status))
    colour = "#2a7" if result.ok else "#c33"
    try:  # a train's 3-D view, in an iframe: its scripts and styles stay its own
        page = result.view3d()
    except OSError:  # three.js not installed: the view is left out, the rest is shown
        page = None
    view = ("" if page is None else
            f"<iframe srcdoc=\"{html.escape(page, quote=True)}\" style=\"width:100%;height:640px;"
            f"border:0\" title=\"geardyn 3-D view\"></iframe>")
    wall = result.wall_time_s
    took = f", {wall:.3g} s" if isinstance(wall, (int, float)) else ""
    text = f"<pre>{html.escape(report_text)}</pre>" if report_text else ""
    return (f"<div><b>geardyn {html.escape(str(result.command))}</b> — status "
            f"<span style='color:{colour}'>{status}</span>{took}"
            f"<table>{rows}</table>{view}{text}"
            f"<small>tables: {html.escape(', '.join(result.tables))}</small></div>")
