#include "doorplate_localization/mcl/laser_model.h"

#include <stdexcept>

namespace doorplate_localization {

BeamCombination ParseBeamCombination(const std::string& name) {
  if (name == "cube_sum") return BeamCombination::kAmclCubeSum;
  if (name == "product") return BeamCombination::kProduct;
  throw std::invalid_argument("beam_combination: expected \"cube_sum\" or \"product\", got \"" + name + "\"");
}

}  // namespace doorplate_localization
