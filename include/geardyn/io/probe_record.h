#pragma once
/// \file
/// Multi-channel probe records (displacement probes x₁, y₁, x₂, y₂ and a keyphasor, Rao 2023
/// §5.4) in three file formats, read with every corruption named and written atomically:
///   - CSV: a header of channel names, an optional time column [s] (uniform, increasing), one
///     row per sample (shortest round-trip decimal, lossless). Written with the result-name
///     convention: `t_s`, then each channel with its unit suffix (`x1_m`, ..., `keyphasor`);
///     read by channel name with or without that suffix (`x1` finds `x1` or `x1_m`);
///   - WAV (RIFF): PCM 16/24/32-bit or IEEE float 32/64-bit, channels in the configured order;
///     the sample rate from the header; integer PCM is scaled to [−1, 1) and then by `scale`;
///     written as 64-bit float (lossless);
///   - HDF5: one 1-D double dataset per channel at the root, named as the channel, and the
///     sample rate [Hz] as the root attribute `sample_rate` (or a `time` dataset).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace geardyn::io {

enum class RecordFormat { kCsv, kWav, kHdf5 };

/// From the extension: .csv, .wav, .h5/.hdf5 (InputError naming `key` otherwise).
RecordFormat recordFormatOf(const std::filesystem::path& path, const std::string& key);
std::string toString(RecordFormat format);

struct ProbeRecord {
  double sample_rate = 0.0;  ///< [Hz]
  double start_time = 0.0;   ///< time of sample 0 [s] (CSV time column, else 0)
  std::vector<std::string> names;
  std::vector<std::vector<double>> channels;  ///< same length each
  /// Per channel, the lower-case unit suffix of its CSV column ("m": `x1_m`); empty or absent:
  /// dimensionless, the column is the channel's name.
  std::vector<std::string> units;

  std::size_t samples() const { return channels.empty() ? 0 : channels.front().size(); }
  /// The samples of a named channel (InputError if absent).
  const std::vector<double>& channel(const std::string& name) const;
};

struct RecordReadOptions {
  std::vector<std::string> channels;  ///< names wanted, in the file's order for WAV
  std::optional<double> sample_rate;  ///< [Hz] when the file has none (CSV without time);
                                      ///< must agree with the file's when both exist
  double scale = 1.0;                 ///< multiplies every value (e.g. m per full-scale unit)
  std::string key = "input.file";     ///< configuration key of the path, for messages
  /// CSV: the time column; empty: the first of "t_s", "time", "time_s", "t" present (none: no
  /// time).
  std::string time_column;
};

/// Reads the wanted channels. InputError (file, channel, sample index) for: a missing or
/// truncated file, a wrong channel count (WAV), a missing channel, NaN/Inf samples, a time
/// column that is not increasing or not uniform (to 1e-6 of the interval), no sample rate.
ProbeRecord readProbeRecord(const std::filesystem::path& path, const RecordReadOptions& options);

/// Writes the record atomically (temporary file + rename) in the given format.
void writeProbeRecord(const std::filesystem::path& path, RecordFormat format,
                      const ProbeRecord& record);

}  // namespace geardyn::io
