/// libFuzzer target (issue 34): arbitrary bytes as a REXS model — the first byte picks the form
/// (XML .rexs, JSON .rexsj, zipped .rexsz through a temporary file) — through the whole import:
/// parse, alias table, mapping to a gearbox description, the gearbox schema, and the gear-train
/// description a model would be built from. Bad input may only end in geardyn::InputError;
/// another exception, a crash, a sanitizer report, a time-out or running out of memory is a bug.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "geardyn/config/config.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/rexs_gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_gearbox.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "geardyn/io/rexs/rexs_vocabulary.h"

namespace {

geardyn::io::rexs::Document readZipped(std::string_view bytes) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("libfuzzer_input_" + std::to_string(::getpid()) + ".rexsz");
  {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  struct Remove {
    std::filesystem::path path;
    ~Remove() { std::filesystem::remove(path); }
  } remove{path};
  return geardyn::io::rexs::readRexsZip(path);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  namespace rexs = geardyn::io::rexs;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  static const geardyn::config::ConfigSchema schema = geardyn::config::gearboxSchema();
  try {
    rexs::Document document = data[0] % 3 == 0   ? rexs::parseRexsXml(bytes, "fuzz.rexs")
                              : data[0] % 3 == 1 ? rexs::parseRexsJson(bytes, "fuzz.rexsj")
                                                 : readZipped(bytes);
    std::vector<std::string> warnings;
    rexs::normalize(document, warnings);
    const rexs::RexsImport imported = geardyn::config::importRexsGearbox(document);
    const auto config = geardyn::config::parseConfig(imported.toml, "fuzz", schema);
    const auto spec = geardyn::config::gearTrainFromConfig(config, warnings);
    volatile std::size_t shafts = spec.shafts.size();
    (void)shafts;
  } catch (const geardyn::InputError&) {
    // the expected outcome for bad input
  }
  return 0;
}
