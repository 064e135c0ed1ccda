/// Probe records: lossless round trips in CSV, WAV and HDF5, and every corruption named.

#include "geardyn/io/probe_record.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "geardyn/error.h"

namespace geardyn::io {
namespace {

namespace fs = std::filesystem;

ProbeRecord sample() {
  ProbeRecord r;
  r.sample_rate = 5000.0;
  r.names = {"x1", "y1", "x2", "y2", "keyphasor"};
  for (int c = 0; c < 5; ++c) {
    std::vector<double> v;
    for (int i = 0; i < 777; ++i) v.push_back(1e-5 * std::sin(0.013 * i * (c + 1) + c) + 3e-7 * c);
    r.channels.push_back(v);
  }
  return r;
}

/// This process's scratch folder, removed when the process ends (each test runs in its own
/// process: one folder each was left in /tmp before).
struct ScratchFolder {
  fs::path path =
      fs::temp_directory_path() / ("geardyn_probe_record_" + std::to_string(::getpid()));
  ScratchFolder() { fs::create_directories(path); }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

fs::path folder() {
  static const ScratchFolder scratch;
  return scratch.path;
}

RecordReadOptions options(std::optional<double> rate = std::nullopt) {
  RecordReadOptions o;
  o.channels = {"x1", "y1", "x2", "y2", "keyphasor"};
  o.sample_rate = rate;
  return o;
}

TEST(ProbeRecord, RoundTripsAreLossless) {
  const ProbeRecord r = sample();
  for (const char* name : {"m.csv", "m.wav", "m.h5"}) {
    const fs::path path = folder() / name;
    writeProbeRecord(path, recordFormatOf(path, "file"), r);
    const ProbeRecord back = readProbeRecord(path, options());
    EXPECT_EQ(back.sample_rate, 5000.0) << name;
    ASSERT_EQ(back.channels.size(), 5u);
    for (int c = 0; c < 5; ++c) EXPECT_EQ(back.channels[c], r.channels[c]) << name << c;
  }
}

TEST(ProbeRecord, ConflictingOrMissingSampleRateIsAnError) {
  const fs::path path = folder() / "rate.wav";
  writeProbeRecord(path, RecordFormat::kWav, sample());
  EXPECT_THROW(readProbeRecord(path, options(4000.0)), InputError);
  EXPECT_NO_THROW(readProbeRecord(path, options(5000.0)));
  const fs::path csv = folder() / "no_time.csv";
  std::ofstream(csv) << "x1,y1,x2,y2,keyphasor\n1,2,3,4,5\n1,2,3,4,5\n";
  EXPECT_THROW(readProbeRecord(csv, options()), InputError);
  EXPECT_EQ(readProbeRecord(csv, options(100.0)).sample_rate, 100.0);
}

TEST(ProbeRecord, CsvNamesTimeAndChannelsWithUnitsAndReadsOldNames) {
  ProbeRecord r = sample();
  r.units = {"m", "m", "m", "m", ""};
  const fs::path path = folder() / "units.csv";
  writeProbeRecord(path, RecordFormat::kCsv, r);
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t_s,x1_m,y1_m,x2_m,y2_m,keyphasor");
  // Channels are asked for by name, with or without the unit suffix in the file.
  const ProbeRecord back = readProbeRecord(path, options());
  EXPECT_EQ(back.sample_rate, 5000.0);
  EXPECT_EQ(back.names.front(), "x1");
  for (int c = 0; c < 5; ++c) EXPECT_EQ(back.channels[c], r.channels[c]) << c;
  // A record written before the convention: time, x1, ...
  const fs::path old = folder() / "old_names.csv";
  std::ofstream(old) << "time,x1,y1,x2,y2,keyphasor\n0,1,2,3,4,5\n0.01,1,2,3,4,5\n";
  EXPECT_EQ(readProbeRecord(old, options()).sample_rate, 100.0);
}

std::string messageOf(const fs::path& path, const RecordReadOptions& o) {
  try {
    readProbeRecord(path, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ProbeRecord, CorruptFilesAreRejectedSayingWhatAndWhere) {
  const fs::path dir = folder();
  // NaN in a CSV: row and column named.
  std::ofstream(dir / "nan.csv") << "time,x1,y1,x2,y2,keyphasor\n0,1,2,3,4,5\n0.001,1,nan,3,4,5\n";
  EXPECT_NE(messageOf(dir / "nan.csv", options()).find("y1"), std::string::npos);
  // Non-monotonic time.
  std::ofstream(dir / "time.csv")
      << "time,x1,y1,x2,y2,keyphasor\n0,1,2,3,4,5\n0.002,1,2,3,4,5\n0.001,1,2,3,4,5\n";
  EXPECT_NE(messageOf(dir / "time.csv", options()).find("not increasing"), std::string::npos);
  // Truncated WAV.
  writeProbeRecord(dir / "t.wav", RecordFormat::kWav, sample());
  fs::resize_file(dir / "t.wav", fs::file_size(dir / "t.wav") - 13);
  EXPECT_NE(messageOf(dir / "t.wav", options()).find("truncated"), std::string::npos);
  // Wrong channel count.
  RecordReadOptions four = options();
  four.channels.pop_back();
  writeProbeRecord(dir / "c.wav", RecordFormat::kWav, sample());
  EXPECT_NE(messageOf(dir / "c.wav", four).find("5 channels"), std::string::npos);
  // Missing HDF5 dataset, truncated HDF5.
  writeProbeRecord(dir / "m.h5", RecordFormat::kHdf5, sample());
  RecordReadOptions extra = options();
  extra.channels.push_back("z9");
  EXPECT_NE(messageOf(dir / "m.h5", extra).find("z9"), std::string::npos);
  fs::copy_file(dir / "m.h5", dir / "cut.h5", fs::copy_options::overwrite_existing);
  fs::resize_file(dir / "cut.h5", fs::file_size(dir / "cut.h5") / 2);
  EXPECT_FALSE(messageOf(dir / "cut.h5", options()).empty());
  // NaN sample in a WAV.
  ProbeRecord r = sample();
  r.channels[3][100] = NAN;
  writeProbeRecord(dir / "nan.wav", RecordFormat::kWav, r);
  EXPECT_NE(messageOf(dir / "nan.wav", options()).find("sample 100"), std::string::npos);
  EXPECT_THROW(readProbeRecord(dir / "absent.csv", options()), InputError);
  EXPECT_THROW(recordFormatOf("m.mat", "input.file"), InputError);
}

}  // namespace
}  // namespace geardyn::io
