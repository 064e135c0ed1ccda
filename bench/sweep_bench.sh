#!/usr/bin/env bash
# geardyn sweep: speed-up on 2 cores for equal-cost cases, and the MPI overhead per case.
#   bench/sweep_bench.sh [build/bin/geardyn]
# Equal-cost cases: 32 `simulate` runs of exactly 2000 mesh periods each (min_periods = 2000).
# Overhead: 2000 trivial `geometry` cases with 2 threads and with mpirun -n 2 (rank 0 dispatches
# and runs one worker, rank 1 runs the other): (T_mpi − T_threads − T_mpi_startup) / cases.
set -euo pipefail
cli="${1:-build/bin/geardyn}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,tcp \
  OMPI_MCA_btl_tcp_if_include=lo OMPI_MCA_rmaps_base_oversubscribe=1

cat > "$work/equal.toml" <<TOML
[study]
command = "simulate"
base = "$here/examples/simulate_gear_pair_backlash.toml"
set = ["solver.min_periods=2000", "solver.max_periods=100000"]
outputs = ["/dynamic_factor"]
[study.parameters]
"model.damping_ratio" = { min = 0.05, max = 0.08, num = 32 }
[output]
plots = false
TOML
cat > "$work/trivial.toml" <<TOML
[study]
command = "geometry"
base = "$here/examples/geometry_rao2023_rig.toml"
outputs = ["/contact_ratio_total"]
[study.parameters]
"gear.face_width" = { min = 0.01, max = 0.03, num = NUM }
[output]
plots = false
TOML
seconds() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>&1; e=$(date +%s.%N); echo "$e - $s" | bc -l; }

t1=$(seconds "$cli" sweep "$work/equal.toml" --out "$work/o1" --threads 1 --quiet)
t2=$(seconds "$cli" sweep "$work/equal.toml" --out "$work/o2" --threads 2 --quiet)
tm=$(seconds mpirun -n 2 "$cli" sweep "$work/equal.toml" --out "$work/om" --quiet)

sed 's/NUM/2000/' "$work/trivial.toml" > "$work/t400.toml"
sed 's/NUM/2/' "$work/trivial.toml" > "$work/t2.toml"
tt=$(seconds "$cli" sweep "$work/t400.toml" --out "$work/tt" --threads 2 --quiet)
tm400=$(seconds mpirun -n 2 "$cli" sweep "$work/t400.toml" --out "$work/tm" --quiet)
tm2=$(seconds mpirun -n 2 "$cli" sweep "$work/t2.toml" --out "$work/tm2" --quiet)
printf 'equal-cost sweep (32 cases): 1 thread %.3f s, 2 threads %.3f s (speed-up %.2f), mpirun -n 2 %.3f s (speed-up %.2f; %.2f without the %.2f s mpirun start-up)\n' \
  "$t1" "$t2" "$(echo "$t1 / $t2" | bc -l)" "$tm" "$(echo "$t1 / $tm" | bc -l)" \
  "$(echo "$t1 / ($tm - $tm2)" | bc -l)" "$tm2"
printf 'trivial cases (2000): threads %.3f s, mpirun %.3f s, mpirun start-up (2 cases) %.3f s: MPI overhead %.1f us per case\n' \
  "$tt" "$tm400" "$tm2" "$(echo "($tm400 - $tm2 - $tt) / 2000 * 1000000" | bc -l)"
