#include "doorplate_localization/mcl/localization_scan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

LaserScan Scan(int beams, float range = 2.0f) {
  LaserScan s;
  s.angle_min_rad = -M_PI;
  s.angle_increment_rad = 2.0 * M_PI / beams;
  s.min_range_m = 0.1;
  s.max_range_m = 10.0;
  s.ranges_m.assign(beams, range);
  return s;
}

TEST(ClassifyRange, FollowsRep117) {
  EXPECT_EQ(ClassifyRange(2.0f, 0.1, 10.0), BeamKind::kHit);
  EXPECT_EQ(ClassifyRange(kInf, 0.1, 10.0), BeamKind::kMaxRange);    // no echo
  EXPECT_EQ(ClassifyRange(10.0f, 0.1, 10.0), BeamKind::kMaxRange);   // at max range
  EXPECT_EQ(ClassifyRange(-kInf, 0.1, 10.0), BeamKind::kInvalid);    // too close
  EXPECT_EQ(ClassifyRange(std::nanf(""), 0.1, 10.0), BeamKind::kInvalid);
  EXPECT_EQ(ClassifyRange(0.05f, 0.1, 10.0), BeamKind::kInvalid);    // below the device minimum
}

TEST(SelectBeams, SpreadsLaserMaxBeamsEvenlyIncludingBothEnds) {
  const LaserScan s = Scan(360);
  const auto beams = SelectBeams(s, {});  // laser_max_beams 60
  ASSERT_EQ(beams.size(), 60u);
  EXPECT_NEAR(beams.front().angle_rad, -M_PI, 1e-12);
  EXPECT_NEAR(beams.back().angle_rad, -M_PI + 359 * s.angle_increment_rad, 1e-12);
  for (size_t i = 1; i < beams.size(); ++i) {
    const double gap = beams[i].angle_rad - beams[i - 1].angle_rad;
    EXPECT_GE(gap, 6.0 * s.angle_increment_rad - 1e-9);
    EXPECT_LE(gap, 7.0 * s.angle_increment_rad + 1e-9);
  }
}

TEST(SelectBeams, UsesEveryBeamOfAShortScan) {
  BeamSelectionOptions o;
  o.laser_max_beams = 500;
  EXPECT_EQ(SelectBeams(Scan(90), o).size(), 90u);
  o.laser_max_beams = 1;
  EXPECT_EQ(SelectBeams(Scan(90), o).size(), 1u);
}

TEST(SelectBeams, DropsInvalidBeamsAndMarksMaxRangeOnes) {
  LaserScan s = Scan(4);
  s.ranges_m = {std::nanf(""), kInf, 3.0f, -kInf};
  const auto beams = SelectBeams(s, {});
  ASSERT_EQ(beams.size(), 2u);
  EXPECT_EQ(beams[0].kind, BeamKind::kMaxRange);
  EXPECT_DOUBLE_EQ(beams[0].range_m, 10.0);
  EXPECT_EQ(beams[1].kind, BeamKind::kHit);
  EXPECT_DOUBLE_EQ(beams[1].range_m, 3.0);
}

TEST(SelectBeams, RangeOverridesNarrowTheScansInterval) {
  LaserScan s = Scan(2);
  s.ranges_m = {6.0f, 0.3f};
  BeamSelectionOptions o;
  o.laser_max_range_m = 5.0;  // amcl's laser_max_range
  o.laser_min_range_m = 0.5;
  const auto beams = SelectBeams(s, o);
  ASSERT_EQ(beams.size(), 1u);  // 0.3 m is now below the minimum
  EXPECT_EQ(beams[0].kind, BeamKind::kMaxRange);
  EXPECT_DOUBLE_EQ(beams[0].range_m, 5.0);
}

TEST(ValidateLocalizationScan, NamesTheBadField) {
  EXPECT_EQ(ValidateLocalizationScan(Scan(4)), "");
  LaserScan s = Scan(4);
  s.angle_increment_rad = 0.0;
  EXPECT_NE(ValidateLocalizationScan(s).find("angle_increment_rad"), std::string::npos);
  s = Scan(4);
  s.ranges_m.clear();
  EXPECT_NE(ValidateLocalizationScan(s).find("ranges_m"), std::string::npos);
  s = Scan(4);
  s.max_range_m = 0.05;
  EXPECT_NE(ValidateLocalizationScan(s).find("max_range_m"), std::string::npos);
  EXPECT_THROW(SelectBeams(s, {}), std::invalid_argument);
  s = Scan(4);
  s.ranges_m.assign(100001, 1.0f);  // issue 18: more than limits::kMaxScanBeams
  EXPECT_EQ(ValidateLocalizationScan(s),
            "LaserScan.ranges_m: 100001 beams, more than the limit of 100000 (limits::kMaxScanBeams)");
  s.ranges_m.resize(100000);
  EXPECT_EQ(ValidateLocalizationScan(s), "");
}

}  // namespace
}  // namespace doorplate_localization
