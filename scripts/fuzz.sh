#!/usr/bin/env bash
# Build the libFuzzer targets with clang (+ ASan/UBSan) and fuzz the configuration loader.
#   scripts/fuzz.sh [SECONDS]     default 300 s; corpus kept in fuzz-corpus/ (git-ignored)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
seconds="${1:-300}"
bash scripts/setup.sh --deps
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGEARDYN_BUILD_FUZZERS=ON -DGEARDYN_BUILD_TESTS=OFF -DGEARDYN_BUILD_PYTHON=OFF >/dev/null
cmake --build build-fuzz --target geardyn_config_fuzzer
mkdir -p fuzz-corpus/config
cp -n examples/*.toml fuzz-corpus/config/ 2>/dev/null || true
build-fuzz/bin/geardyn_config_fuzzer fuzz-corpus/config -dict=fuzz/geometry_config.dict \
  -max_total_time="$seconds" -max_len=4096 -print_final_stats=1 2>&1 | tail -n 25
