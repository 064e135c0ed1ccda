"""Rao (2023), Table 4.1: the 4-DOF lateral geared rotor with asymmetric transmission error,
exact frequency-domain whirl peaks against the Dormand–Prince steady state (both from Python,
numpy arrays out), and the thesis's forward/backward structure of the full spectrum."""

import numpy as np

import geardyn

rotor = geardyn.LateralRotor()  # Table 4.1 defaults
peaks = rotor.frequency_response()
mesh1 = peaks["pinion"]["mesh_1_fwd"], peaks["pinion"]["mesh_1_bwd"]
print("pinion 1st mesh harmonic: forward %.1f um at %+.0f Hz, backward %.1f um at %+.0f Hz"
      % (abs(mesh1[0][1]) * 1e6, mesh1[0][0], abs(mesh1[1][1]) * 1e6, mesh1[1][0]))
assert abs(abs(mesh1[0][1]) * 1e6 - 102.0) < 0.1 and abs(abs(mesh1[1][1]) * 1e6 - 233.2) < 0.1

response = rotor.time_response()  # the thesis: 15 s, 2^15 samples
eta = response["eta"]  # samples × (x1, y1, x2, y2) [m]
begin, end = response["window"]
print(f"time response: {response['status']}, steady window {end - begin} samples, "
      f"pinion orbit p2p {np.ptp(eta[begin:end, 0]) * 1e6:.1f} um")
assert response["status"] == "steady_state"
