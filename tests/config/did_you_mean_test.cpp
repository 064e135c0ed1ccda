#include "geardyn/config/did_you_mean.h"

#include <gtest/gtest.h>

namespace geardyn::config {
namespace {

TEST(DidYouMean, EditDistance) {
  EXPECT_EQ(editDistance("module", "module"), 0);
  EXPECT_EQ(editDistance("modul", "module"), 1);
  EXPECT_EQ(editDistance("mdoule", "module"), 1);  // transposition
  EXPECT_EQ(editDistance("", "abc"), 3);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3);
}

TEST(DidYouMean, SuggestsOnlyPlausibleMatches) {
  const std::vector<std::string> keys = {"teeth", "module", "pressure_angle_deg", "face_width"};
  EXPECT_EQ(closestMatch("modul", keys).value_or(""), "module");
  EXPECT_EQ(closestMatch("teath", keys).value_or(""), "teeth");
  EXPECT_EQ(closestMatch("pressure", keys).value_or(""), "pressure_angle_deg");
  EXPECT_EQ(closestMatch("facewidth", keys).value_or(""), "face_width");
  EXPECT_FALSE(closestMatch("colour", keys).has_value());
}

}  // namespace
}  // namespace geardyn::config
