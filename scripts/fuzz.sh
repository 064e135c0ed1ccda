#!/usr/bin/env bash
# Build the libFuzzer targets with clang (+ ASan/UBSan) and fuzz the configuration loaders.
#   scripts/fuzz.sh [SECONDS] [TARGET]   each target runs 10^6 inputs or SECONDS (default 1800),
#                                        whichever comes first; TARGET config | stiffness_config |
#                                        dynamics_config | probe_record (WAV/CSV readers) | rexs
#                                        (REXS XML, JSON and zip) | gearbox (gearbox TOML)
#   (default: all). Corpora in fuzz-corpus/<target>/ (git-ignored), seeded with the examples,
#   the gearbox files and the REXS models of ../shared/rexs where present. A crash, a time-out
#   (-timeout=10 s an input) or running out of memory (-rss_limit_mb=2048) fails the script.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
seconds="${1:-1800}"
targets=("${2:-config}")
[ -n "${2:-}" ] || targets=(config stiffness_config dynamics_config probe_record rexs gearbox)
bash scripts/setup.sh --deps
# clang brings libFuzzer; only the fuzzing needs it, so it is installed here, not by setup.sh.
if ! command -v clang++ >/dev/null 2>&1; then
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    clang >/dev/null
fi
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGEARDYN_BUILD_FUZZERS=ON -DGEARDYN_BUILD_TESTS=OFF -DGEARDYN_BUILD_PYTHON=OFF >/dev/null
for target in "${targets[@]}"; do
  cmake --build build-fuzz --target "geardyn_${target}_fuzzer"
  mkdir -p "fuzz-corpus/$target"
  options=(-dict=fuzz/geometry_config.dict -max_len=4096)
  if [ "$target" = rexs ]; then
    /usr/bin/python3 fuzz/rexs_seeds.py "fuzz-corpus/$target" ../shared/rexs
    options=(-max_len=65536)
  elif [ "$target" = gearbox ]; then
    cp -n examples/gearboxes/*.toml "fuzz-corpus/$target/" 2>/dev/null || true
    options=(-max_len=8192)
  elif [ "$target" = probe_record ]; then
    # Seeds: a small WAV (first byte 0: .wav) and CSV (1: .csv) record with a keyphasor.
    /usr/bin/python3 fuzz/probe_record_seeds.py "fuzz-corpus/$target"
    options=(-max_len=16384)
  else
    cp -n examples/*.toml "fuzz-corpus/$target/" 2>/dev/null || true
  fi
  echo "== fuzzing $target: 10^6 inputs or $seconds s"
  "build-fuzz/bin/geardyn_${target}_fuzzer" "fuzz-corpus/$target" "${options[@]}" \
    -runs=1000000 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 2>&1 | tail -n 8
done
