// Builds a ready TextAmcl from one options struct, a map and an optional text map: the one place that
// turns configuration into the filter's models, shared by the Text AMCL nodelet, `doorplate_eval
// localize` and the benchmarks (so they all run the same filter). amcl's laser_model_type values:
// "likelihood_field" (cube-sum combination), "likelihood_field_prob" (product), "beam".
#pragma once

#include <memory>
#include <string>

#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/mcl/beam_model.h"
#include "doorplate_localization/mcl/diff_drive_motion_model.h"
#include "doorplate_localization/mcl/likelihood_field_model.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/mcl/plate_likelihood_model.h"
#include "doorplate_localization/mcl/plate_pose_sampler.h"
#include "doorplate_localization/mcl/text_amcl.h"

namespace doorplate_localization {

enum class LaserModelType { kLikelihoodField, kLikelihoodFieldProb, kBeam };

// amcl's laser_model_type names: "likelihood_field", "likelihood_field_prob", "beam". Throws
// std::invalid_argument naming laser_model_type for anything else.
LaserModelType ParseLaserModelType(const std::string& name);
const char* ToString(LaserModelType type);

struct TextAmclSetupOptions {
  TextAmclOptions filter;
  LocalizationGridOptions grid;            // how map values read as free / occupied / unknown
  LaserModelType laser_model_type = LaserModelType::kLikelihoodField;
  // The likelihood-field options serve both likelihood_field types (their `combination` is set from
  // laser_model_type); `beam` serves "beam".
  LikelihoodFieldModelOptions likelihood_field;
  BeamModelOptions beam;
  OdometryMotionModelOptions motion;
  // false: plain amcl — plate readings are ignored even when a text map is given.
  bool use_text = true;
  PlateLikelihoodModelOptions plate;
  PlatePoseSamplerOptions plate_sampler;
};

// The filter, not yet initialized (call Initialize or GlobalLocalization). `text_map` may be null
// (laser only). Throws std::invalid_argument naming the field of a bad option, an unusable map (beyond
// limits.h's bounds, or without a free cell: "map: no free cell: ...") or an empty text map with use_text.
std::unique_ptr<TextAmcl> MakeTextAmcl(const TextAmclSetupOptions& options, const OccupancyGrid& map,
                                       std::shared_ptr<const TextMap> text_map);

}  // namespace doorplate_localization
