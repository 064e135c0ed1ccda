#!/usr/bin/env bash
# Compiler/linker launcher that logs each command's CPU time (issue 34's build-time measurements):
#   cmake -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/cpu_time_wrapper.sh \
#         -DCMAKE_CXX_LINKER_LAUNCHER=$PWD/scripts/cpu_time_wrapper.sh ...
# Each line of $CPU_TIME_LOG (default /tmp/geardyn_cpu_time.log): wall s, user s, sys s, command.
# scripts/cpu_time_summary.py sums it by group.
exec /usr/bin/time -f "%e %U %S %C" -a -o "${CPU_TIME_LOG:-/tmp/geardyn_cpu_time.log}" "$@"
