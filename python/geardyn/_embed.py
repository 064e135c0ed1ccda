"""JavaScript libraries embedded in geardyn's HTML pages, gzip-compressed and base64-encoded
(a third of their size: plotly.js is 4.8 MB as text, 2.0 MB so), and the loader that unpacks
them in the browser (``embed_loader.js``, with the standard DecompressionStream; no network).

three.js (MIT; the npm package ``three``, installed by ``scripts/setup.sh`` into ``.cache/npm``)
is looked for, first found wins, in ``$GEARDYN_THREE_DIR`` (a folder holding ``build/`` and
``examples/`` as the npm package does), the package's own ``_assets/three``, then
``.cache/npm/node_modules/three`` in a parent of this file or of the working directory.
"""

import base64
import functools
import gzip
import os
import pathlib

_HERE = pathlib.Path(__file__).resolve().parent
# (element id, file in the npm package): the core, the renderer module that imports it, and
# the orbit controls that import both as 'three'.
THREE_FILES = (("gd-lib-three-core", "build/three.core.min.js"),
               ("gd-lib-three-module", "build/three.module.min.js"),
               ("gd-lib-three-orbit", "examples/jsm/controls/OrbitControls.js"))


def first_found(what, variable, relative, usable, install, extra=()):
    """The first usable path among: $`variable`; the package's own ``_assets`` copy;
    ``.cache/npm/node_modules/<relative>`` in a parent of this file or of the working directory;
    then `extra`. FileNotFoundError naming the places tried and `install` when none is usable."""
    tried = [pathlib.Path(os.environ[variable])] if os.environ.get(variable) else []
    tried.append(_HERE / "_assets" / pathlib.Path(relative).name)
    npm = pathlib.Path(".cache/npm/node_modules") / relative
    for start in (_HERE, pathlib.Path.cwd().resolve()):
        tried += [parent / npm for parent in start.parents] + [start / npm]
    tried += list(extra)
    for path in tried:
        if usable(path):
            return path
    raise FileNotFoundError(
        f"{what} not found (looked in ${variable}, "
        + ", ".join(dict.fromkeys(str(p) for p in tried[:4])) + f", ...); {install}")


def find_three_dir():
    """The folder of the npm package three (see the module doc for the search order)."""
    return first_found("three.js", "GEARDYN_THREE_DIR", "three",
                       lambda path: all((path / name).is_file() for _, name in THREE_FILES),
                       "install it with `bash scripts/setup.sh --deps` (npm package three into "
                       ".cache/npm) or set GEARDYN_THREE_DIR to a copy of the npm package")


def packed(element_id, text):
    """A <script> element holding `text` gzip-compressed and base64-encoded (the loader's
    gdLib.text(element_id) gives it back)."""
    data = base64.b64encode(gzip.compress(text.encode("utf-8"), compresslevel=9, mtime=0))
    return f"<script type=\"application/gzip-base64\" id=\"{element_id}\">{data.decode('ascii')}</script>"


@functools.lru_cache(maxsize=4)
def packed_text(element_id, text):
    """packed(), remembered for the last few texts (a report packs the same plotly.js)."""
    return packed(element_id, text)


@functools.lru_cache(maxsize=4)
def _packed_file(element_id, path):
    return packed(element_id, pathlib.Path(path).read_text(encoding="utf-8"))


def library_scripts(names):
    """The packed script elements of the libraries `names` ("three")."""
    parts = []
    if "three" in names:
        folder = find_three_dir()
        parts += [_packed_file(element_id, str(folder / name)) for element_id, name in THREE_FILES]
    return "".join(parts)


def packed_file(element_id, path):
    """The packed script element of the file at `path` (cached per file)."""
    return _packed_file(element_id, str(path))


def loader_js():
    """The loader (window.gdLib: text, classic, three), a classic script."""
    return (_HERE / "embed_loader.js").read_text(encoding="utf-8")
