"""In-process speed of a small train from Python (issue 39): Lin & Parker's 3-planet stage
(examples/train_lin_parker1999.toml, 18 DOFs), per call, all in one run so that every number
sees the same load on the shared machine.

- geardyn.GearTrain, built once: ``frequencies()`` (the modal analysis of the built model: the
  undamped, non-rotating stage takes the symmetric eigensolver), ``modal()`` (the same as a
  DataFrame with mode types and strain energies), ``set(sun-planet stiffness)`` followed by
  ``frequencies()`` (a rank-one update of the three sun-planet meshes, then the modes).
- ``geardyn.run('train', dict)`` (the issue's 1.8-2.0 ms: the dict to TOML, parsed,
  validated, the model built, every table packaged).
- The numpy reference for the peer (Drivetrain-python: assembly + scipy eigvals, 0.7 ms in
  the issue; it cannot be installed here): the same M and K assembled in numpy from the same
  parts (each bearing's, pin's and coupling's Jᵀ k J scattered into K, each mesh's k̄ v vᵀ),
  then ``scipy.linalg.eigvals(K, M)`` (the general solver the peer calls) and, as the
  better numpy one can do, ``scipy.linalg.eigh(K, M, eigvals_only=True)``. Its frequencies
  are checked against geardyn's.

Each case: the median and the fastest of REPEAT calls after a warm-up, in ROUNDS alternating
rounds. Run: PYTHONPATH=build/python python3 bench/python_train_bench.py
"""

import argparse
import os
import pathlib
import statistics
import sys
import time
import tomllib

import warnings

import numpy as np
import scipy.linalg

import geardyn

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[1]))
LIN_PARKER = SOURCE / "examples" / "train_lin_parker1999.toml"
KEY = "planetary.stage.sun_planet.stiffness_value"


def numpy_assembly(mass, elements, meshes):
    """K from the parts as a numpy program assembles it; M given (diagonal)."""
    n = mass.shape[0]
    K = np.zeros((n, n))
    for dofs, k in elements:
        K[np.ix_(dofs, dofs)] += k
    for dofs, v, k in meshes:
        v = np.asarray(v)
        K[np.ix_(dofs, dofs)] += k * np.outer(v, v)
    return K


def timed(call, repeat):
    call()  # warm-up
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return times


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=2000)
    parser.add_argument("--rounds", type=int, default=3)
    options = parser.parse_args()
    warnings.simplefilter("ignore")  # the stage is unloaded on purpose (free vibration)
    with open(LIN_PARKER, "rb") as handle:
        document = tomllib.load(handle)
    train = geardyn.GearTrain(LIN_PARKER)
    mass = np.array(train.mass)
    elements = [(list(d), np.array(k)) for d, k in train._native.element_parts]
    meshes = [(list(d), list(v), k) for d, v, k in train._native.mesh_parts]
    # The reference's frequencies against geardyn's (the same M and K).
    K = numpy_assembly(mass, elements, meshes)
    reference = np.sqrt(np.abs(scipy.linalg.eigh(K, mass, eigvals_only=True))) / (2 * np.pi)
    ours = train.frequencies()
    agreement = np.abs(reference[3:] - ours[3:]).max() / ours[-1]
    print(f"Lin & Parker 3-planet stage, {mass.shape[0]} DOFs; numpy reference vs geardyn "
          f"frequencies: {agreement:.1e} of the highest")
    stiffness = [5e8, 5.5e8]
    state = {"i": 0}

    def set_and_modes():
        state["i"] ^= 1
        train.set(KEY, stiffness[state["i"]])
        return train.frequencies()

    def numpy_eigvals():
        k = numpy_assembly(mass, elements, meshes)
        return scipy.linalg.eigvals(k, mass)

    def numpy_eigh():
        k = numpy_assembly(mass, elements, meshes)
        return scipy.linalg.eigh(k, mass, eigvals_only=True)

    cases = {
        "GearTrain.frequencies()": (train.frequencies, options.repeat),
        "GearTrain.modal() (DataFrame)": (train.modal, options.repeat // 4),
        "GearTrain.set(k_sp) + frequencies()": (set_and_modes, options.repeat),
        "numpy assembly + scipy eigvals (peer)": (numpy_eigvals, options.repeat),
        "numpy assembly + scipy eigh": (numpy_eigh, options.repeat),
        "geardyn.run('train', dict)": (
            lambda: geardyn.run("train", document, progress=False),
            options.repeat // 20),
    }
    best = {name: [] for name in cases}
    for _ in range(options.rounds):
        for name, (call, repeat) in cases.items():
            best[name] += timed(call, repeat)
    print(f"{'case':<40} {'median [us]':>12} {'fastest [us]':>13}")
    for name, times in best.items():
        print(f"{name:<40} {1e6 * statistics.median(times):12.1f} {1e6 * min(times):13.1f}")
    peer = statistics.median(best["numpy assembly + scipy eigvals (peer)"])
    ours = statistics.median(best["GearTrain.frequencies()"])
    print(f"GearTrain.frequencies() is {peer / ours:.1f}x faster than the numpy reference")
    return 0


if __name__ == "__main__":
    sys.exit(main())
