"""Builds geardyn's compiled parts with CMake for `pip install .` and `python3 -m build`.

The extension `geardyn._geardyn`, the optional HDF5 module it loads on demand and the `geardyn`
executable (for `geardyn.sweep` and `train`) are built by the project's CMake build (Release,
ccache when installed, no tests) in the setuptools build folder and copied into the package.
Environment: GEARDYN_CMAKE_BUILD_DIR reuses a build folder; GEARDYN_BUILD_JOBS sets -j (2);
GEARDYN_PREBUILT_DIR names a CMake build folder of this same version whose `_geardyn` and
`geardyn_cli` targets are built already: they are packaged as they are, with no compilation (the
packaging test in the default suite packages the project's own build this way instead of
compiling everything a second time).
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(geardyn VERSION ([0-9.]+)", text).group(1)


def prebuilt_folder(folder):
    """A finished build folder of this version, or SystemExit saying what is missing."""
    build = pathlib.Path(folder).resolve()
    cache = build / "CMakeCache.txt"
    if not cache.exists():
        raise SystemExit(f"GEARDYN_PREBUILT_DIR={folder}: no CMakeCache.txt there (not a build folder)")
    built = re.search(r"^CMAKE_PROJECT_VERSION:STATIC=([0-9.]+)$", cache.read_text(), re.M)
    if not built or built.group(1) != version():
        raise SystemExit(f"GEARDYN_PREBUILT_DIR={folder}: built version "
                         f"{built.group(1) if built else '?'}, the source is {version()}")
    return build


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if os.environ.get("GEARDYN_PREBUILT_DIR"):
            self.copy_artefacts(prebuilt_folder(os.environ["GEARDYN_PREBUILT_DIR"]), ext)
            return
        build = pathlib.Path(os.environ.get("GEARDYN_CMAKE_BUILD_DIR") or
                             pathlib.Path(self.build_temp).resolve() / "cmake")
        build.mkdir(parents=True, exist_ok=True)
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DGEARDYN_BUILD_TESTS=OFF", "-DGEARDYN_BUILD_BENCHMARKS=OFF",
                     f"-DPython3_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True)
        jobs = os.environ.get("GEARDYN_BUILD_JOBS", "2")
        subprocess.run(["cmake", "--build", str(build), "-j", jobs, "--target", "_geardyn",
                       "geardyn_cli"], check=True)
        self.copy_artefacts(build, ext)

    def copy_artefacts(self, build, ext):
        """Copies the extension, its on-demand modules and the executable out of `build`."""
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        extension = build / "python" / "geardyn" / f"_geardyn{suffix}"
        executable = build / "bin" / "geardyn"
        for needed in (extension, executable):
            if not needed.exists():
                raise SystemExit(f"{needed} is missing: build the _geardyn and geardyn_cli targets")
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(extension, target)
        # Beside the extension: the modules it loads on demand and the executable.
        for module in (build / "lib").glob("libgeardyn_*.so"):
            shutil.copy2(module, target.parent / module.name)
        shutil.copy2(executable, target.parent / "geardyn-cli")


setup(
    version=version(),
    ext_modules=[Extension("geardyn._geardyn", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
