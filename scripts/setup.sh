#!/usr/bin/env bash
# geardyn setup: install the Debian packages the project needs (idempotent: only what is missing,
# `apt-get update` only when something is missing), then configure and build in Release.
#
#   scripts/setup.sh            packages + configure + build (build/)
#   scripts/setup.sh --deps     packages only
#
# Environment: BUILD_DIR (default build), BUILD_TYPE (default Release), GEARDYN_CMAKE_ARGS (extra),
# BUILD_TARGETS (default: all; `make demo` builds only geardyn_demo_programs, the CLI and the
# Python module, and leaves the test binaries to `make test`).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

# One list, so that the README, CI and developers agree on what geardyn needs.
packages=(
  build-essential cmake ninja-build pkg-config git
  ccache  # recompiles only what changed, across clones side by side (base_dir below)
  libeigen3-dev libspectra-dev libfftw3-dev libboost-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libfmt-dev libhdf5-dev
  libpugixml-dev libminizip-dev zlib1g-dev  # REXS import: XML, zipped .rexsz
  libgtest-dev libgmock-dev libbenchmark-dev
  pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pytest python3-h5py
  python3-scipy  # bench/rotor_scipy_compare.py only
  python3-pandas python3-tqdm  # Python results as DataFrames, progress bars
  python3-setuptools python3-wheel python3-pip python3-venv python3-build python3-pybind11  # pip install .
  python3-nbconvert python3-ipykernel jupyter-nbconvert  # example notebooks in the tests
  libopenmpi-dev openmpi-bin  # mpirun -n N geardyn sweep
  chromium chromium-driver python3-selenium  # the HTML report's test in headless Chromium
  calculix-ccx gmsh python3-gmsh  # [housing]: ccx assembles K, M of the user's deck; gmsh meshes the example's box
  libsuitesparse-dev  # [housing]: CHOLMOD's supernodal Cholesky (METIS ordering) of the housing's K_oo
)
# npm fetches plotly.js for `geardyn report`; Debian's npm only if no npm is on PATH (a NodeSource
# nodejs brings its own and conflicts with Debian's).
command -v npm >/dev/null 2>&1 || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} Debian package(s): ${missing[*]}" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: all ${#packages[@]} Debian packages present" >&2
fi

# plotly.js (MIT) and three.js (MIT) for the self-contained HTML report, from npm into a
# project-local folder that is never committed (.cache/ is ignored); python/geardyn/report.py and
# _embed.py find them there and embed them compressed. plotly.js is its cartesian bundle (the
# scatter, bar and heatmap traces the report draws; 1.3 MB, the full bundle is 4.8 MB and takes
# three times as long to start in the browser). three.js is a pinned release that still ships
# minified ES modules (build/three.core.min.js, build/three.module.min.js); Debian's libjs-three
# is r111 (2019), before the module layout the view loads. One npm call installs both: an install
# without a package.json drops the packages it was not given.
plotly_version=4.1.1
plotly_js=".cache/npm/node_modules/plotly.js-cartesian-dist-min/plotly-cartesian.min.js"
three_version=0.179.1
three_dir=".cache/npm/node_modules/three"
if ! grep -qs "\"version\": \"$plotly_version\"" "$(dirname "$plotly_js")/package.json" ||
   [ ! -f "$plotly_js" ] ||
   ! grep -qs "\"version\": \"$three_version\"" "$three_dir/package.json" ||
   [ ! -f "$three_dir/build/three.module.min.js" ]; then
  echo "setup: installing plotly.js-cartesian-dist-min@$plotly_version and three@$three_version (npm) into .cache/npm" >&2
  mkdir -p .cache/npm
  npm install --prefix .cache/npm --no-save --no-audit --no-fund --no-package-lock --silent \
    "plotly.js-cartesian-dist-min@$plotly_version" "three@$three_version" >/dev/null
fi

[ "${1:-}" = "--deps" ] && exit 0

build_dir="${BUILD_DIR:-build}"
build_type="${BUILD_TYPE:-Release}"
generator=()
[ -f "$build_dir/CMakeCache.txt" ] || generator=(-G Ninja)
# Debian's interpreter is pinned: the first python3 on PATH may lack numpy/pytest.
# ccache with base_dir = the clone's parent folder: a second clone beside this one (the packaging
# test's, a developer's worktree) finds this build's objects under its own paths.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=("-DCMAKE_CXX_COMPILER_LAUNCHER=/usr/bin/env;CCACHE_BASEDIR=$(dirname "$here");ccache"
            "-DCMAKE_C_COMPILER_LAUNCHER=/usr/bin/env;CCACHE_BASEDIR=$(dirname "$here");ccache")
fi
cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE="$build_type" "${launcher[@]}" \
  -DPython3_EXECUTABLE=/usr/bin/python3 ${GEARDYN_CMAKE_ARGS:-} >/dev/null
targets=()
[ -z "${BUILD_TARGETS:-}" ] || targets=(--target ${BUILD_TARGETS})
cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}"
