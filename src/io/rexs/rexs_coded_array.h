#pragma once
/// Coded arrays of REXS ≥ 1.3: little-endian int32, float32 or float64 values, base64-encoded
/// (RFC 4648), in XML `<array code="float64">…</array>` and JSON `{"code": …, "value": …}`.

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace geardyn::io::rexs::detail {

/// The decoded numbers, or nullopt for an unknown code or text that is not base64 of whole
/// values.
inline std::optional<std::vector<double>> decodeCodedArray(const std::string& code,
                                                           const std::string& text) {
  std::vector<unsigned char> bytes;
  unsigned buffer = 0;
  int bits = 0;
  for (char ch : text) {
    int v = -1;
    if (ch >= 'A' && ch <= 'Z')
      v = ch - 'A';
    else if (ch >= 'a' && ch <= 'z')
      v = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9')
      v = ch - '0' + 52;
    else if (ch == '+')
      v = 62;
    else if (ch == '/')
      v = 63;
    else if (ch == '=' || ch == ' ' || ch == '\n' || ch == '\r' || ch == '\t')
      continue;
    else
      return std::nullopt;
    buffer = (buffer << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
    }
  }
  const std::size_t size = code == "float64" ? 8 : (code == "float32" || code == "int32") ? 4 : 0;
  if (size == 0 || bytes.size() % size != 0) return std::nullopt;
  std::vector<double> out;
  for (std::size_t i = 0; i < bytes.size(); i += size) {
    if (code == "float64") {
      double d;
      std::memcpy(&d, &bytes[i], 8);
      out.push_back(d);
    } else if (code == "float32") {
      float f;
      std::memcpy(&f, &bytes[i], 4);
      out.push_back(f);
    } else {
      std::int32_t n;
      std::memcpy(&n, &bytes[i], 4);
      out.push_back(n);
    }
  }
  return out;
}

}  // namespace geardyn::io::rexs::detail
