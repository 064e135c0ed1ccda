"""Runs a Python example in-process and checks it left no file or folder behind in the
temporary folder (issue 19: in-process analyses write nothing; subprocess sweeps clean up).

Usage: run_without_temp_files.py EXAMPLE.py SCRATCH_DIR
TMPDIR is set to SCRATCH_DIR (emptied first) for the run, so that anything written through
tempfile or std::filesystem::temp_directory_path is caught there; /tmp is also listed before
and after for geardyn-* entries.
"""

import os
import pathlib
import runpy
import shutil
import sys
import tempfile


def main():
    example, scratch = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir(parents=True)
    os.environ["TMPDIR"] = str(scratch)
    tempfile.tempdir = None  # re-read TMPDIR
    before = {e for e in os.listdir("/tmp") if e.startswith("geardyn")}
    sys.argv = [str(example)]
    runpy.run_path(str(example), run_name="__main__")
    left = sorted(os.listdir(scratch))
    new_in_tmp = sorted({e for e in os.listdir("/tmp") if e.startswith("geardyn")} - before)
    if left or new_in_tmp:
        print(f"{example.name} left {left} in TMPDIR and {new_in_tmp} in /tmp", file=sys.stderr)
        return 1
    print(f"{example.name}: nothing left in the temporary folder")
    return 0


if __name__ == "__main__":
    sys.exit(main())
