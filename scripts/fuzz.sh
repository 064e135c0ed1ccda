#!/usr/bin/env bash
# Build the libFuzzer targets with clang (+ ASan/UBSan) and fuzz the configuration loaders.
#   scripts/fuzz.sh [SECONDS] [TARGET]   default 300 s each; TARGET config | stiffness_config |
#                                        dynamics_config | probe_record (WAV/CSV readers)
#   (default: all). Corpora in fuzz-corpus/<target>/ (git-ignored), seeded with the examples.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
seconds="${1:-300}"
targets=("${2:-config}")
[ -n "${2:-}" ] || targets=(config stiffness_config dynamics_config probe_record)
bash scripts/setup.sh --deps
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGEARDYN_BUILD_FUZZERS=ON -DGEARDYN_BUILD_TESTS=OFF -DGEARDYN_BUILD_PYTHON=OFF >/dev/null
for target in "${targets[@]}"; do
  cmake --build build-fuzz --target "geardyn_${target}_fuzzer"
  mkdir -p "fuzz-corpus/$target"
  options=(-dict=fuzz/geometry_config.dict -max_len=4096)
  if [ "$target" = probe_record ]; then
    # Seeds: a small WAV (first byte 0: .wav) and CSV (1: .csv) record with a keyphasor.
    /usr/bin/python3 fuzz/probe_record_seeds.py "fuzz-corpus/$target"
    options=(-max_len=16384)
  else
    cp -n examples/*.toml "fuzz-corpus/$target/" 2>/dev/null || true
  fi
  echo "== fuzzing $target for $seconds s"
  "build-fuzz/bin/geardyn_${target}_fuzzer" "fuzz-corpus/$target" "${options[@]}" \
    -max_total_time="$seconds" -print_final_stats=1 2>&1 | tail -n 8
done
