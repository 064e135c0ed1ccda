"""The ``geardyn`` executable from Python, for the commands that run across processes
(``sweep``, which may use MPI, and ``train``): ``run_cli(command, config)``. Every other
analysis runs in-process (geardyn.run, analysis.py). A run without ``out`` goes to a temporary
folder that is read into memory and removed before run_cli returns.
"""

import csv
import json
import os
import pathlib
import shutil
import subprocess
import tempfile

import numpy as np

__all__ = ["FolderResult", "load", "run_cli", "cli_path", "to_toml"]


def cli_path():
    """The geardyn executable: $GEARDYN_CLI, the one installed in this package (pip), the
    build tree beside this package (build/python/geardyn -> build/bin/geardyn), or `geardyn`
    on PATH."""
    override = os.environ.get("GEARDYN_CLI")
    if override:
        return override
    installed = pathlib.Path(__file__).resolve().parent / "geardyn-cli"
    if installed.exists():
        return str(installed)
    beside = pathlib.Path(__file__).resolve().parents[2] / "bin" / "geardyn"
    if beside.exists():
        return str(beside)
    found = shutil.which("geardyn")
    if found:
        return found
    raise FileNotFoundError("the geardyn executable: set GEARDYN_CLI or build the project")


def _toml_value(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        text = repr(float(value))
        return text if any(c in text for c in ".eEn") else text + ".0"
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string is a JSON string
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{json.dumps(str(k))} = {_toml_value(v)}" for k, v in value.items()) + " }"
    raise ValueError(f"{value!r}: cannot be written as a TOML value")


def to_toml(config):
    """A nested dict of configuration sections as TOML text (None values are left out).
    Tables whose keys contain dots (sweep parameters) are written with quoted keys."""
    lines = []

    def section(path, table):
        scalars = {k: v for k, v in table.items() if not isinstance(v, dict) or "." in k
                   or (isinstance(v, dict) and path.endswith("parameters"))}
        tables = {k: v for k, v in table.items() if k not in scalars}
        if path and scalars:
            lines.append(f"[{path}]")
        for k, v in scalars.items():
            if v is not None:
                key = json.dumps(k) if "." in k else k
                lines.append(f"{key} = {_toml_value(v)}")
        for k, v in tables.items():
            section(f"{path}.{k}" if path else k, v)

    section("", config)
    return "\n".join(lines) + "\n"


def _column_array(values):
    """Integers (a seed may exceed int64: uint64) stay integers; then floats; else text."""
    for dtype in (np.int64, np.uint64):
        try:
            return np.array([int(v) for v in values], dtype=dtype)
        except (ValueError, OverflowError):
            pass
    try:
        return np.array([float(v) for v in values])
    except ValueError:
        return np.array(values)


class FolderResult:
    """A finished command-line run: its summary (dict), results (dict) and tables (CSV files
    as {column: numpy array}). When the run went to a temporary folder, everything is read
    into memory and the folder is removed (``folder`` is then None)."""

    def __init__(self, folder, returncode, stdout, stderr, keep=True, summary=None):
        self.folder = pathlib.Path(folder)
        self.returncode = returncode
        self.stdout = stdout
        self.stderr = stderr
        summary_path = self.folder / "summary.json"
        if summary is None and summary_path.exists():
            summary = json.loads(summary_path.read_text())
        self.summary = summary or {}
        self.results = self.summary.get("results", {})
        self.status = self.summary.get("status")
        self.command = self.summary.get("command")
        self._tables = {}
        if not keep:
            for name in self.files:
                if name.endswith(".csv"):
                    self.table(name)
            self.folder = None

    @property
    def ok(self):
        """False when the numerical method failed (``status`` says how; the CLI's exit code 1)."""
        if "numerical_failure" in self.summary:
            return not self.summary["numerical_failure"]
        return self.returncode != 1  # a summary written before geardyn recorded it

    @property
    def warnings(self):
        return list(self.summary.get("warnings", []))

    @property
    def wall_time_s(self):
        return self.summary.get("wall_time_s")

    @property
    def headline(self):
        """{label [unit]: value} of the numbers geardyn.Result shows first."""
        from .results import headline_of

        return headline_of(self.command, self.results)

    @property
    def files(self):
        return self.summary.get("files", [])

    @property
    def tables(self):
        return [f[:-4] for f in self.files if f.endswith(".csv")]

    def table(self, name=None):
        """A CSV result file as {column: numpy array} (integer columns — case, seed, counts — as
        integer arrays, other numbers as float arrays, text as str)."""
        name = name or self.tables[0]
        name = name if name.endswith(".csv") else name + ".csv"
        if name not in self._tables:
            if self.folder is None:
                raise KeyError(f"no table {name!r}; the result has {', '.join(self.tables)}")
            with open(self.folder / name, newline="") as handle:
                rows = list(csv.DictReader(handle))
            columns = {}
            for column in (rows[0].keys() if rows else []):
                columns[column] = _column_array([r[column] for r in rows])
            self._tables[name] = columns
        return self._tables[name]

    def to_pandas(self, name=None):
        """A table as a DataFrame, ``.attrs["units"]`` as for geardyn.Result."""
        import pandas as pd

        from ._units import column_units, sweep_units

        name = (name or self.tables[0]).removesuffix(".csv")
        columns = self.table(name)
        frame = pd.DataFrame(columns)
        if self.command == "sweep" and name == "sweep":
            units = sweep_units(self.summary.get("config"), columns)
        else:  # as geardyn.Result's: text columns None, numbers their unit
            units = column_units(self, name, {c: (list(v) if v.dtype.kind in "USO" else v)
                                              for c, v in columns.items()})
        frame.attrs["units"] = units
        frame.attrs["table"] = name
        return frame

    def view3d(self):
        """A `train` result folder's 3-D view (geardyn.view3d) as a standalone HTML page, or None
        (not a train, no geometry, or read into memory without its folder)."""
        if self.command != "train" or "geometry" not in self.results or self.folder is None:
            return None
        from . import view3d

        return view3d.view_page(str(self.folder), self.summary)

    def _repr_html_(self):
        from .results import html_card

        return html_card(self)

    def __repr__(self):
        where = str(self.folder) if self.folder else "(in memory)"
        lines = [f"<geardyn {self.command} result: status {self.status}, folder {where}, "
                 f"tables {', '.join(self.tables) or '(none)'}>"]
        lines += [f"  {label}: {value:.6g}" for label, value in self.headline.items()]
        return "\n".join(lines)


def load(folder):
    """The result folder of an earlier run (`geardyn <command> --out FOLDER`, ``make demo``'s
    results/<example>, or ``Result.save``) as a FolderResult: ``summary``, ``results``,
    ``headline``, ``table``/``to_pandas`` (tables read on first use). Raises FileNotFoundError
    when ``folder`` holds no summary.json, ValueError when its summary.json is not a geardyn
    result."""
    folder = pathlib.Path(folder)
    summary = folder / "summary.json"
    if not summary.is_file():
        raise FileNotFoundError(f"{folder}: no summary.json here; a geardyn result folder is "
                                f"what `geardyn <command> --out FOLDER` writes")
    try:
        document = json.loads(summary.read_text())
    except json.JSONDecodeError as error:
        raise ValueError(f"{summary}: not JSON ({error})") from error
    if not isinstance(document, dict) or "command" not in document:
        raise ValueError(f"{summary}: not a geardyn summary (no \"command\" key)")
    return FolderResult(folder, 1 if document.get("numerical_failure") else 0, "", "",
                        summary=document)


def run_cli(command, config, out=None, overrides=None, threads=None, check=True, plots=None,
        resume=False, timeout=None, overwrite=False):
    """Runs the `geardyn COMMAND` executable on a configuration file or dict and returns a
    FolderResult (``geardyn.run`` uses it for `sweep` and `train`).

    - ``overrides``: {"section.key": value} or ["section.key=value", ...] (as --set).
    - ``out``: the result folder (default: a temporary folder, read into memory and removed).
    - ``plots``: True/False to force output.plots.
    - ``threads``: worker threads (default: all cores).
    - ``resume`` / ``overwrite`` (sweep): continue, or discard, the journal of a previous sweep
      in ``out``.
    Raises ValueError for bad input (exit code 2), RuntimeError for a numerical failure (exit
    code 1, unless check=False) and OSError for I/O errors (3)."""
    work = None
    if isinstance(config, dict):
        study = config.get("study")
        if isinstance(study, dict) and "base" in study and not os.path.isabs(str(study["base"])):
            # The file is written to a temporary folder: a relative base is relative to here.
            config = dict(config, study=dict(study, base=os.path.abspath(str(study["base"]))))
        work = tempfile.mkdtemp(prefix="geardyn-")
        path = pathlib.Path(work) / "config.toml"
        path.write_text(to_toml(config))
    else:
        path = pathlib.Path(config)
    keep = out is not None
    if out is None:
        out = tempfile.mkdtemp(prefix=f"geardyn-{command}-")
    args = [cli_path(), command, str(path), "--out", str(out), "--quiet"]
    sets = []
    if isinstance(overrides, dict):
        sets = [f"{k}={_toml_value(v)}" for k, v in overrides.items()]
    elif overrides:
        sets = list(overrides)
    if plots is not None:
        sets.append(f"output.plots={'true' if plots else 'false'}")
    for s in sets:
        args += ["--set", s]
    if threads:
        args += ["--threads", str(int(threads))]
    if resume:
        args.append("--resume")
    if overwrite:
        args.append("--overwrite")
    try:
        done = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
        result = FolderResult(out, done.returncode, done.stdout, done.stderr, keep=keep)
    finally:
        if work:
            shutil.rmtree(work, ignore_errors=True)
        if not keep:
            shutil.rmtree(out, ignore_errors=True)
    message = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ""
    if done.returncode == 2:
        from ._geardyn import ConfigError

        raise ConfigError(message or f"geardyn {command}: bad input")
    if done.returncode in (3,):
        raise OSError(message)
    if done.returncode == 4:
        raise RuntimeError(message)
    if done.returncode == 1 and check:
        error = RuntimeError(f"geardyn {command}: {result.status}: {message}")
        error.result = result
        raise error
    return result
