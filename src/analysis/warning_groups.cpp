#include "geardyn/analysis/warning_groups.h"

#include <cctype>
#include <map>
#include <set>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/stiffness/foundation_fit_note.h"

namespace geardyn::analysis {
namespace {

struct Parts {
  std::string subject;  ///< before the first ": " (empty when there is none)
  std::string kind;     ///< the rest with its numbers masked
};

/// The text with every number (digits, with a sign, decimals and an exponent) replaced by #
/// and every parenthesised detail by "(…)": warnings of one kind differ in their numbers and in
/// the details they give ("(pinion: M* = 1.07; gear: L* = 6.9)" against "(pinion: M* = 1.03)").
std::string masked(std::string_view text) {
  std::string out;
  int depth = 0;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '(' || (depth > 0 && text[i] == ')')) {
      depth += text[i] == '(' ? 1 : -1;
      if (depth == (text[i] == '(' ? 1 : 0)) out += text[i] == '(' ? "(…" : ")";
      ++i;
      continue;
    }
    if (depth > 0) {
      ++i;
      continue;
    }
    const auto digit = [&](std::size_t k) {
      return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]));
    };
    const bool sign = (text[i] == '+' || text[i] == '-') && digit(i + 1);
    if (digit(i) || sign) {
      i += sign ? 1 : 0;
      while (digit(i) || (i < text.size() && text[i] == '.' && digit(i + 1))) ++i;
      if (i + 1 < text.size() && (text[i] == 'e' || text[i] == 'E') &&
          (digit(i + 1) || ((text[i + 1] == '-' || text[i + 1] == '+') && digit(i + 2)))) {
        i += 2;
        while (digit(i)) ++i;
      }
      out += '#';
    } else {
      out += text[i++];
    }
  }
  return out;
}

Parts partsOf(const std::string& warning) {
  std::string_view text = warning;
  std::string prefix;
  if (text.substr(0, kNotePrefix.size()) == kNotePrefix) {
    prefix = kNotePrefix;
    text.remove_prefix(kNotePrefix.size());
  }
  const std::size_t colon = text.find(": ");
  if (colon == std::string_view::npos) return {"", prefix + masked(text)};
  return {std::string(text.substr(0, colon)), prefix + masked(text.substr(colon + 2))};
}

}  // namespace

std::vector<std::string> groupedWarnings(const std::vector<std::string>& given, int max_named) {
  // Sainsot's fit extrapolated on several meshes: one line naming them and the largest change
  // of k̄ (issue #34), where the first of them stood.
  std::vector<std::string> warnings;
  std::vector<FoundationFitExtrapolation> fits;
  std::size_t fits_at = 0;
  std::set<std::string> fit_texts;  // exact repeats are dropped
  for (const std::string& w : given) {
    auto fit = parseFoundationFitWarning(w);
    if (!fit) {
      warnings.push_back(w);
      continue;
    }
    if (!fit_texts.insert(w).second) continue;
    if (fits.empty()) fits_at = warnings.size();
    fits.push_back(std::move(*fit));
    if (fits.size() == 1) warnings.push_back(w);
  }
  if (fits.size() > 1) warnings[fits_at] = foundationFitSummaryLine(fits, max_named);

  struct Group {
    std::string first;
    std::vector<std::string> others;  ///< subjects of the later ones
  };
  std::vector<Group> groups;
  std::map<std::string, std::size_t> by_kind;  // kind (or the whole text) -> group
  std::set<std::string> shown;                 // exact repeats are dropped
  for (const std::string& w : warnings) {
    if (!shown.insert(w).second) continue;
    const Parts p = partsOf(w);
    // Without a subject only identical texts are of one kind.
    const std::string key = p.subject.empty() ? "\n" + w : p.kind;
    const auto [it, added] = by_kind.emplace(key, groups.size());
    if (added) {
      groups.push_back({w, {}});
      continue;
    }
    Group& g = groups[it->second];
    bool named = p.subject == partsOf(g.first).subject;
    for (const auto& s : g.others) named = named || s == p.subject;
    // A subject the group already names, with other values: its own line (never hidden).
    if (named) {
      groups.push_back({w, {}});
    } else {
      g.others.push_back(p.subject);
    }
  }
  std::vector<std::string> out;
  for (const Group& g : groups) {
    if (g.others.empty()) {
      out.push_back(g.first);
      continue;
    }
    std::string names;
    const int n = static_cast<int>(g.others.size());
    for (int i = 0; i < n && i < max_named; ++i) names += (i ? ", " : "") + g.others[i];
    if (n > max_named) names += ", …";
    out.push_back(g.first + " (the same for " + std::to_string(n) + " more: " + names +
                  "; each in summary.json)");
  }
  return out;
}

void AnalysisContext::warnings(const std::vector<std::string>& texts) const {
  if (!warn) return;
  for (const std::string& line : groupedWarnings(texts)) warn(line);
}

}  // namespace geardyn::analysis
