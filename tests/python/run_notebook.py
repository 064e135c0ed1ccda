"""Executes an example notebook with nbconvert (Debian's python3-nbconvert) from its own folder
and checks that the repository copy has its outputs stripped. With GEARDYN_EXAMPLE_RESULTS set
(the suite's example result folders), a notebook that runs an example again instead of loading
its result fails.

Usage: run_notebook.py NOTEBOOK.ipynb OUTPUT_DIR
"""

import os
import pathlib
import subprocess
import sys

import nbformat


def main():
    notebook, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    stored = nbformat.read(notebook, as_version=4)
    for cell in stored.cells:
        if cell.cell_type == "code" and (cell.outputs or cell.execution_count is not None):
            print(f"{notebook.name}: outputs are not stripped (cell {cell.source[:40]!r})",
                  file=sys.stderr)
            return 1
    out.mkdir(parents=True, exist_ok=True)
    done = subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute",
                           "--ExecutePreprocessor.timeout=-1", "--output-dir", str(out),
                           str(notebook.resolve())], cwd=notebook.parent)
    if done.returncode != 0:
        return done.returncode
    executed = nbformat.read(out / notebook.name, as_version=4)
    errors = [o for c in executed.cells if c.cell_type == "code" for o in c.outputs
              if o.output_type == "error"]
    print(f"{notebook.name}: {len(executed.cells)} cells executed, {len(errors)} errors")
    # With the suite's example results at hand, no example may run a second time (issue 34).
    rerun = [line for c in executed.cells if c.cell_type == "code" for o in c.outputs
             if o.output_type == "stream" for line in o.text.splitlines()
             if line.endswith(": running the example here")]
    if os.environ.get("GEARDYN_EXAMPLE_RESULTS") and rerun:
        print(f"{notebook.name}: ran again instead of loading "
              f"{os.environ['GEARDYN_EXAMPLE_RESULTS']}: {'; '.join(rerun)}", file=sys.stderr)
        return 1
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
