/// `spectrum CONFIG`: full spectra and whirl peaks of a probe record (Rao 2023 §4.3–4.4,
/// §5.4–5.5): whole pinion cycles between keyphasor pulses, phases referred to the first pulse
/// (the gear shaft through the gear ratio: its angle is taken as zero there too).

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/rotor_results.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/error.h"
#include "geardyn/io/probe_record.h"

namespace geardyn::analysis {

AnalysisResult spectrumAnalysis(const config::Config& config, const AnalysisContext& context) {
  AnalysisResult result("spectrum", config, context);
  std::filesystem::path file = config.string("input.file");
  if (file.is_relative()) file = std::filesystem::path(config.source()).parent_path() / file;
  io::RecordReadOptions read;
  read.channels = config.stringList("input.channels");
  read.sample_rate = config.optionalReal("input.sample_rate");
  read.scale = config.real("input.scale");
  read.time_column = config.string("input.time_column");
  for (const char* role : {"x1", "y1", "x2", "y2"}) {
    if (std::find(read.channels.begin(), read.channels.end(), role) == read.channels.end()) {
      throw InputError("input.channels", fmt::format("[{}]", fmt::join(read.channels, ", ")),
                       fmt::format("must name the channel '{}' (x1, y1, x2, y2 and optionally "
                                   "keyphasor)",
                                   role));
    }
  }
  const io::ProbeRecord record = io::readProbeRecord(file, read);
  const double fs = record.sample_rate;

  GearWhirlSetup setup;
  setup.pinion_teeth = static_cast<int>(config.integer("gears.pinion_teeth"));
  setup.gear_teeth = static_cast<int>(config.integer("gears.gear_teeth"));
  setup.harmonics = static_cast<int>(config.integer("gears.harmonics"));
  const auto configured_rpm = config.optionalReal("gears.speed_rpm");
  const bool has_keyphasor =
      std::find(read.channels.begin(), read.channels.end(), "keyphasor") != read.channels.end();
  const bool use_keyphasor = config.boolean("keyphasor.enabled");
  if (use_keyphasor && !has_keyphasor) {
    throw InputError("keyphasor.enabled", "true",
                     "the record has no 'keyphasor' channel: add it to input.channels or set "
                     "keyphasor.enabled = false (and gears.speed_rpm)");
  }
  std::size_t begin = 0, end = record.samples();
  double reference = record.start_time;
  nlohmann::ordered_json keyphasor_json;
  if (use_keyphasor) {
    const KeyphasorPulses pulses =
        findKeyphasorPulses(record.channel("keyphasor"), fs, record.start_time,
                            config.optionalReal("keyphasor.threshold").value_or(NAN),
                            config.real("keyphasor.max_speed_variation"));
    setup.pinion_speed = pulses.speed;
    if (configured_rpm && std::abs(*configured_rpm / 60.0 / pulses.speed - 1.0) > 0.01) {
      throw InputError("gears.speed_rpm", fmt::format("{:g}", *configured_rpm),
                       fmt::format("disagrees with the keyphasor's {:.6g} rpm by more than 1 %",
                                   60.0 * pulses.speed));
    }
    // Whole revolutions: samples from the first pulse to before the last.
    reference = pulses.times.front();
    begin = static_cast<std::size_t>(std::ceil((pulses.times.front() - record.start_time) * fs));
    end = static_cast<std::size_t>(std::ceil((pulses.times.back() - record.start_time) * fs));
    keyphasor_json = {
        {"pulses", pulses.times.size()},       {"first_pulse_s", pulses.times.front()},
        {"last_pulse_s", pulses.times.back()}, {"revolutions", pulses.times.size() - 1},
        {"speed_rpm", 60.0 * pulses.speed},    {"threshold", pulses.threshold}};
  } else {
    if (!configured_rpm) {
      throw InputError("gears.speed_rpm", "(not set)", "needed when the keyphasor is not used");
    }
    setup.pinion_speed = *configured_rpm / 60.0;
  }
  setup.validate();
  const double highest = setup.meshFrequency() * std::max(1, setup.harmonics);
  if (fs <= 2.0 * highest) {
    throw InputError(
        "input.sample_rate", fmt::format("{:g} Hz", fs),
        fmt::format("must exceed twice the highest mesh harmonic ({:.6g} Hz)", highest));
  }
  std::array<std::vector<double>, 4> channels;
  const char* roles[] = {"x1", "y1", "x2", "y2"};
  for (int c = 0; c < 4; ++c) {
    const auto& all = record.channel(roles[c]);
    channels[c].assign(all.begin() + static_cast<std::ptrdiff_t>(begin),
                       all.begin() + static_cast<std::ptrdiff_t>(end));
  }
  const std::uint64_t seed = static_cast<std::uint64_t>(config.integer("spectrum.seed"));
  const double noise = config.real("spectrum.noise_level");
  if (noise > 0.0) {
    std::mt19937_64 rng(seed);
    for (auto& channel : channels) addRelativeNoise(channel, noise, rng);
  }
  const GearPairSpectrumOptions spectrum_options =
      config::gearPairSpectrumOptionsFromConfig(config);
  const double first_time = record.start_time + static_cast<double>(begin) / fs;
  const GearPairSpectrum spectrum =
      analyseGearPairRecord(channels, fs, first_time, reference, setup, spectrum_options);

  io::RunSummary& summary = result.summary;
  if (noise > 0.0) summary.seed = seed;
  result.addTable("spectrum_peaks.csv", analysis::whirlPeaksTable(spectrum.peaks));
  result.addTable("full_spectrum.csv",
                  analysis::fullSpectrumTable(
                      spectrum.display,
                      config.optionalReal("spectrum.max_frequency").value_or(1.25 * highest)));
  io::CsvTable history({"t_s", "x1_m", "y1_m", "x2_m", "y2_m"});
  for (std::size_t k = 0; k < channels[0].size(); ++k) {
    history.addRow({first_time + static_cast<double>(k) / fs, channels[0][k], channels[1][k],
                    channels[2][k], channels[3][k]});
  }
  result.addTable("time_history.csv", history);
  summary.results = {
      {"record",
       {{"file", file.string()},
        {"format", io::toString(io::recordFormatOf(file, "input.file"))},
        {"sample_rate_hz", fs},
        {"samples", record.samples()},
        {"analysed_samples", end - begin},
        {"analysed_from_s", first_time}}},
      {"frequencies",
       {{"pinion_hz", setup.pinion_speed},
        {"gear_hz", setup.gearSpeed()},
        {"mesh_hz", setup.meshFrequency()},
        {"common_period_s", setup.commonPeriod()}}},
      {"extraction",
       spectrum.method == WhirlExtraction::kExactBins ? "exact_bins" : "least_squares"},
      {"conventions",
       analysis::whirlConventionsJson(
           spectrum_options.frame,
           use_keyphasor ? "the first keyphasor pulse (pinion angle 0; the gear angle "
                           "is taken as 0 there too, the gear-ratio adjustment of "
                           "thesis §5.5)"
                         : "the record's first sample")},
      {"coefficient_noise",
       {{"pinion", spectrum.coefficient_sigma[0]}, {"gear", spectrum.coefficient_sigma[1]}}},
      {"peaks", analysis::whirlPeaksJson(spectrum.peaks)}};
  if (!keyphasor_json.is_null()) summary.results["keyphasor"] = keyphasor_json;
  std::string text = fmt::format(
      "full spectra of {} ({} samples at {:g} Hz, {} analysed): pinion {:.6g} Hz, mesh {:.6g} "
      "Hz\n",
      file.filename().string(), record.samples(), fs, end - begin, setup.pinion_speed,
      setup.meshFrequency());
  for (int sh = 0; sh < 2; ++sh) {
    const auto& peaks = spectrum.peaks[sh];
    const auto top = std::max_element(
        peaks.begin() + 1, peaks.end(),
        [](const auto& a, const auto& b) { return std::abs(a.value) < std::abs(b.value); });
    text += fmt::format("  {} shaft: largest whirl {} {:.4g} m at {:.6g} Hz\n",
                        analysis::kShaftNames[sh], top->name, std::abs(top->value), top->frequency);
  }
  result.report = text;
  return result;
}

}  // namespace geardyn::analysis
