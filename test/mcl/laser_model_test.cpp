#include "doorplate_localization/mcl/laser_model.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace doorplate_localization {
namespace {

TEST(ParseBeamCombination, AcceptsTheTwoAmclVariants) {
  EXPECT_EQ(ParseBeamCombination("cube_sum"), BeamCombination::kAmclCubeSum);
  EXPECT_EQ(ParseBeamCombination("product"), BeamCombination::kProduct);
  try {
    ParseBeamCombination("sum");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("beam_combination"), std::string::npos);
  }
}

}  // namespace
}  // namespace doorplate_localization
