"""Every analysis from Python, in-process: ``geardyn.run(command, config, **sections)``.

``config`` is a TOML file, a nested dict of configuration sections, or nothing; keyword
arguments add sections (a dict, or a geardyn object such as ``geardyn.Gear`` for [pinion] and
[gear]). The keys are those of the files (``geardyn.config_reference(command)``). The analysis
runs in this process, in the compiled library, without the GIL, with a progress bar on long
runs (tqdm when importable, else stderr) and Ctrl-C; nothing is written unless ``out`` is
given; a dict's relative ``gearbox.file`` is relative to the working directory. ``sweep``
goes through the ``geardyn`` executable (geardyn._cli), into a temporary folder that is
removed.

Bad input raises geardyn.ConfigError (a ValueError with .key, .value, .allowed); a file that
cannot be read raises OSError; a numerical failure raises RuntimeError with the result attached
(``error.result``) unless ``check=False``.

>>> import geardyn
>>> r = geardyn.run("stiffness", "examples/stiffness_visnadi2021_spur.toml",
...                 overrides={"mesh_stiffness.models": ["api"]})         # doctest: +SKIP
>>> r.to_pandas().columns[:2].tolist()                                      # doctest: +SKIP
['mesh_phase', 'roll_angle_rad']
"""

import difflib
import os
import sys
import time
import warnings

from . import _geardyn
from ._cli import _toml_value, run_cli, to_toml
from .results import Result
from .train import GearTrain

__all__ = ["run", "sweep", "COMMANDS"]

#: Commands ``run`` knows: the in-process analyses (train among them), then the executable's
#: sweep.
COMMANDS = tuple(_geardyn.analysis_names()) + ("sweep",)

# Keys of a [pinion] / [gear] section, read from a geardyn.Gear given as a keyword argument.
_GEAR_KEYS = ("teeth", "module", "face_width", "pressure_angle_deg", "helix_angle_deg",
              "profile_shift", "addendum_coefficient", "dedendum_coefficient",
              "root_fillet_coefficient", "tip_radius_modification", "bore_diameter",
              "youngs_modulus", "poisson_ratio", "density")


def _section(name, value):
    """A configuration section from a keyword argument: a dict, or a geardyn object."""
    if isinstance(value, dict):
        return value
    if isinstance(value, _geardyn.Gear):
        return {k: getattr(value, k) for k in _GEAR_KEYS if hasattr(value, k)}
    raise TypeError(f"{name}=: a configuration section is a dict (or a geardyn.Gear), "
                    f"not {type(value).__name__}")


def _merge(base, extra):
    out = dict(base)
    for key, value in extra.items():
        out[key] = _merge(out[key], value) if isinstance(out.get(key), dict) and isinstance(
            value, dict) else value
    return out


def _command(command):
    if command in COMMANDS:
        return command
    close = difflib.get_close_matches(str(command), COMMANDS, n=1, cutoff=0.5)
    hint = f"; did you mean {close[0]!r}?" if close else ""
    raise _geardyn.ConfigError(f"command = {command!r}: must be one of "
                               f"{', '.join(COMMANDS)}{hint}")


class _Progress:
    """The progress of a running analysis: a tqdm bar when tqdm is importable, else a line
    on stderr; nothing for runs shorter than ``after`` seconds."""

    def __init__(self, after=2.0):
        self.after = after
        self.start = time.monotonic()
        self.label = None
        self.bar = None
        self.last_line = 0.0

    def __call__(self, label, unit, done, total):
        if time.monotonic() - self.start < self.after:
            return
        if label != self.label:
            self.close()
            self.label = label
            try:
                from tqdm.auto import tqdm

                self.bar = tqdm(total=total, desc=label, unit=unit.split(" ")[0] or "it",
                                leave=False)
            except ImportError:
                self.bar = None
        if self.bar is not None:
            self.bar.total = total
            self.bar.n = done
            self.bar.refresh()
        elif time.monotonic() - self.last_line >= 1.0 or done >= total:
            self.last_line = time.monotonic()
            print(f"{label}: {100 * done / total:.0f} % ({done:.6g}/{total:.6g} {unit})",
                  file=sys.stderr, flush=True)

    def close(self):
        if self.bar is not None:
            self.bar.close()
            self.bar = None


def _overrides(overrides):
    if isinstance(overrides, dict):
        return [f"{k}={_toml_value(v)}" for k, v in overrides.items()]
    return list(overrides or [])


def run(command, config=None, *, out=None, overrides=None, threads=None, check=True, plots=None,
        progress=True, resume=False, timeout=None, overwrite=False, **sections):
    """Runs analysis ``command`` and returns a geardyn.Result (sweep: FolderResult).

    - ``config``: a TOML file (str or path), a dict of sections, or None; for ``train`` also a
      geardyn.GearTrain (its built model, analysed without reading the gearbox again).
    - ``**sections``: sections added to (or merged into) ``config``, e.g.
      ``pinion=geardyn.Gear(...)``, ``excitation={"speed_rpm": 1500}``.
    - ``overrides``: {"section.key": value} or ["section.key=value"] (as the CLI's --set).
    - ``out``: also write the CLI's result folder there (with plots when ``plots``).
    - ``threads``: worker threads (default: all cores).
    - ``progress``: False for no progress display.
    """
    command = _command(command)
    # A GearTrain built before: `train` on its model, without reading or building it again.
    if command == "train" and isinstance(config, GearTrain):
        if sections or overrides:
            raise TypeError("run('train', GearTrain): change keys with GearTrain.set(key, value)")
        return _finish(config.run(), command, out, plots, check)
    # In-process: every analysis; through the executable: `sweep` (a study of many runs).
    if command == "sweep":
        if sections:
            config = _merge(config or {}, {k: _section(k, v) for k, v in sections.items()})
        return run_cli(command, config, out=out, overrides=overrides, threads=threads,
                       check=check, plots=plots, resume=resume, timeout=timeout,
                       overwrite=overwrite)
    path, text, model_type = "", "", ""
    if isinstance(config, (str, os.PathLike)) and not sections:
        path = os.fspath(config)
        with open(path, "rb"):  # OSError (FileNotFoundError, PermissionError) as Python has it
            pass
    else:
        if isinstance(config, (str, os.PathLike)):
            raise TypeError("sections as keyword arguments go with a dict config, not a file: "
                            "use overrides={'section.key': value} with a file")
        document = _merge(config or {}, {k: _section(k, v) for k, v in sections.items()})
        model_type = str((document.get("model") or {}).get("type", ""))
        text = to_toml(document)
    display = _Progress() if progress else None
    shown = set()  # each text once: a note raised while loading may be in result.warnings too

    def warn_once(text, stacklevel):
        if text not in shown:
            shown.add(text)
            warnings.warn(text, stacklevel=stacklevel + 1)

    try:
        native = _geardyn.analyze(command, path=path, text=text, model_type=model_type,
                                  overrides=_overrides(overrides), threads=int(threads or 0),
                                  progress=display, warn=lambda note: warn_once(note, 3))
    finally:
        if display is not None:
            display.close()
    return _finish(Result(native), command, out, plots, check, shown)


def _finish(result, command, out, plots, check, shown=None):
    """Warnings (one line per kind, as the CLI, each text once: ``shown`` holds those raised
    while loading), the result folder when ``out``, RuntimeError on a numerical failure."""
    shown = set() if shown is None else shown
    for warning in _geardyn.grouped_warnings(result.warnings):
        if warning not in shown:
            shown.add(warning)
            warnings.warn(warning, stacklevel=3)
    if out is not None:
        if plots is None:
            plots = bool((result.summary.get("config", {}).get("output") or {}).get("plots"))
        result.plot(out) if plots else result.save(out)
    if not result.ok and check:
        error = RuntimeError(f"geardyn {command}: {result.status}: "
                             f"{'; '.join(result.errors) or 'numerical failure'}")
        error.result = result
        raise error
    return result


def sweep(study, out=None, threads=None, resume=False, check=True, plots=None, overwrite=False):
    """`geardyn sweep`: ``study`` is a sweep file or a dict {"study": {...}} (see
    docs/config/sweep.md); returns a FolderResult whose ``table("sweep")`` has one row per
    case (read into memory; without ``out`` the temporary folder is removed)."""
    return run_cli("sweep", study, out=out, threads=threads, resume=resume, check=check,
                   plots=plots, overwrite=overwrite)
