/// libFuzzer: arbitrary bytes as a WAV or CSV probe record (the first byte picks the format; HDF5
/// parsing is libhdf5's, not fuzzed here), then the keyphasor and the whirl analysis of whatever
/// was read. Bad input must end in InputError, never in a crash, a hang or a sanitizer report.

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "geardyn/error.h"
#include "geardyn/io/probe_record.h"
#include "geardyn/signal/gear_whirl.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const std::string extensions[] = {".wav", ".csv"};
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("libfuzzer_input_" + std::to_string(::getpid()) + extensions[data[0] % 2]);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    geardyn::io::RecordReadOptions options;
    options.channels = {"x1", "y1", "x2", "y2", "keyphasor"};
    options.sample_rate = data[0] % 4 >= 2 ? std::optional<double>(5000.0) : std::nullopt;
    const auto record = geardyn::io::readProbeRecord(path, options);
    if (record.samples() <= 100000) {
      const auto pulses = geardyn::findKeyphasorPulses(record.channel("keyphasor"),
                                                       record.sample_rate, record.start_time);
      geardyn::GearWhirlSetup setup{pulses.speed, 16, 35, 2};
      std::array<std::vector<double>, 4> channels{record.channel("x1"), record.channel("y1"),
                                                  record.channel("x2"), record.channel("y2")};
      geardyn::analyseGearPairRecord(channels, record.sample_rate, record.start_time,
                                     record.start_time, setup, {});
    }
  } catch (const geardyn::InputError&) {
  }
  std::filesystem::remove(path);
  return 0;
}
