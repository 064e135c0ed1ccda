/// A housing from its deck to its cached Craig–Bampton model (housing_source.h).

#include "geardyn/config/housing_source.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"
#include "geardyn/io/calculix_deck.h"

namespace geardyn::config {
namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'G', 'D', 'H', 'O', 'U', 'S', '2', '\0'};

struct Fnv1a {
  std::uint64_t h = 0xcbf29ce484222325ull;
  void add(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  }
  void add(const std::string& s) { add(s.data(), s.size() + 1); }
  void add(double v) { add(&v, sizeof v); }
};

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("housing.deck", path, "an existing, readable CalculiX deck (.inp)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class Writer {
 public:
  void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  void count(std::int64_t n) { raw(&n, sizeof n); }
  void text(const std::string& s) {
    count(static_cast<std::int64_t>(s.size()));
    raw(s.data(), s.size());
  }
  void matrix(const Eigen::MatrixXd& A) {
    count(A.rows());
    count(A.cols());
    raw(A.data(), sizeof(double) * static_cast<std::size_t>(A.size()));
  }
  const std::string& bytes() const { return out_; }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string bytes) : in_(std::move(bytes)) {}
  void raw(void* p, std::size_t n) {
    if (at_ + n > in_.size()) throw std::runtime_error("truncated");
    std::memcpy(p, in_.data() + at_, n);
    at_ += n;
  }
  std::int64_t count() {
    std::int64_t n = 0;
    raw(&n, sizeof n);
    if (n < 0 || static_cast<std::size_t>(n) > in_.size()) throw std::runtime_error("bad size");
    return n;
  }
  std::string text() {
    std::string s(static_cast<std::size_t>(count()), '\0');
    raw(s.data(), s.size());
    return s;
  }
  Eigen::MatrixXd matrix() {
    const std::int64_t r = count(), c = count();
    Eigen::MatrixXd A(r, c);
    raw(A.data(), sizeof(double) * static_cast<std::size_t>(A.size()));
    return A;
  }
  bool done() const { return at_ == in_.size(); }

 private:
  std::string in_;
  std::size_t at_ = 0;
};

std::string serialise(const ReducedHousing& h) {
  Writer w;
  w.raw(kMagic, sizeof kMagic);
  w.matrix(h.K);
  w.matrix(h.M);
  w.matrix(h.mode_frequencies_hz);
  w.matrix(h.recovery);
  w.count(static_cast<std::int64_t>(h.residual_vectors));
  w.count(static_cast<std::int64_t>(h.seats.size()));
  for (std::size_t s = 0; s < h.seats.size(); ++s) {
    w.text(h.seats[s]);
    w.matrix(h.centres[s]);
  }
  w.count(static_cast<std::int64_t>(h.points.size()));
  for (const std::string& p : h.points) w.text(p);
  return w.bytes();
}

/// The cached model, or false when the file is absent or not a whole cache file.
bool deserialise(const fs::path& path, ReducedHousing& h) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  try {
    Reader r(s.str());
    char magic[8];
    r.raw(magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof magic) != 0) return false;
    h.K = r.matrix();
    h.M = r.matrix();
    h.mode_frequencies_hz = r.matrix();
    h.recovery = r.matrix();
    h.residual_vectors = r.count();
    for (std::int64_t s = r.count(); s > 0; --s) {
      h.seats.push_back(r.text());
      h.centres.push_back(r.matrix());
    }
    for (std::int64_t p = r.count(); p > 0; --p) h.points.push_back(r.text());
    return r.done();
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<HousingNodeSet> namedSets(const io::CalculixDeck& deck,
                                      const std::vector<std::string>& names, const std::string& key,
                                      const std::string& deck_path) {
  std::vector<std::string> known;
  for (const auto& [name, nodes] : deck.nsets) known.push_back(name);
  std::vector<HousingNodeSet> sets;
  for (const std::string& name : names) {
    std::string upper = name;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const auto it = deck.nsets.find(upper);
    if (it == deck.nsets.end()) {
      const auto match = closestMatch(upper, known);
      throw InputError(key, "\"" + name + "\"",
                       fmt::format("a node set (*NSET) of {}{}", deck_path,
                                   match ? " (did you mean \"" + *match + "\"?)" : ""));
    }
    sets.push_back({name, it->second});
  }
  return sets;
}

/// The elastic mounts' springs to the ground [N/m, SI] on K's diagonal: each set's total
/// stiffness spread evenly over its nodes, in x, y and z.
void addElasticMounts(io::FeMatrices& fe, const io::CalculixDeck& deck,
                      const HousingSource& source) {
  if (source.elastic_mounts.empty()) return;
  std::map<int, double> per_node;  // node -> spring [N/m]
  for (const auto& [set, k] : source.elastic_mounts) {
    if (!(k > 0.0) || !std::isfinite(k)) {
      throw InputError("housing.mounts." + set + ".stiffness", fmt::format("{:g} N/m", k),
                       "a finite stiffness > 0 N/m (absent: a fixed mount)");
    }
    const std::vector<int> nodes =
        namedSets(deck, {set}, "housing.mounts." + set, source.deck)[0].nodes;
    for (int node : nodes) per_node[node] += k / static_cast<double>(nodes.size());
  }
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(fe.dofs.size()); ++i) {
    const auto it = per_node.find(fe.dofs[static_cast<std::size_t>(i)].node);
    if (it != per_node.end()) fe.K.coeffRef(i, i) += it->second;
  }
}

}  // namespace

std::string housingCacheKey(const HousingSource& source) {
  Fnv1a h;
  const std::string bytes = readBytes(source.deck);
  h.add(bytes.data(), bytes.size());
  h.add(source.units);
  for (const std::string& s : source.seats) h.add("seat:" + s);
  for (const std::string& p : source.points) h.add("point:" + p);
  for (const std::string& f : source.fixed_mounts) h.add("fixed:" + f);
  for (const auto& [set, k] : source.elastic_mounts) h.add("elastic:" + set), h.add(k);
  for (const std::string* f : {&source.stiffness_matrix, &source.mass_matrix, &source.dof_map}) {
    h.add("mm:" + *f);
    if (!f->empty()) {
      const std::string b = readBytes(*f);
      h.add(b.data(), b.size());
    }
  }
  h.add(source.reduction.cutoff_hz);
  h.add(static_cast<double>(source.reduction.modes));
  h.add(std::string(source.reduction.residual_vectors ? "residual vectors" : "classic"));
  return fmt::format("{:016x}", h.h);
}

LoadedHousing loadHousing(const HousingSource& source) {
  const FeUnits units = feUnits(source.units, "housing.units");
  LoadedHousing out;
  const fs::path cache =
      fs::path(source.deck).string() + ".reduced-" + housingCacheKey(source) + ".bin";
  if (deserialise(cache, out.housing)) {
    out.cache_file = cache.string();
    out.from_cache = true;
    return out;
  }
  io::CalculixDeck deck = io::readCalculixDeck(source.deck, "housing.deck");
  if (deck.has_step) {
    throw InputError("housing.deck", source.deck,
                     "a deck without *STEP (mesh, material, *BOUNDARY): geardyn adds the step "
                     "that stores K and M");
  }
  if (source.memory_limit_bytes > 0.0) {
    io::checkHousingFits(deck, source.deck, "housing.deck", source.memory_limit_bytes);
  }
  const std::vector<HousingNodeSet> seats =
      namedSets(deck, source.seats, "housing.seats", source.deck);
  const std::vector<HousingNodeSet> points =
      namedSets(deck, source.points, "housing.points", source.deck);
  for (const auto& [set, k] : source.elastic_mounts) {
    namedSets(deck, {set}, "housing.mounts." + set, source.deck);
  }
  for (const std::string& set : source.fixed_mounts) {
    namedSets(deck, {set}, "housing.mounts." + set, source.deck);
  }
  const auto assembly = std::chrono::steady_clock::now();
  io::FeMatrices fe = source.stiffness_matrix.empty()
                          ? io::runCalculix(source.deck, "housing.deck", "ccx", source.fixed_mounts)
                          : io::readMatrixMarketModel(source.stiffness_matrix, source.mass_matrix,
                                                      source.dof_map, "housing.stiffness_matrix");
  out.assembly_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - assembly).count();
  scaleToSi(fe, deck.nodes, units);
  addElasticMounts(fe, deck, source);
  out.housing = reduceHousing(fe, deck.nodes, seats, points, source.reduction);
  try {
    io::writeFileAtomic(cache, serialise(out.housing), false);
    out.cache_file = cache.string();
  } catch (const IoError&) {
    // A read-only folder: the reduction stays in memory (see the file comment).
  }
  return out;
}

}  // namespace geardyn::config
