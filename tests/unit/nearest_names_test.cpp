// The names nearest a mistyped case name (apps/case/input/nearest_names.hpp).
#include "apps/case/input/nearest_names.hpp"

#include <gtest/gtest.h>

namespace flexmoor::app {
namespace {

using Names = std::vector<std::string>;

TEST(NearestNames, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(editDistance("", ""), 0);
  EXPECT_EQ(editDistance("abc", ""), 3);
  EXPECT_EQ(editDistance("", "abc"), 3);
  EXPECT_EQ(editDistance("oc4-semi-surg", "oc4-semi-surge"), 1);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3);
  EXPECT_EQ(editDistance("flaw", "lawn"), 2);
  EXPECT_EQ(editDistance("ex8-relaxation-test", "ex8-relaxation-test"), 0);
}

TEST(NearestNames, TheNearestWithinAThirdOfTheNameElseThoseContainingIt) {
  const Names cases = {"ex8-relaxation-test", "ex9-submerged-tube", "oc3-hywind-statics",
                       "oc3-hywind-surge",    "oc4-semi-statics",   "oc4-semi-surge"};
  EXPECT_EQ(nearestNames("oc4-semi-surg", cases), Names{"oc4-semi-surge"});
  EXPECT_EQ(nearestNames("oc4-semi-srge", cases), Names{"oc4-semi-surge"});
  EXPECT_EQ(nearestNames("oc3-hywind-sturge", cases), Names{"oc3-hywind-surge"});
  EXPECT_EQ(nearestNames("ex8", cases), Names{"ex8-relaxation-test"});
  EXPECT_EQ(nearestNames("oc3-hywind", cases), (Names{"oc3-hywind-statics", "oc3-hywind-surge"}));
  EXPECT_TRUE(nearestNames("zzz", cases).empty());
  EXPECT_TRUE(nearestNames("", cases).empty());
  EXPECT_EQ(nearestNames("oc", cases, 2), (Names{"oc3-hywind-statics", "oc3-hywind-surge"}));
}

TEST(NearestNames, DidYouMeanListsThem) {
  EXPECT_EQ(didYouMean({}), "");
  EXPECT_EQ(didYouMean({"a"}), "; did you mean 'a'?");
  EXPECT_EQ(didYouMean({"a", "b"}), "; did you mean 'a' or 'b'?");
  EXPECT_EQ(didYouMean({"a", "b", "c"}), "; did you mean 'a', 'b' or 'c'?");
}

}  // namespace
}  // namespace flexmoor::app
