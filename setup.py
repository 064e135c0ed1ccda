"""Builds geardyn's compiled parts with CMake for `pip install .` and `python3 -m build`.

The extension `geardyn._geardyn`, the optional HDF5 module it loads on demand and the `geardyn`
executable (for `geardyn.sweep` and `train`) are built by the project's CMake build (Release,
ccache when installed, no tests) in the setuptools build folder and copied into the package.
Environment: GEARDYN_CMAKE_BUILD_DIR reuses a build folder; GEARDYN_BUILD_JOBS sets -j (2).
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


class CMakeBuild(build_ext):
    def build_extension(self, ext):
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
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        target.parent.mkdir(parents=True, exist_ok=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        shutil.copy2(build / "python" / "geardyn" / f"_geardyn{suffix}", target)
        # Beside the extension: the modules it loads on demand and the executable.
        for module in (build / "lib").glob("libgeardyn_*.so"):
            shutil.copy2(module, target.parent / module.name)
        shutil.copy2(build / "bin" / "geardyn", target.parent / "geardyn-cli")


setup(
    version=version(),
    ext_modules=[Extension("geardyn._geardyn", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
