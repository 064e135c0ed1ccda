#!/usr/bin/env bash
# Whole-process time of short geardyn runs (issue 22): start-up dominates them, so scripts,
# Python wrappers and job arrays that call the CLI thousands of times pay it every time.
#   bench/startup_bench.sh [build/bin/geardyn] [REPEATS]
# Median (and min) of REPEATS runs (default 20) of each command, measured from bash with
# $EPOCHREALTIME around the process (no clock process forked in between); /bin/true gives the
# cost of starting any process here.
# Also prints the shared libraries each kind of run maps and the dynamic loader's relocation
# statistics (LD_DEBUG=statistics).
set -euo pipefail
cli="${1:-build/bin/geardyn}"
repeats="${2:-20}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Median and minimum in ms of `repeats` runs of a command (output discarded).
measure() {
  local label="$1"
  shift
  local times=() s e
  "$@" >/dev/null 2>&1 || { echo "$label: the command failed: $*" >&2; exit 1; }  # warm-up
  for ((i = 0; i < repeats; i++)); do
    s=${EPOCHREALTIME/[.,]/}
    "$@" >/dev/null 2>&1
    e=${EPOCHREALTIME/[.,]/}
    times+=($((e - s)))  # [µs]
  done
  printf '%s\n' "${times[@]}" | sort -n | awk -v label="$label" -v n="$repeats" '
    { t[NR] = $1 }
    END {
      median = (n % 2) ? t[(n + 1) / 2] : (t[n / 2] + t[n / 2 + 1]) / 2
      printf "%-34s median %7.2f ms   min %7.2f ms\n", label, median / 1e3, t[1] / 1e3
    }'
}

quiet=(--quiet --set output.plots=false)
echo "geardyn start-up, whole process, $repeats runs each ($(nproc) cores, $(uname -r))"
measure "/bin/true" /bin/true
measure "geardyn --version" "$cli" --version
measure "geardyn geometry (rig example)" "$cli" geometry \
  "$here/examples/geometry_rao2023_rig.toml" --out "$work/geometry" "${quiet[@]}"
measure "geardyn stiffness (1000 positions)" "$cli" stiffness \
  "$here/examples/stiffness_visnadi2021_spur.toml" --out "$work/stiffness" "${quiet[@]}" \
  --set 'mesh_stiffness.models=["potential_energy"]' --set mesh_stiffness.positions=1000
measure "geardyn hbm (short sweep)" "$cli" hbm \
  "$here/examples/hbm_backlash_kahraman_singh.toml" --out "$work/hbm" "${quiet[@]}" \
  --set sweep.start=0.4 --set sweep.stop=0.5 --set sweep.direction=up \
  --set 'sweep.newmark_frequencies=[]'
measure "geardyn train (Lin & Parker modal)" "$cli" train \
  "$here/examples/train_lin_parker1999.toml" --out "$work/train" "${quiet[@]}"

echo
echo "shared libraries mapped:"
maps() { "$@" >/dev/null 2>&1; LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -c 'calling init:' ; }
printf '  %-32s %s\n' "geardyn --version" "$(maps "$cli" --version)"
printf '  %-32s %s\n' "geardyn geometry" "$(maps "$cli" geometry \
  "$here/examples/geometry_rao2023_rig.toml" --out "$work/geometry" "${quiet[@]}")"
echo "dynamic loader, geardyn --version:"
LD_DEBUG=statistics "$cli" --version 2>&1 >/dev/null | grep -E 'total startup time|relocation processing|number of relocations' |
  sed -e 's/^ *[0-9]*: */  /'
