/// sweep.h5, the gathered results of `geardyn sweep` (see sweep_io.h), written through the HDF5
/// module that is loaded on demand (geardyn/io/hdf5_file.h).

#include <limits>

#include "geardyn/analysis/sweep_results.h"
#include "geardyn/config/sweep_config.h"
#include "geardyn/io/hdf5_file.h"
#include "geardyn/version.h"

namespace geardyn::analysis {
namespace fs = std::filesystem;

void writeSweepHdf5(const fs::path& path, const config::SweepDefinition& study,
                    const std::vector<SweepCaseRecord>& records, const std::string& base_config) {
  using Type = io::Hdf5Dataset::Type;
  const std::uint64_t n = records.size(), np = study.parameters.size(), no = study.outputs.size();
  const auto dataset = [](const char* name, Type type, std::uint64_t rows, std::uint64_t cols) {
    io::Hdf5Dataset d;
    d.name = name, d.type = type, d.rows = rows, d.cols = cols;
    return d;
  };
  io::Hdf5Dataset index = dataset("case", Type::kInt64, n, 0),
                  seeds = dataset("seed", Type::kUInt64, n, 0),
                  status = dataset("status", Type::kString, n, 0),
                  message = dataset("message", Type::kString, n, 0),
                  params = dataset("parameters", Type::kFloat64, n, np),
                  text = dataset("parameter_text", Type::kString, n, np),
                  outputs = dataset("outputs", Type::kFloat64, n, no),
                  pnames = dataset("parameter_names", Type::kString, np, 0),
                  onames = dataset("output_names", Type::kString, no, 0);
  for (const auto& r : records) {
    index.i64.push_back(r.index);
    seeds.u64.push_back(r.seed);
    status.text.push_back(r.status);
    message.text.push_back(r.message);
    for (const auto& v : r.values) {
      params.f64.push_back(v.is_number() ? v.get<double>()
                                         : std::numeric_limits<double>::quiet_NaN());
      text.text.push_back(v.is_string() ? v.get<std::string>() : v.dump());
    }
    outputs.f64.insert(outputs.f64.end(), r.outputs.begin(), r.outputs.end());
  }
  for (const auto& p : study.parameters) pnames.text.push_back(p.key);
  for (const auto& o : study.outputs) onames.text.push_back(o.name);
  io::Hdf5Content content;
  content.attributes = {{"geardyn_version", true, 0.0, kVersion},
                        {"study", true, 0.0, study.resolved.dump()},
                        {"base_config", true, 0.0, base_config}};
  for (auto* d : {&index, &seeds, &status, &message, &params, &text, &outputs, &pnames, &onames})
    content.datasets.push_back(std::move(*d));
  io::writeHdf5File(path.string(), content);
}

}  // namespace geardyn::analysis
