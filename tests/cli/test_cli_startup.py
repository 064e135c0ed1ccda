"""Start-up (issue 22): the plain commands map neither OpenMPI nor HDF5 (with its network
stack); HDF5 is loaded by the runs that read or write .h5 files, MPI by sweeps under mpirun."""

import os
import re
import subprocess

from cli_support import CLI, EXAMPLES

HEAVY = ("libmpi", "libopen-pal", "libhwloc", "libhdf5", "libcurl", "libgnutls", "libkrb5")


def loaded_objects(*args, cwd=None):
    """The shared objects the dynamic loader maps during `geardyn ARGS` (LD_DEBUG=files)."""
    env = dict(os.environ, LD_DEBUG="files")
    result = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, env=env,
                            cwd=cwd)
    assert result.returncode == 0, result.stderr[-2000:]
    return set(re.findall(r"file=(\S+)\s+\[0\];\s+(?:needed by|dynamically loaded)", result.stderr))


def heavy(objects):
    return sorted(o for o in objects if any(os.path.basename(o).startswith(h) for h in HEAVY))


def test_the_executable_does_not_link_mpi_or_hdf5():
    needed = subprocess.run(["ldd", CLI], capture_output=True, text=True, check=True).stdout
    assert "libmpi" not in needed and "libhdf5" not in needed, needed


def test_plain_commands_map_neither_mpi_nor_hdf5(tmp_path):
    assert heavy(loaded_objects("--version")) == []
    objects = loaded_objects("geometry", EXAMPLES / "geometry_rao2023_rig.toml", "--out",
                             tmp_path / "g", "--quiet", "--set", "output.plots=false")
    assert objects and heavy(objects) == [], objects  # something was mapped: libstdc++ at least
    objects = loaded_objects("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml", "--out",
                             tmp_path / "s", "--quiet", "--set", "output.plots=false")
    assert heavy(objects) == []


def test_hdf5_is_loaded_only_by_a_run_that_writes_an_h5_file(tmp_path):
    table41 = EXAMPLES / "rotor_rao2023_table41.toml"
    common = ("--quiet", "--set", "output.plots=false", "--set", "measurement.duration=1.0")
    wav = loaded_objects("rotor", table41, "--out", tmp_path / "wav", *common,
                         "--set", 'measurement.formats=["wav"]')
    assert heavy(wav) == []
    h5 = loaded_objects("rotor", table41, "--out", tmp_path / "h5", *common,
                        "--set", 'measurement.formats=["hdf5"]')
    assert any("libgeardyn_hdf5" in o for o in h5), sorted(h5)
    assert any(os.path.basename(o).startswith("libhdf5") for o in h5), sorted(h5)
    assert (tmp_path / "h5" / "measurement.h5").stat().st_size > 0
