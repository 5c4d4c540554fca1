// The best rigid 2D fit of a map's plates onto the true plates (issue 17): plate errors that remain after
// removing the map's overall rotation and translation, next to those under the start-pose alignment
// (ScorePlates in map_measure.h). A SLAM map's frame starts where the robot started, so a small heading
// error there swings far plates by metres; the rigid fit separates that from the map's own distortion.
#pragma once

#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

struct PlateAlignment {
  bool ok = false;                  // >= 2 pairs whose mapped positions are not all one point
  Pose2D world_from_map;            // least-squares rotation + translation taking map positions to true ones
  int pairs = 0;                    // mapped plates matched to a true plate by text
  double rmse_m = 0.0;              // of the pairs' residuals after the fit
  double max_residual_m = 0.0;
  std::vector<double> residuals_m;  // per mapped plate in map order: distance after the fit; -1 if unmatched
};

// Matches plates by text (SameRoom, common/room_id.h): a mapped plate and a true plate pair up when each is
// the only one of its map naming that room; repeated room numbers are left out (residual -1; ScorePlates
// with the fitted transform matches them by distance). Then the closed-form least-squares fit of the pairs'
// positions (centroids, then the rotation angle atan2(Σ cross, Σ dot) of the centred pairs; no scale).
// Not ok: world_from_map only shifts the pairs' centroid onto the true one (identity with no pair), and
// the residuals are under that shift.
PlateAlignment AlignPlates(const TextMap& mapped, const TextMap& truth);

}  // namespace doorplate_localization
