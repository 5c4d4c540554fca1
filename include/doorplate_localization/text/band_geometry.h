// The image band in which doorplates can appear, computed from the camera and the building instead of
// being tuned by hand (MserBandDetectorOptions::band).
//
// Geometry: a pinhole camera looking sideways at a corridor wall, its optical centre `mount_height_m`
// above the floor and its optical axis tilted up by `pitch_up_deg` (rotation about the image x axis). A
// point at height z on a wall at horizontal distance d along the (unpitched) optical axis is seen at
//   row(z, d) = cy + fy · (sin p · d − cos p · (z − h)) / (cos p · d + sin p · (z − h)),
// the same model as the simulator's CameraRenderer. The row does not depend on where the point is
// left or right of the axis, and it is monotonic in z (higher = smaller row) and in d for fixed z, so the
// band [top, bottom) is bounded by the four corners: the highest text top at the nearest and farthest
// distance, the lowest text bottom at both. A margin is added and the band clipped to the image.
// Units: metres, degrees, pixels (rows from the image top, pixel centres at integers).
#pragma once

#include "doorplate_localization/text/mser_band_detector.h"

namespace doorplate_localization {

struct BandGeometryOptions {
  // Camera: intrinsics (from camera_info's K: fy = K[4], cy = K[5]) and mount on the robot.
  int image_height_px = 480;
  double fy_px = 554.26;
  double cy_px = 239.5;
  double mount_height_m = 1.2;     // optical centre above the floor
  double pitch_up_deg = 10.0;      // positive: tilted up (the simulator's CameraOptions::pitch_deg)
  // Building: where plate text is and from how far it is read.
  double text_bottom_min_m = 1.565;  // lowest bottom edge of plate text above the floor
  double text_top_max_m = 1.635;     // highest top edge of plate text above the floor
  double min_distance_m = 1.0;       // nearest wall distance along the optical axis at which to read
  double max_distance_m = 3.5;       // farthest
  double margin_px = 8.0;            // added above and below (tilt, bumps, padding of the text boxes)
};

// Band rows for the detector: a BandOptions with enabled = true and top_px / bottom_px set (the
// fractions keep their defaults and are unused). Throws std::invalid_argument naming the field when an
// option is out of range (heights, distances, fy, image height), when a corner of the text range is
// behind the camera, or when the band lies entirely outside the image.
BandOptions BandFromGeometry(const BandGeometryOptions& options);

// The mount and building fields alone (not the intrinsics, which come with each camera_info): throws
// std::invalid_argument "BandFromGeometry: <field> must be ..." as BandFromGeometry would.
void ValidateBandGeometryOptions(const BandGeometryOptions& options);

// The row (possibly outside the image) at which a point `height_m` above the floor on a wall
// `distance_m` away is seen; false when it is behind the camera.
bool RowOfWallPoint(const BandGeometryOptions& options, double height_m, double distance_m, double* row_px);

}  // namespace doorplate_localization
