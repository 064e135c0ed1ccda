"""pip-installability (issue 19, item 4): a clean `git clone` of the source, a fresh virtual
environment with Debian's site packages, `pip install --no-build-isolation --no-index .`
(offline: setuptools, pybind11-dev, cmake from Debian), then the README's Python one-liners run
from /tmp with the installed package, `import geardyn` from any folder, the stubs installed,
and a wheel built with `python3 -m build --no-isolation --wheel`.

Usage: pip_install_test.py --source DIR --work DIR [--prebuilt BUILD] [--no-wheel]
With --prebuilt (the default suite, issue 34) the package and the wheel take the extension and
the executable of the project's own build folder BUILD (setup.py's GEARDYN_PREBUILT_DIR): nothing
is compiled a second time, so the test takes seconds on a busy machine too. Without it (label
`long`) the clone is compiled from source in WORK/clone/build, through ccache with base_dir the
source's parent folder when ccache is installed, so that the project's own objects serve it.
"""

import argparse
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile


def run(args, **kwargs):
    print("+", " ".join(str(a) for a in args), flush=True)
    return subprocess.run([str(a) for a in args], check=True, **kwargs)


def readme_one_liners(readme):
    """The `python3 -c "..."` lines of the README's shell blocks."""
    lines = []
    for line in readme.read_text().splitlines():
        if re.match(r"^(/usr/bin/)?python3 -c ", line.strip()):
            lines.append(line.strip())
    return lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source", required=True, type=pathlib.Path)
    parser.add_argument("--work", required=True, type=pathlib.Path)
    parser.add_argument("--prebuilt", type=pathlib.Path,
                        help="package this build folder's artefacts instead of compiling")
    parser.add_argument("--no-wheel", action="store_true")
    options = parser.parse_args()
    start = time.monotonic()
    work = options.work.resolve()
    shutil.rmtree(work / "clone", ignore_errors=True)
    shutil.rmtree(work / "venv", ignore_errors=True)
    shutil.rmtree(work / "dist", ignore_errors=True)
    work.mkdir(parents=True, exist_ok=True)
    clone = work / "clone"
    run(["git", "clone", "--quiet", options.source, clone])
    run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", work / "venv"])
    python = work / "venv" / "bin" / "python"
    env = dict(os.environ, GEARDYN_CMAKE_BUILD_DIR=str(clone / "build"), PIP_NO_INDEX="1")
    if options.prebuilt:
        env["GEARDYN_PREBUILT_DIR"] = str(options.prebuilt.resolve())
    else:
        env.setdefault("CCACHE_BASEDIR", str(options.source.resolve().parent))
    env.pop("PYTHONPATH", None)
    env.pop("GEARDYN_CLI", None)
    run([python, "-m", "pip", "install", "--quiet", "--no-build-isolation", "--no-index", "."],
        cwd=clone, env=env)
    print(f"installed in {time.monotonic() - start:.0f} s", flush=True)

    # The installed package, from another folder: not the build tree, with its stubs.
    with tempfile.TemporaryDirectory(prefix="geardyn-pip-") as elsewhere:
        where = subprocess.run(
            [python, "-c", "import geardyn, pathlib; p = pathlib.Path(geardyn.__file__).parent; "
             "print(p); assert (p / '_geardyn.pyi').exists() and (p / 'py.typed').exists(); "
             "assert (p / 'geardyn-cli').exists()"],
            cwd=elsewhere, env=env, check=True, capture_output=True, text=True).stdout.strip()
    assert str(work / "venv") in where, f"imported from {where}, not the virtual environment"

    # The README's one-liners, run from /tmp with the environment's python.
    venv_bin = str(work / "venv" / "bin")
    one_liners = readme_one_liners(clone / "README.md")
    assert len(one_liners) >= 2, "the README has no python3 -c one-liners"
    before = set(os.listdir("/tmp"))
    for line in one_liners:
        args = shlex.split(line)
        args[0] = str(python)
        done = subprocess.run(args, cwd="/tmp", env=dict(env, PATH=venv_bin + ":" + env["PATH"]),
                              capture_output=True, text=True)
        print(line, "->", done.stdout.strip()[:200], flush=True)
        assert done.returncode == 0, done.stderr
    left = {e for e in set(os.listdir("/tmp")) - before if e.startswith("geardyn")}
    assert not left, f"the one-liners left {left} in /tmp"

    if not options.no_wheel:
        run(["/usr/bin/python3", "-m", "build", "--no-isolation", "--wheel", "--outdir",
             work / "dist", clone], env=env, stdout=subprocess.DEVNULL)
        wheels = list((work / "dist").glob("geardyn-*.whl"))
        assert len(wheels) == 1, wheels
        names = zipfile.ZipFile(wheels[0]).namelist()
        for needed in ("geardyn/_geardyn.pyi", "geardyn/py.typed", "geardyn/__init__.py"):
            assert needed in names, f"{needed} missing from {wheels[0].name}"
        assert any(re.match(r"geardyn/_geardyn\..*\.so$", n) for n in names), names
        print(f"wheel {wheels[0].name}: {len(names)} files", flush=True)
    shutil.rmtree(work / "venv", ignore_errors=True)
    print(f"pip install test passed in {time.monotonic() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
