#include "geardyn/contact/loaded_contact.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn {

LoadedToothContact::LoadedToothContact(
    std::shared_ptr<const PotentialEnergyMeshStiffness> stiffness, PairModifications modifications,
    int slices)
    : stiffness_(std::move(stiffness)), modifications_(std::move(modifications)), slices_(slices) {
  if (!stiffness_) throw InputError("stiffness", "null", "a potential-energy model is needed");
  if (slices_ < 1 || slices_ > 10000) {
    throw InputError("ltca.slices", fmt::format("{}", slices_), "an integer in [1, 10000]");
  }
  modifications_.pinion.validate("modifications.pinion");
  modifications_.gear.validate("modifications.gear");
}

void LoadedToothContact::slice(double phase, int pair, int slice, double& stiffness,
                               double& separation, int period) const {
  stiffness = 0.0;
  separation = 0.0;
  const auto& k = *stiffness_;
  double s_pair = 0.0;
  if (!k.pairSection(phase, pair, s_pair)) return;
  const double s_begin = k.contactStart(), s_end = k.contactEnd(), b = k.faceWidth();
  const double fraction = (slice + 0.5) / slices_;
  const double s = s_pair + fraction * k.stagger();
  if (s < s_begin || s > s_end) return;
  stiffness = std::max(0.0, k.sliceScale() * (b / slices_) * k.pairStiffnessPerWidth(s));
  // Pair j entered contact j periods ago: the teeth of period − j.
  const int tooth = period - pair;
  separation = modifications_.separation(s, (fraction - 0.5) * b, tooth, tooth, s_begin, s_end, b);
}

void LoadedToothContact::gather(double phase, int period, std::vector<Slice>& out) const {
  out.clear();
  for (int j = 0; j < pairCount(); ++j) {
    for (int i = 0; i < slices_; ++i) {
      double k = 0.0, g = 0.0;
      slice(phase, j, i, k, g, period);
      if (k > 0.0) out.push_back({k, g, j, i});
    }
  }
}

LoadedContactPoint LoadedToothContact::solve(double phase, double force, int period) const {
  if (!(force >= 0.0) || !std::isfinite(force)) {
    throw InputError("force", fmt::format("{:g}", force), "must be finite and >= 0 [N]");
  }
  thread_local std::vector<Slice> slices;
  gather(phase, period, slices);
  LoadedContactPoint p;
  p.phase = phase;
  p.pair_loads.assign(pairCount(), 0.0);
  p.face_loads.assign(slices_, 0.0);
  if (slices.empty()) {
    throw InputError("phase", fmt::format("{:g}", phase), "no tooth pair is in contact there");
  }
  std::sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.g < b.g; });
  p.no_load_te = slices.front().g;
  // Water filling: with the first m slices loaded, δ = (F + Σ k g)/Σ k; valid when δ does not
  // reach the next separation.
  double sum_k = 0.0, sum_kg = 0.0, delta = slices.front().g;
  std::size_t m = 0;
  while (m < slices.size()) {
    sum_k += slices[m].k;
    sum_kg += slices[m].k * slices[m].g;
    ++m;
    delta = force > 0.0 ? (force + sum_kg) / sum_k : slices.front().g;
    if (m == slices.size() || delta <= slices[m].g) break;
  }
  p.ste = delta;
  for (std::size_t i = 0; i < m; ++i) {
    const double load = slices[i].k * std::max(0.0, delta - slices[i].g);
    p.pair_loads[slices[i].pair] += load;
    p.face_loads[slices[i].face] += load;
    if (delta > slices[i].g || force == 0.0) p.tangent += slices[i].k;
  }
  p.loaded_slices = static_cast<int>(m);
  p.secant = delta > 0.0 ? force / delta : 0.0;
  return p;
}

std::vector<LoadedContactPoint> LoadedToothContact::sweep(double force, int positions, int periods,
                                                          const ProgressCallback& progress) const {
  if (positions < 2 || periods < 1) {
    throw InputError("ltca.positions", fmt::format("{} x {} periods", positions, periods),
                     "at least 2 positions over at least one period");
  }
  std::vector<LoadedContactPoint> out;
  out.reserve(static_cast<std::size_t>(positions) * periods);
  for (int p = 0; p < periods; ++p) {
    for (int i = 0; i < positions; ++i) {
      auto point = solve(static_cast<double>(i) / positions, force, p);
      point.phase += p;
      out.push_back(std::move(point));
    }
    if (progress)
      progress(static_cast<double>(p + 1) * positions, static_cast<double>(periods) * positions);
  }
  return out;
}

std::vector<std::complex<double>> steHarmonics(const std::vector<LoadedContactPoint>& period,
                                               int harmonics) {
  std::vector<std::complex<double>> c(harmonics, 0.0);
  const double n = static_cast<double>(period.size());
  for (const auto& p : period) {
    for (int h = 1; h <= harmonics; ++h)
      c[h - 1] += p.ste * std::polar(2.0 / n, -2.0 * std::numbers::pi * h * p.phase);
  }
  return c;
}

std::vector<HarrisPoint> harrisMap(const LoadedToothContact& contact,
                                   const std::vector<double>& forces, int positions, int harmonics,
                                   const ProgressCallback& progress) {
  std::vector<HarrisPoint> out;
  for (double f : forces) {
    if (progress) progress(static_cast<double>(out.size()), static_cast<double>(forces.size()));
    const auto period = contact.sweep(f, positions);
    HarrisPoint h;
    h.force = f;
    const auto [lo, hi] = std::minmax_element(
        period.begin(), period.end(), [](const auto& a, const auto& b) { return a.ste < b.ste; });
    h.peak_to_peak = hi->ste - lo->ste;
    for (const auto& p : period) h.mean += p.ste / positions;
    for (const auto& v : steHarmonics(period, harmonics)) h.harmonics.push_back(std::abs(v));
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace geardyn
