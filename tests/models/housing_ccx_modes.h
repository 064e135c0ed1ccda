#pragma once
/// \file
/// The full finite-element model's own natural frequencies from CalculiX (`*FREQUENCY`), the
/// independent reference of the housing's Craig–Bampton reduction (issue #37, validation): the
/// deck is included as it stands, each seat's node set is tied to a reference node by
/// `*RIGID BODY, NSET=..., REF NODE=..., ROT NODE=...` (CalculiX CrunchiX User's Manual, ccx
/// 2.20, *RIGID BODY: the rigid tie geardyn's reduction makes, u_n = u_r + θ × (x_n − x_r),
/// linearised in a linear step), the fixed sets get a `*BOUNDARY`, and ccx's Lanczos solver
/// (ARPACK) finds the lowest `count` modes. The eigenvalues are read from job.dat's
/// "E I G E N V A L U E   O U T P U T" table (ccx prints 7 significant digits: ω² to 1e-7,
/// f to 5e-8 relative).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace geardyn::testing {

/// Frequencies [Hz] of the lowest `count` modes of the deck at `deck` with `seats` tied rigidly
/// (the seats' node coordinates from `nodes`, in the deck's units) and `fixed` held; ccx runs in
/// `folder`. Fails the test (empty result) when ccx does not finish.
inline std::vector<double> ccxFrequenciesHz(const std::filesystem::path& deck,
                                            const std::map<int, Eigen::Vector3d>& nodes,
                                            const std::map<std::string, std::vector<int>>& seats,
                                            const std::vector<std::string>& fixed, int count,
                                            const std::filesystem::path& folder) {
  int next = nodes.rbegin()->first + 1;
  std::ostringstream job;
  job.precision(12);  // ccx reads a number of at most 20 characters
  job << "*INCLUDE, INPUT=" << std::filesystem::absolute(deck).string() << "\n";
  for (const auto& [name, members] : seats) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : members) c += nodes.at(n);
    c /= static_cast<double>(members.size());
    const int ref = next++, rot = next++;
    job << "*NODE\n"
        << ref << ", " << c.x() << ", " << c.y() << ", " << c.z() << "\n"
        << rot << ", " << c.x() << ", " << c.y() << ", " << c.z() << "\n"
        << "*RIGID BODY, NSET=" << name << ", REF NODE=" << ref << ", ROT NODE=" << rot << "\n";
  }
  for (const std::string& set : fixed) job << "*BOUNDARY\n" << set << ", 1, 3\n";
  job << "*STEP\n*FREQUENCY\n" << count << "\n*END STEP\n";
  std::ofstream(folder / "ccxref.inp") << job.str();
  const std::string command = "cd '" + folder.string() + "' && ccx -i ccxref > ccxref.log 2>&1";
  if (std::system(command.c_str()) != 0) {
    ADD_FAILURE() << "ccx *FREQUENCY failed, see " << (folder / "ccxref.log");
    return {};
  }
  std::ifstream dat(folder / "ccxref.dat");
  std::string line;
  while (std::getline(dat, line) && line.find("E I G E N V A L U E   O U T P U T") == line.npos) {
  }
  std::vector<double> hz;
  while (std::getline(dat, line) && static_cast<int>(hz.size()) < count) {
    std::istringstream in(line);
    int mode = 0;
    double eigenvalue = 0.0;
    if (in >> mode >> eigenvalue && mode == static_cast<int>(hz.size()) + 1) {
      hz.push_back(std::sqrt(std::max(eigenvalue, 0.0)) / (2.0 * std::numbers::pi));
    }
  }
  EXPECT_EQ(static_cast<int>(hz.size()), count) << "eigenvalues in " << (folder / "ccxref.dat");
  return hz;
}

}  // namespace geardyn::testing
