"""What the CLI tests share: the executable under test, the source tree and a runner."""

import os
import pathlib
import subprocess

CLI = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE / "examples"


def run(*args):
    """Runs `geardyn ARGS...` and returns the completed process (text output captured)."""
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
