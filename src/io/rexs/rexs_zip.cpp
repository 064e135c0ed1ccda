/// Zipped REXS (.rexsz) with Debian's minizip (rexs_reader.h). minizip rather than libzip: it
/// needs only zlib (libzip pulls in libssl and libbz2 that the command line would map at every
/// start, issue 22), and a .rexsz is a plain zip archive with one model entry.

#include <fmt/format.h>
#include <minizip/unzip.h>

#include <algorithm>
#include <cctype>
#include <memory>
#include <string>

#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_reader.h"

namespace geardyn::io::rexs {

Document readRexsZip(const std::filesystem::path& file) {
  const std::string source = file.filename().string();
  std::unique_ptr<void, int (*)(unzFile)> zip(unzOpen64(file.string().c_str()), unzClose);
  if (!zip) throw InputError("REXS file", file.string(), "a readable zip archive (.rexsz)");
  for (int status = unzGoToFirstFile(zip.get()); status == UNZ_OK;
       status = unzGoToNextFile(zip.get())) {
    unz_file_info64 info;
    char name[1024];
    if (unzGetCurrentFileInfo64(zip.get(), &info, name, sizeof name, nullptr, 0, nullptr, 0) !=
        UNZ_OK)
      break;
    std::string entry = name;
    std::string lower = entry;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    const bool xml = lower.size() > 5 && lower.ends_with(".rexs");
    const bool json = lower.ends_with(".rexsj");
    if (!xml && !json) continue;
    // Neither the declared size nor the ratio is trusted (a zip bomb declares what it likes):
    // the entry is inflated in chunks and refused as soon as it passes kMaxRexsModelBytes.
    // 0xFFFFFFFF is the zip64 placeholder: minizip replaces it by the zip64 extra field's size
    // when there is one; left as it is, the entry's size is unknown, not 4 GiB.
    constexpr std::uint64_t kZip64Placeholder = 0xFFFFFFFFu;
    const bool declared = info.uncompressed_size != kZip64Placeholder;
    const auto too_large = [&](std::uint64_t bytes, const char* how) {
      return InputError(source + ": entry " + entry,
                        fmt::format("{:.1f} MiB uncompressed ({})", bytes / 1048576.0, how),
                        fmt::format("a REXS model of at most {} MiB uncompressed (the largest "
                                    "published gearbox models are a few MiB)",
                                    kMaxRexsModelBytes >> 20));
    };
    if (declared && info.uncompressed_size > kMaxRexsModelBytes)
      throw too_large(info.uncompressed_size, "its declared size");
    if (unzOpenCurrentFile(zip.get()) != UNZ_OK)
      throw InputError(source + ": entry " + entry, "", "an entry that can be decompressed");
    std::string text;
    if (declared) text.reserve(static_cast<std::size_t>(info.uncompressed_size));
    constexpr unsigned kChunk = 1u << 20;
    int read = 0;
    do {
      const std::size_t at = text.size();
      text.resize(at + kChunk);
      read = unzReadCurrentFile(zip.get(), text.data() + at, kChunk);
      text.resize(at + static_cast<std::size_t>(std::max(read, 0)));
      if (text.size() > kMaxRexsModelBytes) {
        unzCloseCurrentFile(zip.get());
        throw too_large(text.size(), "or more: inflating stopped there");
      }
    } while (read > 0);
    const int closed = unzCloseCurrentFile(zip.get());
    if (read < 0 || (declared && text.size() != info.uncompressed_size) || closed != UNZ_OK)
      throw InputError(source + ": entry " + entry, fmt::format("zip status {}", read),
                       "an intact zip entry (CRC or size mismatch: truncated archive?)");
    const std::string where = source + "/" + entry;
    return xml ? parseRexsXml(text, where) : parseRexsJson(text, where);
  }
  throw InputError("REXS file", file.string(),
                   "a zip archive that holds a .rexs or .rexsj model entry");
}

}  // namespace geardyn::io::rexs
