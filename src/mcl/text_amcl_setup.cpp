#include "doorplate_localization/mcl/text_amcl_setup.h"

#include <stdexcept>

#include "doorplate_localization/mcl/resampler.h"

namespace doorplate_localization {

LaserModelType ParseLaserModelType(const std::string& name) {
  if (name == "likelihood_field") return LaserModelType::kLikelihoodField;
  if (name == "likelihood_field_prob") return LaserModelType::kLikelihoodFieldProb;
  if (name == "beam") return LaserModelType::kBeam;
  throw std::invalid_argument("laser_model_type: expected likelihood_field, likelihood_field_prob or beam, got '" +
                              name + "'");
}

const char* ToString(LaserModelType type) {
  switch (type) {
    case LaserModelType::kLikelihoodField: return "likelihood_field";
    case LaserModelType::kLikelihoodFieldProb: return "likelihood_field_prob";
    case LaserModelType::kBeam: return "beam";
  }
  return "?";
}

std::unique_ptr<TextAmcl> MakeTextAmcl(const TextAmclSetupOptions& options, const OccupancyGrid& map,
                                       std::shared_ptr<const TextMap> text_map) {
  auto grid = std::make_shared<const LocalizationGrid>(map, options.grid);
  const std::string no_free = NoFreeCellProblem(*grid);  // before the models are built on it
  if (!no_free.empty()) throw std::invalid_argument("map: " + no_free);
  TextAmclModels models;
  models.grid = grid;
  models.motion = std::make_shared<DiffDriveMotionModel>(options.motion);
  if (options.laser_model_type == LaserModelType::kBeam) {
    models.laser = std::make_shared<BeamModel>(grid, options.beam);
  } else {
    LikelihoodFieldModelOptions field = options.likelihood_field;
    field.combination = options.laser_model_type == LaserModelType::kLikelihoodFieldProb
                            ? BeamCombination::kProduct
                            : BeamCombination::kAmclCubeSum;
    models.laser = std::make_shared<LikelihoodFieldModel>(grid, field);
  }
  models.resampler = std::make_shared<LowVarianceResampler>();
  if (options.use_text && text_map) {
    if (text_map->landmarks.empty()) {
      throw std::invalid_argument("text map: use_text is set but the text map has no landmarks");
    }
    models.text = std::make_shared<PlateLikelihoodModel>(text_map, grid, options.plate);
    models.plate_sampler = std::make_shared<PlatePoseSampler>(text_map, grid, options.plate_sampler);
  }
  return std::make_unique<TextAmcl>(options.filter, std::move(models));
}

}  // namespace doorplate_localization
