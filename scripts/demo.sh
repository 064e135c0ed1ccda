#!/usr/bin/env bash
# The main job: run every seed example (examples/<command>_*.toml) end to end through the CLI
# and say where the results are. Assumes scripts/setup.sh has built build/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
cli="${BUILD_DIR:-build}/bin/geardyn"
[ -x "$cli" ] || { echo "demo: $cli is missing; run scripts/setup.sh first" >&2; exit 3; }

# Meshes the examples read and nobody stores: written by their gmsh scripts when absent.
deck=examples/gearboxes/two_stage_reducer_box.inp
[ -f "$deck" ] || /usr/bin/python3 examples/housing_box_gmsh.py "$deck" --size 0.03

# The examples are independent: run side by side on the machine's cores (DEMO_JOBS), each one's
# output printed whole when it ends (a lock keeps two from interleaving).
jobs="${DEMO_JOBS:-$(nproc)}"
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
export cli logs
run_example() {
  local example="$1" stem command
  stem="$(basename "$example" .toml)"
  command="${stem%%_*}"
  {
    echo "== geardyn $command $example"
    if ! "$cli" "$command" "$example" --out "results/$stem" 2>&1; then
      echo "demo: $example failed"
      touch "$logs/$stem.failed"
    fi
    echo
  } > "$logs/$stem.log"
  flock "$logs" cat "$logs/$stem.log"
}
export -f run_example
printf '%s\n' examples/*.toml | xargs -P "$jobs" -I{} bash -c 'run_example "$1"' _ {}
status=0
for failed in "$logs"/*.failed; do
  [ -e "$failed" ] || continue
  echo "demo: examples/$(basename "$failed" .failed).toml failed" >&2
  status=1
done
echo "Results are in $here/results/ (one folder per example: summary.json, CSV tables)."
exit "$status"
