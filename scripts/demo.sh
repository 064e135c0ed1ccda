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

status=0
for example in examples/*.toml; do
  stem="$(basename "$example" .toml)"
  command="${stem%%_*}"
  echo "== geardyn $command $example"
  if ! "$cli" "$command" "$example" --out "results/$stem"; then
    echo "demo: $example failed" >&2
    status=1
  fi
  echo
done
echo "Results are in $here/results/ (one folder per example: summary.json, CSV tables)."
exit "$status"
