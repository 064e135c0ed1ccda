/// The REXS document model and the reader dispatch (rexs_document.h, rexs_reader.h).

#include "geardyn/io/rexs/rexs_document.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "geardyn/io/rexs/rexs_vocabulary.h"

namespace geardyn::io::rexs {

const Attribute* Component::find(const std::string& attribute_id) const {
  for (const auto& a : attributes)
    if (a.id == attribute_id) return &a;
  return nullptr;
}

std::string Component::label() const {
  return fmt::format("component {} ({}{})", id, type, name.empty() ? "" : " \"" + name + "\"");
}

std::optional<int> Relation::ref(const std::string& role) const {
  for (const auto& r : refs)
    if (r.role == role) return r.id;
  return std::nullopt;
}

const Component* Document::component(int id) const {
  for (const auto& c : components)
    if (c.id == id) return &c;
  return nullptr;
}

int Document::versionNumber() const {
  int major = 0, minor = 0;
  if (std::sscanf(version.c_str(), "%d.%d", &major, &minor) < 1) return 0;
  return major * 100 + minor;
}

void checkReferences(const Document& document) {
  std::map<int, const Component*> ids;
  for (const auto& c : document.components) {
    if (!ids.emplace(c.id, &c).second)
      throw InputError(fmt::format("{}: REXS component id {}", document.source, c.id), c.type,
                       "component ids must be unique in a model");
  }
  for (const auto& r : document.relations) {
    for (const auto& ref : r.refs) {
      if (!ids.count(ref.id)) {
        throw InputError(
            fmt::format("{}: REXS relation {} ({}) role {}", document.source, r.id, r.type,
                        ref.role),
            fmt::format("component {}{}", ref.id, ref.hint.empty() ? "" : " (" + ref.hint + ")"),
            "refers to a component that is not in the model");
      }
    }
  }
  for (const auto& lc : document.load_cases) {
    for (const auto& c : lc.components) {
      if (!ids.count(c.id))
        throw InputError(fmt::format("{}: REXS load case {}", document.source, lc.id),
                         fmt::format("component {} ({})", c.id, c.type),
                         "refers to a component that is not in the model");
    }
  }
}

bool isRexsPath(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext == ".rexs" || ext == ".rexsj" || ext == ".rexsz";
}

Document readRexsFile(const std::filesystem::path& file, std::vector<std::string>& warnings) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  Document document;
  if (ext == ".rexsz") {
    document = readRexsZip(file);
  } else {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError("REXS file", file.string(), "cannot be opened for reading");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    if (ext == ".rexsj") {
      document = parseRexsJson(text, file.filename().string());
    } else if (ext == ".rexs") {
      document = parseRexsXml(text, file.filename().string());
    } else {
      throw InputError("REXS file", file.string(), "a .rexs (XML), .rexsj (JSON) or .rexsz file");
    }
  }
  normalize(document, warnings);
  checkReferences(document);
  return document;
}

}  // namespace geardyn::io::rexs
