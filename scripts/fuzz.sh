#!/usr/bin/env bash
# Build the libFuzzer targets with clang (+ ASan/UBSan) and fuzz the configuration loaders.
#   scripts/fuzz.sh [SECONDS] [TARGET]   default 300 s each; TARGET config | stiffness_config |
#                                        dynamics_config
#   (default: both). Corpora in fuzz-corpus/<target>/ (git-ignored), seeded with the examples.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
seconds="${1:-300}"
targets=("${2:-config}")
[ -n "${2:-}" ] || targets=(config stiffness_config dynamics_config)
bash scripts/setup.sh --deps
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGEARDYN_BUILD_FUZZERS=ON -DGEARDYN_BUILD_TESTS=OFF -DGEARDYN_BUILD_PYTHON=OFF >/dev/null
for target in "${targets[@]}"; do
  cmake --build build-fuzz --target "geardyn_${target}_fuzzer"
  mkdir -p "fuzz-corpus/$target"
  cp -n examples/*.toml "fuzz-corpus/$target/" 2>/dev/null || true
  echo "== fuzzing $target for $seconds s"
  "build-fuzz/bin/geardyn_${target}_fuzzer" "fuzz-corpus/$target" -dict=fuzz/geometry_config.dict \
    -max_total_time="$seconds" -max_len=4096 -print_final_stats=1 2>&1 | tail -n 8
done
