"""What the plotting modules share: the non-interactive matplotlib backend, a figure or the
caller's axes, atomic PNG writing and the readers of result tables."""

import os
import pathlib
import tempfile

import matplotlib

if not os.environ.get("MPLBACKEND"):
    matplotlib.use("Agg")  # no display unless the caller chose a backend (Jupyter does)
import matplotlib.pyplot as plt  # noqa: E402

from ._tables import _long_table, _read_columns, read_summary as _read_summary  # noqa: E402,F401


def _axes(ax, figsize):
    """The caller's axes and its figure, or a new figure (constrained layout, so that legends
    placed outside the axes stay inside the image) with one axes."""
    if ax is not None:
        return ax.figure, ax
    figure, ax = plt.subplots(figsize=figsize, layout="constrained")
    return figure, ax


def _save_atomically(figure, path, close=False):
    """Writes `figure` as PNG to `path` through a temporary file in the same folder."""
    path = pathlib.Path(path)
    handle, temporary = tempfile.mkstemp(prefix="." + path.name + ".tmp-", dir=path.parent)
    os.close(handle)
    try:
        figure.savefig(temporary, format="png", dpi=130)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)  # mkstemp makes 0600; results are ordinary files
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
    if close:
        plt.close(figure)
    return path


def finish(figures, folder, save):
    """{name: Figure} as given; with `save`, each is also written to FOLDER/name."""
    if save:
        for name, figure in figures.items():
            _save_atomically(figure, pathlib.Path(folder) / name)
    return figures
