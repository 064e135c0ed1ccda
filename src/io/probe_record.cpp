#include "geardyn/io/probe_record.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"
#include "geardyn/io/csv_reader.h"
#include "geardyn/io/hdf5_lock.h"
#include "hdf5_module.h"

namespace geardyn::io {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

[[noreturn]] void bad(const RecordReadOptions& o, const fs::path& path, const std::string& what) {
  throw InputError(o.key, path.string(), what);
}

void checkFinite(const RecordReadOptions& o, const fs::path& path, const ProbeRecord& r) {
  for (std::size_t c = 0; c < r.channels.size(); ++c) {
    for (std::size_t i = 0; i < r.channels[c].size(); ++i) {
      if (!std::isfinite(r.channels[c][i])) {
        bad(o, path,
            fmt::format("channel '{}' sample {} is {}: a measured record must be finite",
                        r.names[c], i, r.channels[c][i]));
      }
    }
  }
}

/// Sample rate from a time column: increasing and uniform to 1e-6 of the interval.
double rateFromTime(const RecordReadOptions& o, const fs::path& path,
                    const std::vector<double>& t) {
  if (t.size() < 2) bad(o, path, "needs at least two samples");
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (!(t[i] > t[i - 1])) {
      bad(o, path,
          fmt::format("time is not increasing at sample {} ({:.9g} s after {:.9g} s)", i, t[i],
                      t[i - 1]));
    }
  }
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (std::abs(t[i] - (t.front() + dt * static_cast<double>(i))) > 1e-6 * dt) {
      bad(o, path,
          fmt::format("time is not uniformly sampled at sample {} ({:.9g} s, expected "
                      "{:.9g} s): resample the record first",
                      i, t[i], t.front() + dt * static_cast<double>(i)));
    }
  }
  return 1.0 / dt;
}

double agreeRate(const RecordReadOptions& o, const fs::path& path,
                 std::optional<double> file_rate) {
  if (file_rate && o.sample_rate && std::abs(*file_rate / *o.sample_rate - 1.0) > 1e-6) {
    bad(o, path,
        fmt::format("the file's sample rate {:.9g} Hz disagrees with the configured "
                    "{:.9g} Hz",
                    *file_rate, *o.sample_rate));
  }
  if (file_rate) return *file_rate;
  if (o.sample_rate) return *o.sample_rate;
  bad(o, path, "has no sample rate (no time column or attribute): set input.sample_rate");
}

/// The column of a channel: its name, else its name with a unit suffix (`x1_m`, as geardyn
/// writes displacement channels); the name itself when neither is present (the read then names
/// the missing channel).
std::string csvChannelColumn(const std::vector<std::string>& columns, const std::string& name) {
  if (std::find(columns.begin(), columns.end(), name) != columns.end()) return name;
  for (const char* unit : {"m", "m_per_s", "m_per_s2", "rad"}) {
    const std::string suffixed = name + "_" + unit;
    if (std::find(columns.begin(), columns.end(), suffixed) != columns.end()) return suffixed;
  }
  return name;
}

ProbeRecord readCsv(const fs::path& path, const RecordReadOptions& o) {
  const NumericCsv csv(path, o.key);
  ProbeRecord r;
  std::optional<double> rate;
  const auto& columns = csv.columns();
  // The time column: the one named by time_column, else the first of t_s (geardyn's own
  // records and tables), time, time_s, t (records written before the naming convention).
  std::string time_name = o.time_column;
  if (time_name.empty()) {
    for (const char* name : {"t_s", "time", "time_s", "t"})
      if (time_name.empty() && std::find(columns.begin(), columns.end(), name) != columns.end())
        time_name = name;
  }
  if (!time_name.empty()) {
    const auto& t = csv.column(time_name, o.time_column.empty() ? o.key : "input.time_column");
    rate = rateFromTime(o, path, t);
    r.start_time = t.front();
  }
  r.sample_rate = agreeRate(o, path, rate);
  for (const auto& name : o.channels) {
    r.names.push_back(name);
    r.channels.push_back(csv.column(csvChannelColumn(columns, name), o.key));
  }
  return r;
}

std::uint32_t le(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

ProbeRecord readWav(const fs::path& path, const RecordReadOptions& o) {
  std::ifstream in(path, std::ios::binary);
  if (!in) bad(o, path, "cannot be opened");
  const std::vector<unsigned char> b((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
  if (b.size() < 12 || std::memcmp(b.data(), "RIFF", 4) != 0 ||
      std::memcmp(b.data() + 8, "WAVE", 4) != 0) {
    bad(o, path, "is not a RIFF/WAVE file");
  }
  int format = -1, channels = 0, bits = 0, align = 0;
  double rate = 0.0;
  const unsigned char* data = nullptr;
  std::size_t data_bytes = 0;
  std::size_t at = 12;
  while (at + 8 <= b.size()) {
    const std::string id(reinterpret_cast<const char*>(b.data() + at), 4);
    const std::size_t size = le(b.data() + at + 4, 4);
    const std::size_t body = at + 8;
    if (body + size > b.size()) {
      bad(o, path,
          fmt::format("is truncated: chunk '{}' declares {} bytes, {} remain", id, size,
                      b.size() - body));
    }
    if (id == "fmt " && size >= 16) {
      format = static_cast<int>(le(b.data() + body, 2));
      channels = static_cast<int>(le(b.data() + body + 2, 2));
      rate = le(b.data() + body + 4, 4);
      align = static_cast<int>(le(b.data() + body + 12, 2));
      bits = static_cast<int>(le(b.data() + body + 14, 2));
      if (format == 0xFFFE && size >= 26) format = static_cast<int>(le(b.data() + body + 24, 2));
    } else if (id == "data") {
      data = b.data() + body;
      data_bytes = size;
    }
    at = body + size + (size & 1);
  }
  if (format < 0) bad(o, path, "has no 'fmt ' chunk");
  if (!data) bad(o, path, "has no 'data' chunk");
  const bool pcm = format == 1 && (bits == 16 || bits == 24 || bits == 32);
  const bool ieee = format == 3 && (bits == 32 || bits == 64);
  if (!pcm && !ieee) {
    bad(o, path,
        fmt::format("has sample format {} with {} bits: PCM 16/24/32 or float 32/64 "
                    "are read",
                    format, bits));
  }
  if (channels != static_cast<int>(o.channels.size())) {
    bad(o, path,
        fmt::format("has {} channels; the configuration names {} ({})", channels, o.channels.size(),
                    fmt::join(o.channels, ", ")));
  }
  if (align != channels * bits / 8) bad(o, path, fmt::format("has block align {}", align));
  if (data_bytes % align != 0) {
    bad(o, path,
        fmt::format("is truncated: {} data bytes is not a whole number of {}-byte "
                    "frames",
                    data_bytes, align));
  }
  const std::size_t n = data_bytes / align;
  ProbeRecord r;
  r.names = o.channels;
  r.channels.assign(channels, std::vector<double>(n));
  const int bytes = bits / 8;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < channels; ++c) {
      const unsigned char* p = data + i * align + c * bytes;
      double v;
      if (ieee && bits == 64) {
        std::uint64_t u = 0;
        for (int k = 7; k >= 0; --k) u = (u << 8) | p[k];
        std::memcpy(&v, &u, 8);
      } else if (ieee) {
        const std::uint32_t u = le(p, 4);
        float f;
        std::memcpy(&f, &u, 4);
        v = f;
      } else {
        std::uint32_t u = le(p, bytes);
        const std::uint32_t sign = 1u << (bits - 1);
        const std::int64_t s = (u & sign) ? static_cast<std::int64_t>(u) - (std::int64_t{1} << bits)
                                          : static_cast<std::int64_t>(u);
        v = static_cast<double>(s) / static_cast<double>(sign);
      }
      r.channels[c][i] = v * o.scale;
    }
  }
  r.sample_rate = agreeRate(o, path, rate);
  return r;
}

/// An open HDF5 file of the HDF5 module, closed on scope exit (the caller holds hdf5Mutex()).
struct Hdf5Reading {
  const detail::Hdf5ModuleApi& h5;
  std::int64_t file;
  ~Hdf5Reading() { h5.close(file); }
};

std::vector<double> readDataset(const Hdf5Reading& f, const std::string& name, const fs::path& path,
                                const RecordReadOptions& o) {
  if (!f.h5.has_dataset(f.file, name.c_str())) {
    bad(o, path, fmt::format("has no dataset '/{}'", name));
  }
  std::uint64_t n = 0;
  int status = f.h5.dataset_length(f.file, name.c_str(), &n);
  std::vector<double> v(n);
  if (status == detail::kHdf5Ok) status = f.h5.read_doubles(f.file, name.c_str(), v.data(), n);
  switch (status) {
    case detail::kHdf5Ok:
      return v;
    case detail::kHdf5NotOneDim:
      bad(o, path, fmt::format("dataset '/{}' must be one-dimensional", name));
    case detail::kHdf5CannotOpen:
      bad(o, path, fmt::format("dataset '/{}' cannot be opened", name));
    default:
      bad(o, path, fmt::format("dataset '/{}' cannot be read as numbers (truncated file?)", name));
  }
}

ProbeRecord readHdf5(const fs::path& path, const RecordReadOptions& o) {
  const detail::Hdf5ModuleApi& h5 = detail::hdf5Module();
  const std::lock_guard<std::mutex> lock(hdf5Mutex());
  const std::int64_t handle = h5.open(path.c_str());
  if (handle == -detail::kHdf5NotHdf5) bad(o, path, "is not an HDF5 file (or is truncated)");
  if (handle < 0) bad(o, path, "cannot be opened as HDF5 (truncated?)");
  const Hdf5Reading f{h5, handle};
  ProbeRecord r;
  std::optional<double> rate;
  if (h5.has_attribute(f.file, "sample_rate")) {
    double value = 0.0;
    if (h5.read_number_attribute(f.file, "sample_rate", &value) != detail::kHdf5Ok)
      bad(o, path, "attribute 'sample_rate' cannot be read");
    if (!(value > 0.0) || !std::isfinite(value)) {
      bad(o, path, fmt::format("attribute sample_rate = {:g}: must be > 0 [Hz]", value));
    }
    rate = value;
  } else if (h5.has_dataset(f.file, "time")) {
    const auto t = readDataset(f, "time", path, o);
    rate = rateFromTime(o, path, t);
    r.start_time = t.front();
  }
  r.sample_rate = agreeRate(o, path, rate);
  for (const auto& name : o.channels) {
    r.names.push_back(name);
    r.channels.push_back(readDataset(f, name, path, o));
    for (double& v : r.channels.back()) v *= o.scale;
  }
  return r;
}

std::string csvText(const ProbeRecord& r) {
  std::string s = "t_s";
  for (std::size_t c = 0; c < r.names.size(); ++c) {
    const bool unit = c < r.units.size() && !r.units[c].empty();
    s += "," + r.names[c] + (unit ? "_" + r.units[c] : std::string());
  }
  s += "\n";
  for (std::size_t i = 0; i < r.samples(); ++i) {
    s += fmt::format("{}", r.start_time + static_cast<double>(i) / r.sample_rate);
    for (const auto& c : r.channels) s += fmt::format(",{}", c[i]);
    s += "\n";
  }
  return s;
}

void put(std::string& s, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

std::string wavBytes(const ProbeRecord& r) {
  const std::uint64_t channels = r.channels.size(), n = r.samples();
  const std::uint64_t data = n * channels * 8;
  if (std::llround(r.sample_rate) != r.sample_rate || data + 36 > 0xFFFFFFFFull) {
    throw InputError("measurement.sample_rate", fmt::format("{:g}", r.sample_rate),
                     "WAV needs an integer sample rate [Hz] and less than 4 GiB of data");
  }
  std::string s = "RIFF";
  put(s, 36 + data, 4);
  s += "WAVEfmt ";
  put(s, 16, 4);
  put(s, 3, 2);  // IEEE float
  put(s, channels, 2);
  put(s, static_cast<std::uint64_t>(r.sample_rate), 4);
  put(s, static_cast<std::uint64_t>(r.sample_rate) * channels * 8, 4);
  put(s, channels * 8, 2);
  put(s, 64, 2);
  s += "data";
  put(s, data, 4);
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& c : r.channels) {
      std::uint64_t u;
      std::memcpy(&u, &c[i], 8);
      put(s, u, 8);
    }
  }
  return s;
}

void writeHdf5(const fs::path& path, const ProbeRecord& r) {
  detail::Hdf5Content content;
  content.attributes.push_back({"sample_rate", false, r.sample_rate, {}});
  for (std::size_t c = 0; c < r.channels.size(); ++c) {
    detail::Hdf5Dataset d;
    d.name = r.names[c];
    d.rows = r.samples();
    d.f64 = r.channels[c];
    content.datasets.push_back(std::move(d));
  }
  detail::writeHdf5File(path.string(), content);
}

}  // namespace

RecordFormat recordFormatOf(const fs::path& path, const std::string& key) {
  const std::string ext = lower(path.extension().string());
  if (ext == ".csv") return RecordFormat::kCsv;
  if (ext == ".wav") return RecordFormat::kWav;
  if (ext == ".h5" || ext == ".hdf5") return RecordFormat::kHdf5;
  throw InputError(key, path.string(), "a .csv, .wav, .h5 or .hdf5 file");
}

std::string toString(RecordFormat format) {
  switch (format) {
    case RecordFormat::kCsv:
      return "csv";
    case RecordFormat::kWav:
      return "wav";
    case RecordFormat::kHdf5:
      return "hdf5";
  }
  return "unknown";
}

const std::vector<double>& ProbeRecord::channel(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return channels[i];
  throw InputError("input.channels", name, "is not a channel of the record");
}

ProbeRecord readProbeRecord(const fs::path& path, const RecordReadOptions& options) {
  if (!fs::is_regular_file(path)) bad(options, path, "does not exist or is not a file");
  if (options.channels.empty())
    throw InputError("input.channels", "[]", "name at least one channel");
  if (!(std::isfinite(options.scale) && options.scale != 0.0)) {
    throw InputError("input.scale", fmt::format("{:g}", options.scale), "finite and not 0");
  }
  if (options.sample_rate && !(*options.sample_rate > 0.0 && std::isfinite(*options.sample_rate))) {
    throw InputError("input.sample_rate", fmt::format("{:g}", *options.sample_rate),
                     "must be finite and > 0 [Hz]");
  }
  ProbeRecord r;
  switch (recordFormatOf(path, options.key)) {
    case RecordFormat::kCsv:
      r = readCsv(path, options);
      break;
    case RecordFormat::kWav:
      r = readWav(path, options);
      break;
    case RecordFormat::kHdf5:
      r = readHdf5(path, options);
      break;
  }
  for (std::size_t c = 1; c < r.channels.size(); ++c) {
    if (r.channels[c].size() != r.channels[0].size()) {
      bad(options, path,
          fmt::format("channel '{}' has {} samples, '{}' {}: truncated record?", r.names[c],
                      r.channels[c].size(), r.names[0], r.channels[0].size()));
    }
  }
  if (r.samples() < 2) bad(options, path, "holds fewer than two samples");
  checkFinite(options, path, r);
  return r;
}

void writeProbeRecord(const fs::path& path, RecordFormat format, const ProbeRecord& record) {
  switch (format) {
    case RecordFormat::kCsv:
      writeFileAtomic(path, csvText(record));
      break;
    case RecordFormat::kWav:
      writeFileAtomic(path, wavBytes(record));
      break;
    case RecordFormat::kHdf5:
      writeHdf5(path, record);
      break;
  }
}

}  // namespace geardyn::io
