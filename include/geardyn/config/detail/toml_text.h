#pragma once
/// \file
/// Numbers as TOML text that reads back exactly, for the gearbox descriptions the older file
/// forms translate into (fe_rotor_gearbox.h, rotor_gearbox.h).

#include <fmt/format.h>

#include <string>
#include <vector>

namespace geardyn::config::detail {

/// A TOML float that reads back as the same double: fmt's shortest round-trip form, with ".0"
/// when it would read as an integer (n: inf, nan).
inline std::string tomlReal(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

/// A TOML array of such floats.
inline std::string tomlReals(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + tomlReal(v[i]);
  return out + "]";
}

}  // namespace geardyn::config::detail
