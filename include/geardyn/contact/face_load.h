#pragma once
/// \file
/// Load distribution across the face from a loaded tooth contact sweep (issue 36): the line
/// load w(z, φ) = Σ_pairs p_i / (b/N) of every face slice over a mesh cycle, its cycle mean,
/// the face load factor K_Hβ = peak / mean line load (ISO 6336-1 §7.1, the definition; the
/// mean is F/b) and the centre of load. The peak is taken at the face end's edge when the line
/// load rises towards it: extrapolated linearly from the two outermost slices, which is exact
/// for the linear distributions of a mismatch (docs/theory/gear_whine.md); otherwise the
/// largest slice value.

#include <complex>
#include <vector>

#include "geardyn/contact/loaded_contact.h"

namespace geardyn {

struct FaceLoadDistribution {
  double force = 0.0;       ///< F [N]
  double face_width = 0.0;  ///< b [m]
  std::vector<double> z;    ///< slice centres from the mid-face [m]
  /// Line load per position (outer) and slice (inner) [N/m].
  std::vector<std::vector<double>> line_load;
  std::vector<double> mean_line_load;  ///< over the cycle [N/m]
  /// K_Hβ of the cycle-mean line load (the headline), and the largest instantaneous one.
  double k_hbeta = 1.0, k_hbeta_max = 1.0;
  double centre_of_load = 0.0;             ///< Σ z w̄ / Σ w̄ [m] from the mid-face
  double loaded_fraction = 1.0;            ///< share of slices carrying load in the cycle mean [-]
  std::vector<LoadedContactPoint> points;  ///< the sweep (STE, stiffnesses)
};

/// Peak-over-mean of a line load sampled at slice centres (the edge extrapolation above).
double faceLoadFactor(const std::vector<double>& line_load);

/// The sweep of `contact` at force F over `positions` phases of one mesh period and its load
/// distribution across the face.
FaceLoadDistribution faceLoadDistribution(const LoadedToothContact& contact, double force,
                                          int positions);
/// The same from a sweep already made (`points`: one period of contact.sweep(force, …)).
FaceLoadDistribution faceLoadDistribution(const LoadedToothContact& contact, double force,
                                          std::vector<LoadedContactPoint> points);

}  // namespace geardyn
