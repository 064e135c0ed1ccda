#pragma once
/// \file
/// A solid beam meshed with 20-node hexahedra (C3D20, full integration: no hourglass modes on one
/// element through the section) as a CalculiX deck, for the housing tests: length along x,
/// rectangular section, its x = 0 end face clamped by *BOUNDARY (optional) and node sets ROOT, TIP
/// (the end faces) and MID (the node nearest the middle of the beam's axis).

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace geardyn::testing {

/// A new folder under the temporary directory, removed with everything in it at the end.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "geardyn-housing-test-XXXXXX").string();
    path = mkdtemp(pattern.data());
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

struct BeamDeck {
  double length = 1.0, width = 0.05, height = 0.05;  ///< [m]
  int nx = 20, ny = 2, nz = 2;                       ///< elements along x, y, z
  double E = 210e9, nu = 0.3, rho = 7850.0;          ///< [Pa], [-], [kg/m³]
  bool clamped = true;                               ///< *BOUNDARY on the x = 0 face
};

/// Writes the deck to `path` (SI units, no *STEP).
inline void writeBeamDeck(const BeamDeck& b, const std::filesystem::path& path) {
  std::ofstream out(path);
  const int gx = 2 * b.nx + 1, gy = 2 * b.ny + 1, gz = 2 * b.nz + 1;
  auto id = [&](int i, int j, int k) { return 1 + i + gx * (j + gy * k); };
  auto odd = [](int v) { return v % 2 != 0 ? 1 : 0; };
  out.precision(17);
  out << "*NODE, NSET=NALL\n";
  for (int k = 0; k < gz; ++k)
    for (int j = 0; j < gy; ++j)
      for (int i = 0; i < gx; ++i) {
        if (odd(i) + odd(j) + odd(k) > 1) continue;
        out << id(i, j, k) << ", " << b.length * i / (gx - 1) << ", "
            << b.width * (j / double(gy - 1) - 0.5) << ", " << b.height * (k / double(gz - 1) - 0.5)
            << "\n";
      }
  // C3D20 node order (CalculiX manual, "Three-dimensional elements"): corners, then the
  // mid-edge nodes of the bottom face, of the top face and of the vertical edges.
  static const int corner[20][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2},
                                    {2, 0, 2}, {2, 2, 2}, {0, 2, 2}, {1, 0, 0}, {2, 1, 0},
                                    {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2}, {1, 2, 2},
                                    {0, 1, 2}, {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};
  out << "*ELEMENT, TYPE=C3D20, ELSET=EALL\n";
  int e = 0;
  for (int ez = 0; ez < b.nz; ++ez)
    for (int ey = 0; ey < b.ny; ++ey)
      for (int ex = 0; ex < b.nx; ++ex) {
        out << ++e;
        for (int c = 0; c < 20; ++c) {
          // 16 entries a line at most: the element number and 15 nodes, then a continuation.
          out << (c == 15 ? ",\n" : ", ")
              << id(2 * ex + corner[c][0], 2 * ey + corner[c][1], 2 * ez + corner[c][2]);
        }
        out << "\n";
      }
  auto face = [&](const char* name, int i) {
    out << "*NSET, NSET=" << name << "\n";
    for (int k = 0; k < gz; ++k)
      for (int j = 0; j < gy; ++j)
        if (odd(j) + odd(k) <= 1) out << id(i, j, k) << ",\n";
  };
  face("ROOT", 0);
  face("TIP", gx - 1);
  out << "*NSET, NSET=MID\n" << id(2 * (b.nx / 2), 2 * (b.ny / 2), 2 * (b.nz / 2)) << "\n";
  out.precision(12);  // ccx reads a number of at most 20 characters: 12 digits, not 17
  out << "*MATERIAL, NAME=STEEL\n*ELASTIC\n"
      << b.E << ", " << b.nu << "\n*DENSITY\n"
      << b.rho << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n";
  if (b.clamped) out << "*BOUNDARY\nROOT, 1, 3\n";
}

}  // namespace geardyn::testing
