#include "geardyn/analysis/rotor_results.h"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/error.h"
#include "geardyn/identify/dte_identification.h"

namespace geardyn::analysis {

io::CsvTable whirlPeaksTable(const std::array<std::vector<WhirlComponent>, 2>& peaks) {
  // Complex whirl radii [m] (z = x + j y) and their phase [rad].
  io::CsvTable t(
      {"shaft", "component", "frequency_hz", "re_m", "im_m", "amplitude_m", "phase_rad"});
  for (int s = 0; s < 2; ++s) {
    for (const auto& c : peaks[s]) {
      t.addRow({std::string(kShaftNames[s]), c.name, c.frequency, c.value.real(), c.value.imag(),
                std::abs(c.value), std::arg(c.value)});
    }
  }
  return t;
}

io::CsvTable fullSpectrumTable(const std::array<FullSpectrum, 2>& spectra, double max_frequency) {
  io::CsvTable t({"shaft", "frequency_hz", "re_m", "im_m", "amplitude_m", "phase_rad"});
  for (int s = 0; s < 2; ++s) {
    const auto& sp = spectra[s];
    for (std::size_t i = 0; i < sp.frequency.size(); ++i) {
      if (std::abs(sp.frequency[i]) > max_frequency) continue;
      const auto c = sp.coefficient[i];
      t.addRow({std::string(kShaftNames[s]), sp.frequency[i], c.real(), c.imag(), std::abs(c),
                std::arg(c)});
    }
  }
  return t;
}

nlohmann::ordered_json whirlPeaksJson(const std::array<std::vector<WhirlComponent>, 2>& peaks) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (int s = 0; s < 2; ++s) {
    for (const auto& c : peaks[s]) {
      out[kShaftNames[s]][c.name] = {{"frequency_hz", c.frequency},
                                     {"amplitude", std::abs(c.value)},
                                     {"phase", std::arg(c.value)}};
    }
  }
  return out;
}

std::array<std::vector<WhirlComponent>, 2> frequencyDomainPeaks(
    const std::vector<RotorWhirlResponse>& parts, WhirlFrame frame) {
  return inFrame(whirlPeaksOf(parts), frame);
}

nlohmann::ordered_json whirlConventionsJson(WhirlFrame frame, const std::string& phase_reference) {
  return {
      {"probe_orientation",
       "x and y orthogonal probes at each gear, y vertical (gravity along -y); turning from x to "
       "y is the +z (counter-clockwise) sense"},
      {"rotation", {{"pinion", "-z (clockwise), Rao eq. 2.2"}, {"gear", "+z (counter-clockwise)"}}},
      {"frame", frame == WhirlFrame::kShaft
                    ? "shaft: each shaft relative to its own rotation (pinion record conjugated, "
                      "z = x - jy)"
                    : "probe: z = x + jy for both shafts"},
      {"signal", "z(t) = x(t) + j y(t)"},
      {"fft", "Z_k = sum_n z_n exp(-j 2 pi k n / N), scaled by 1/N"},
      {"amplitude", "0-peak radius of each whirl circle (forward f > 0, backward f < 0)"},
      {"phase", "arg of the complex radius at the phase reference [rad]"},
      {"phase_reference", phase_reference},
  };
}

}  // namespace geardyn::analysis
