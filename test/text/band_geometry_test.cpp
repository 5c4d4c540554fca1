#include "doorplate_localization/text/band_geometry.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

// The simulator's camera: pinhole fy from the horizontal field of view, principal point at the centre.
BandGeometryOptions Camera(int width_px, int height_px, double hfov_deg) {
  BandGeometryOptions o;
  o.image_height_px = height_px;
  o.fy_px = 0.5 * width_px / std::tan(0.5 * hfov_deg * M_PI / 180.0);
  o.cy_px = 0.5 * (height_px - 1);
  return o;
}

std::string ErrorOf(const BandGeometryOptions& o) {
  try {
    BandFromGeometry(o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(BandGeometry, DefaultCameraAndPlatesGiveTheHandTunedBand) {
  // The detector's default fractions (0.20-0.62) were tuned by hand for this camera and these plates.
  const BandOptions band = BandFromGeometry(Camera(640, 480, 60.0));
  EXPECT_TRUE(band.enabled);
  EXPECT_NEAR(band.top_px / 480.0, 0.20, 0.02);
  EXPECT_NEAR(band.bottom_px / 480.0, 0.60, 0.03);
  EXPECT_EQ(ResolveBandRows(band, 480), cv::Range(band.top_px, band.bottom_px));
}

TEST(BandGeometry, EveryTextPointInTheRangesFallsInsideTheBandAt1280x720) {
  BandGeometryOptions o = Camera(1280, 720, 70.0);
  o.mount_height_m = 1.1;
  o.pitch_up_deg = 15.0;
  o.text_bottom_min_m = 1.43;
  o.text_top_max_m = 1.80;
  o.min_distance_m = 1.2;  // all of it inside the image (the band is not clipped)
  o.max_distance_m = 3.0;
  o.margin_px = 0.0;
  const BandOptions band = BandFromGeometry(o);
  for (double z = o.text_bottom_min_m; z <= o.text_top_max_m + 1e-9; z += 0.01) {
    for (double d = o.min_distance_m; d <= o.max_distance_m + 1e-9; d += 0.1) {
      double row = 0.0;
      ASSERT_TRUE(RowOfWallPoint(o, z, d, &row));
      EXPECT_GE(row, band.top_px - 1e-9) << z << " m at " << d << " m";
      EXPECT_LT(row, band.bottom_px) << z << " m at " << d << " m";
    }
  }
  // Tight: the corners lie within a pixel of the band's edges.
  double top = 0.0, bottom = 0.0;
  RowOfWallPoint(o, o.text_top_max_m, o.min_distance_m, &top);
  RowOfWallPoint(o, o.text_bottom_min_m, o.max_distance_m, &bottom);
  EXPECT_NEAR(band.top_px, top, 1.0);
  EXPECT_NEAR(band.bottom_px, bottom, 2.0);
}

TEST(BandGeometry, BandScalesWithTheFocalLengthNotWithTheImageHeight) {
  // Same field of view, double resolution: the band doubles in rows, the same image fraction.
  const BandOptions small = BandFromGeometry(Camera(640, 360, 60.0));
  const BandOptions large = BandFromGeometry(Camera(1280, 720, 60.0));
  EXPECT_NEAR(large.top_px / 720.0, small.top_px / 360.0, 0.03);
  EXPECT_NEAR(large.bottom_px / 720.0, small.bottom_px / 360.0, 0.03);
  // 16:9 at the same horizontal field of view sees less vertically: the band is a larger image fraction
  // than the 4:3 camera's hand-tuned one.
  const BandOptions four_three = BandFromGeometry(Camera(640, 480, 60.0));
  EXPECT_GT((large.bottom_px - large.top_px) / 720.0, (four_three.bottom_px - four_three.top_px) / 480.0);
}

TEST(BandGeometry, TextAtCameraHeightWithoutPitchIsOnTheCentreRow) {
  BandGeometryOptions o = Camera(640, 480, 60.0);
  o.pitch_up_deg = 0.0;
  double row = 0.0;
  ASSERT_TRUE(RowOfWallPoint(o, o.mount_height_m, 2.0, &row));
  EXPECT_NEAR(row, o.cy_px, 1e-9);
  ASSERT_TRUE(RowOfWallPoint(o, o.mount_height_m + 0.5, 1.0, &row));  // 0.5 m up at 1 m: fy/2 above
  EXPECT_NEAR(row, o.cy_px - 0.5 * o.fy_px, 1e-9);
}

TEST(BandGeometry, BandIsClippedToTheImage) {
  BandGeometryOptions o = Camera(640, 480, 60.0);
  o.min_distance_m = 0.3;  // very close: the text top leaves the image
  const BandOptions band = BandFromGeometry(o);
  EXPECT_EQ(band.top_px, 0);
  EXPECT_LE(band.bottom_px, 480);
}

TEST(BandGeometry, TextOutsideTheImageIsAnErrorNamingIt) {
  BandGeometryOptions o = Camera(640, 480, 60.0);
  o.text_bottom_min_m = 5.0;  // far above a camera pitched 10° up, 1 m away
  o.text_top_max_m = 5.5;
  o.max_distance_m = 1.2;
  EXPECT_NE(ErrorOf(o).find("outside the image"), std::string::npos) << ErrorOf(o);
}

TEST(BandGeometry, BadOptionsAreErrorsNamingTheField) {
  BandGeometryOptions o = Camera(640, 480, 60.0);
  o.fy_px = 0.0;
  EXPECT_NE(ErrorOf(o).find("fy_px"), std::string::npos);
  o = Camera(640, 480, 60.0);
  o.text_top_max_m = o.text_bottom_min_m;
  EXPECT_NE(ErrorOf(o).find("text_top_max_m"), std::string::npos);
  o = Camera(640, 480, 60.0);
  o.max_distance_m = 0.5;
  EXPECT_NE(ErrorOf(o).find("max_distance_m"), std::string::npos);
  o = Camera(640, 480, 60.0);
  o.image_height_px = 0;
  EXPECT_NE(ErrorOf(o).find("image_height_px"), std::string::npos);
  o = Camera(640, 480, 60.0);
  o.margin_px = -1.0;
  EXPECT_NE(ErrorOf(o).find("margin_px"), std::string::npos);
}

// Checked at start-up, before any camera_info: the mount and building fields alone, never the intrinsics.
TEST(BandGeometry, ValidatingTheMountAndBuildingIgnoresTheIntrinsics) {
  BandGeometryOptions o;
  o.image_height_px = 0;  // no camera yet
  o.fy_px = 0.0;
  EXPECT_NO_THROW(ValidateBandGeometryOptions(o));
  o.max_distance_m = 0.5;  // below min_distance_m
  try {
    ValidateBandGeometryOptions(o);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_distance_m must be finite and >= min_distance_m"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization
