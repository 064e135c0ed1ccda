#pragma once
/// \file
/// An HDF5 file as plain data (datasets and root attributes) and its atomic writer. The HDF5
/// library itself is only loaded on the first call (src/io/hdf5_module.h: libgeardyn_hdf5.so).

#include <cstdint>
#include <string>
#include <vector>

namespace geardyn::io {

/// A dataset to write: 1-D (cols == 0) or 2-D row-major, of one element type.
struct Hdf5Dataset {
  enum class Type { kFloat64, kInt64, kUInt64, kString };
  std::string name;
  Type type = Type::kFloat64;
  std::uint64_t rows = 0, cols = 0;
  std::vector<double> f64;
  std::vector<std::int64_t> i64;
  std::vector<std::uint64_t> u64;
  std::vector<std::string> text;  ///< variable-length UTF-8
};

/// A root attribute: a number (one float64, stored as a 1-element array) or a UTF-8 string.
struct Hdf5Attribute {
  std::string name;
  bool is_text = false;
  double number = 0.0;
  std::string text;
};

/// A whole file: root attributes (written first), then datasets at the root.
struct Hdf5Content {
  std::vector<Hdf5Attribute> attributes;
  std::vector<Hdf5Dataset> datasets;
};

/// Writes `content` to `path` atomically (temporary file beside it, then rename) under
/// hdf5Mutex(); IoError naming the path on failure.
void writeHdf5File(const std::string& path, const Hdf5Content& content);

}  // namespace geardyn::io
