"""What the Python API costs over the C++ library call (issue 19: at most 5 % more), for a
1000-point mesh-stiffness curve (examples/stiffness_visnadi2021_spur.toml: five models over
1000 positions) and a harmonic-balance sweep (examples/hbm_backlash_kahraman_singh.toml).

C++: bench/analysis_api_bench.cpp (geardyn_analysis_bench) times the library call that
`geardyn.run(command, file)` makes — analysisSchema, loadConfigFile, runAnalysis — in a C++
program. Python: `geardyn.run(command, file)` end to end (the file checked, the same C++ call
through pybind11 with the GIL released, the Result object) plus one access of every table as
numpy arrays. Each side: the fastest of REPEAT runs after a warm-up (the run least disturbed by
other processes; the 2-core reference machine is shared), in rounds that alternate C++ and
Python so that both see the same load.

Run: PYTHONPATH=build/python python3 bench/python_api_bench.py --cpp build/bin/geardyn_analysis_bench
(CTest: `ctest -L bench -R python_api`). Exit code 1 when a case exceeds the limit.
"""

import argparse
import json
import os
import pathlib
import subprocess
import sys
import time

import geardyn

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[1]))
CASES = [("stiffness", "stiffness_visnadi2021_spur.toml", 30),
         ("hbm", "hbm_backlash_kahraman_singh.toml", 8)]
ROUNDS = 3


def python_fastest(command, path, repeat):
    geardyn.run(command, path, progress=False)  # warm-up
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        result = geardyn.run(command, path, progress=False)
        for table in result.tables:
            result.table(table)
        best = min(best, time.perf_counter() - start)
    return best


def cpp_fastest(binary, command, path, repeat):
    done = subprocess.run([binary, command, str(path), str(repeat)], check=True,
                          capture_output=True, text=True)
    return json.loads(done.stdout)["total_s"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cpp", required=True, help="the geardyn_analysis_bench executable")
    parser.add_argument("--limit", type=float, default=0.05)
    options = parser.parse_args()
    worst = -float("inf")
    print(f"{'case':<10} {'C++ library [ms]':>17} {'Python API [ms]':>16} {'overhead':>9}")
    for command, file, repeat in CASES:
        path = SOURCE / "examples" / file
        cpp, py = float("inf"), float("inf")
        for _ in range(ROUNDS):
            cpp = min(cpp, cpp_fastest(options.cpp, command, path, repeat))
            py = min(py, python_fastest(command, path, repeat))
        overhead = py / cpp - 1.0
        worst = max(worst, overhead)
        print(f"{command:<10} {1e3 * cpp:17.3f} {1e3 * py:16.3f} {100 * overhead:+8.2f} %")
    print(f"worst overhead {100 * worst:+.2f} % (limit {100 * options.limit:.0f} %)")
    return 0 if worst <= options.limit else 1


if __name__ == "__main__":
    sys.exit(main())
