/// The table of analysis commands. A new command adds one line here and one *_command.cpp.

#include "command.h"
#include "geardyn/io/geometry_io.h"

namespace geardyn::cli {

int runGeometry(const io::Config& config, const CommandOptions& options);

std::vector<Command> allCommands() {
  return {
      {"geometry", "involute gear-pair geometry: radii, contact ratios, checks, mass properties",
       io::geometrySchema, runGeometry},
  };
}

}  // namespace geardyn::cli
