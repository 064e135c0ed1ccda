#pragma once
/// \file
/// What the modal solver (train_modal.cpp) and the FE rotor's reference modes of the tests
/// (tests/support/fe_rotor_modes.h) share to describe a mode: its
/// kinetic-energy shares (lateral, torsional, axial, from the diagonal mass) and its whirl.
/// A node's lateral motion (Y, Z) = F e^{iΩt} + B e^{−iΩt} splits into forward and backward
/// circles, |F|² ∝ |Y + iZ|², |B|² ∝ |Y − iZ|², forward meaning with the shaft's spin.

#include <complex>
#include <string>
#include <utility>

namespace geardyn::detail {

struct WhirlShares {
  double lateral = 0.0, torsional = 0.0, axial = 0.0;  ///< Σ m_d |q_d|² by kind of DOF
  double forward = 0.0, backward = 0.0;                ///< Σ m |F|², Σ m |B|² over the nodes

  /// Adds a node's lateral motion (Y, Z) with mass m; spin_sign < 0 when its shaft turns
  /// about −x (forward is then the other circle).
  void addWhirl(double m, std::complex<double> Y, std::complex<double> Z, double spin_sign) {
    const std::complex<double> I(0.0, 1.0);
    double f = std::norm(Y + I * Z), b = std::norm(Y - I * Z);
    if (spin_sign < 0.0) std::swap(f, b);
    forward += m * f;
    backward += m * b;
  }

  /// Writes the fractions and the whirl label ("torsional" or "axial" when that share is over
  /// half, else "forward"/"backward" beyond 3:1, else "mixed") into a mode that has the fields
  /// lateral_fraction, torsional_fraction, axial_fraction, forward_fraction and whirl.
  template <class Mode>
  void describe(Mode& mode) const {
    const double total = lateral + torsional + axial;
    mode.lateral_fraction = total > 0.0 ? lateral / total : 0.0;
    mode.torsional_fraction = total > 0.0 ? torsional / total : 0.0;
    mode.axial_fraction = total > 0.0 ? axial / total : 0.0;
    mode.forward_fraction = forward + backward > 0.0 ? forward / (forward + backward) : 0.5;
    if (mode.torsional_fraction > 0.5) {
      mode.whirl = "torsional";
    } else if (mode.axial_fraction > 0.5) {
      mode.whirl = "axial";
    } else {
      mode.whirl = mode.forward_fraction > 0.75   ? "forward"
                   : mode.forward_fraction < 0.25 ? "backward"
                                                  : "mixed";
    }
  }
};

}  // namespace geardyn::detail
