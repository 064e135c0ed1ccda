"""What the Python API costs over the C++ library call (issue 19: at most 5 % more), for a
1000-point mesh-stiffness curve (examples/stiffness_visnadi2021_spur.toml, five models over
1000 positions) and a harmonic-balance sweep (examples/hbm_backlash_kahraman_singh.toml).

The C++ time is geardyn::analysis::runAnalysis as the library measures it
(AnalysisResult::wall_time_s, the analysis from the validated configuration to the result
with its tables). The Python time is `geardyn.run(command, file)` end to end: reading and
validating the file, the analysis, and the Result object with its summary dictionary (the
columns are numpy views, made on access: one access of every table is included). Medians of
REPEAT runs, after one warm-up run.

Run: PYTHONPATH=build/python python3 bench/python_api_bench.py [--repeat N] [--limit 0.05]
(CTest: `ctest -L bench -R python_api`). Exit code 1 when a case exceeds the limit.
"""

import argparse
import os
import pathlib
import statistics
import sys
import time

import geardyn

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[1]))
CASES = [("stiffness", "stiffness_visnadi2021_spur.toml", 15),
         ("hbm", "hbm_backlash_kahraman_singh.toml", 5)]


def measure(command, path, repeat):
    python, library = [], []
    geardyn.run(command, path, progress=False)  # warm-up
    for _ in range(repeat):
        start = time.perf_counter()
        result = geardyn.run(command, path, progress=False)
        for table in result.tables:
            result.table(table)
        python.append(time.perf_counter() - start)
        library.append(result.wall_time_s)
    return statistics.median(python), statistics.median(library)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=0, help="runs per case (0: per case)")
    parser.add_argument("--limit", type=float, default=0.05)
    options = parser.parse_args()
    worst = 0.0
    print(f"{'case':<12} {'C++ library [ms]':>17} {'Python API [ms]':>16} {'overhead':>9}")
    for command, file, repeat in CASES:
        py, cpp = measure(command, SOURCE / "examples" / file, options.repeat or repeat)
        overhead = py / cpp - 1.0
        worst = max(worst, overhead)
        print(f"{command:<12} {1e3 * cpp:17.2f} {1e3 * py:16.2f} {100 * overhead:8.2f} %")
    print(f"worst overhead {100 * worst:.2f} % (limit {100 * options.limit:.0f} %)")
    return 0 if worst <= options.limit else 1


if __name__ == "__main__":
    sys.exit(main())
