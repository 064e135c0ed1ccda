#include "geardyn/stiffness/foundation_fit_note.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "geardyn/notes.h"

namespace geardyn {
namespace {

constexpr std::string_view kWhat = "Sainsot's (2004) fillet-foundation fit is extrapolated";
constexpr std::string_view kChange = "the mean mesh stiffness changes by ";

}  // namespace

std::string foundationFitWarning(const std::string& detail, double mean_stiffness_change) {
  return fmt::format(
      "{}{} ({}): held at its data range {}{:+.2f} %, so read k̄ as uncertain by about that much",
      kNotePrefix, kWhat, detail, kChange, 100.0 * mean_stiffness_change);
}

std::optional<FoundationFitExtrapolation> parseFoundationFitWarning(std::string_view warning) {
  if (isNote(warning)) warning.remove_prefix(kNotePrefix.size());
  const std::size_t what = warning.find(std::string(kWhat) + " (");
  if (what == std::string_view::npos) return std::nullopt;
  FoundationFitExtrapolation out;
  if (what > 0) {
    const std::string_view subject = warning.substr(0, what);
    if (subject.size() < 2 || subject.substr(subject.size() - 2) != ": ") return std::nullopt;
    out.subject = std::string(subject.substr(0, subject.size() - 2));
  }
  // The detail is the parenthesis after kWhat; it holds parentheses of its own ("(data ...)").
  const std::size_t open = what + kWhat.size() + 1;
  int depth = 0;
  std::size_t close = open;
  for (; close < warning.size(); ++close) {
    if (warning[close] == '(') ++depth;
    if (warning[close] == ')' && --depth == 0) break;
  }
  if (close >= warning.size()) return std::nullopt;
  out.detail = std::string(warning.substr(open + 1, close - open - 1));
  if (out.detail.starts_with("pinion: ")) out.members.push_back("pinion");
  if (out.detail.starts_with("gear: ") || out.detail.find("; gear: ") != std::string::npos) {
    out.members.push_back("gear");
  }
  const std::size_t change = warning.find(kChange, close);
  if (change == std::string_view::npos) return std::nullopt;
  const std::string number(warning.substr(change + kChange.size(), 16));
  char* end = nullptr;
  const double percent = std::strtod(number.c_str(), &end);
  if (end == number.c_str()) return std::nullopt;
  // Printed to 1e-4 (two decimals of a per cent): the nearest double to that, not percent/100.
  out.mean_stiffness_change = std::round(percent * 100.0) / 1e4;
  return out;
}

std::string foundationFitSummaryLine(const std::vector<FoundationFitExtrapolation>& notes,
                                     int max_named) {
  if (notes.empty()) return "";
  const FoundationFitExtrapolation* largest = &notes.front();
  std::string named;
  const int n = static_cast<int>(notes.size());
  for (int i = 0; i < n; ++i) {
    const FoundationFitExtrapolation& note = notes[i];
    if (std::abs(note.mean_stiffness_change) > std::abs(largest->mean_stiffness_change)) {
      largest = &note;
    }
    if (i >= max_named) continue;
    std::string members;
    for (const std::string& m : note.members) members += (members.empty() ? "" : " and ") + m;
    named += fmt::format("{}{}: {}", i ? "; " : "", note.subject.empty() ? "pair" : note.subject,
                         members.empty() ? "?" : members);
  }
  if (n > max_named) named += fmt::format("; {} more", n - max_named);
  return fmt::format(
      "{}{} for {} meshes ({}): held at its data range {}up to {:+.2f} % ({}), so read k̄ as "
      "uncertain by up to that much; each mesh's coefficients in summary.json "
      "(foundation_fit_extrapolated)",
      kNotePrefix, kWhat, n, named, kChange, 100.0 * largest->mean_stiffness_change,
      largest->subject.empty() ? "pair" : largest->subject);
}

}  // namespace geardyn
