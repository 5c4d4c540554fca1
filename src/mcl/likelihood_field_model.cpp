#include "doorplate_localization/mcl/likelihood_field_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

void Require(bool ok, const std::string& field, const std::string& rule, double value) {
  if (!ok) {
    throw std::invalid_argument("LikelihoodFieldModel: " + field + ": " + rule + ", got " + std::to_string(value));
  }
}

}  // namespace

LikelihoodFieldModel::LikelihoodFieldModel(std::shared_ptr<const LocalizationGrid> grid,
                                           const LikelihoodFieldModelOptions& options)
    : grid_(std::move(grid)), options_(options) {
  if (!grid_) throw std::invalid_argument("LikelihoodFieldModel: grid: must not be null");
  const auto& o = options_;
  Require(o.z_hit >= 0.0 && o.z_rand >= 0.0 && o.z_hit + o.z_rand > 0.0, "z_hit/z_rand", "must be >= 0, not both 0",
          o.z_hit);
  Require(std::isfinite(o.sigma_hit_m) && o.sigma_hit_m > 0.0, "sigma_hit_m", "must be > 0", o.sigma_hit_m);
  Require(o.beams.laser_max_beams >= 1, "laser_max_beams", "must be >= 1", o.beams.laser_max_beams);
  const double max_cells = o.laser_likelihood_max_dist_m / grid_->resolution_m();
  Require(std::isfinite(max_cells) && o.laser_likelihood_max_dist_m > 0.0 && max_cells * kStepsPerCell < 65535.0,
          "laser_likelihood_max_dist_m", "must be > 0 and < 4095 cells", o.laser_likelihood_max_dist_m);
  Require(o.beam_skip_threshold >= 0.0 && o.beam_skip_threshold <= 1.0, "beam_skip_threshold", "must be in [0, 1]",
          o.beam_skip_threshold);
  Require(o.beam_skip_error_threshold >= 0.0 && o.beam_skip_error_threshold <= 1.0, "beam_skip_error_threshold",
          "must be in [0, 1]", o.beam_skip_error_threshold);
  Require(o.beam_skip_distance_m >= 0.0, "beam_skip_distance_m", "must be >= 0", o.beam_skip_distance_m);

  max_steps_ = static_cast<std::uint16_t>(std::ceil(max_cells * kStepsPerCell));
  const int w = grid_->width(), h = grid_->height();
  cv::Mat free_mask(h, w, CV_8U);  // 0 on occupied cells: distanceTransform measures the distance to them
  bool any_occupied = false;
  for (int y = 0; y < h; ++y) {
    auto* row = free_mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      const bool occupied = grid_->State(x, y) == CellState::kOccupied;
      row[x] = occupied ? 0 : 255;
      any_occupied |= occupied;
    }
  }
  distance_steps_.assign(static_cast<size_t>(w) * h, max_steps_);
  if (!any_occupied) return;
  cv::Mat distance_cells;
  cv::distanceTransform(free_mask, distance_cells, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  for (int y = 0; y < h; ++y) {
    const float* row = distance_cells.ptr<float>(y);
    std::uint16_t* out = &distance_steps_[grid_->Index(0, y)];
    for (int x = 0; x < w; ++x) {
      const double steps = std::round(static_cast<double>(row[x]) * kStepsPerCell);
      out[x] = static_cast<std::uint16_t>(std::min<double>(steps, max_steps_));
    }
  }
}

double LikelihoodFieldModel::ObstacleDistance(Vec2 p) const {
  int x = 0, y = 0;
  const std::uint16_t steps = grid_->PointToCell(p, &x, &y) ? distance_steps_[grid_->Index(x, y)] : max_steps_;
  return std::min(static_cast<double>(steps) / kStepsPerCell * grid_->resolution_m(),
                  options_.laser_likelihood_max_dist_m);
}

void LikelihoodFieldModel::EndPointSteps(const Pose2D& robot, const std::vector<double>& beam_x,
                                         const std::vector<double>& beam_y, std::uint16_t* steps) const {
  // The robot pose in cell coordinates; beam end points (base_link, in cells) rotate with it.
  const Vec2 origin = grid_->ToCellCoords(robot.Position());
  const double a = robot.theta_rad - grid_->origin().theta_rad;
  const double c = std::cos(a), s = std::sin(a);
  const int w = grid_->width(), h = grid_->height();
  const std::uint16_t* field = distance_steps_.data();
  for (size_t b = 0; b < beam_x.size(); ++b) {
    const double u = origin.x + c * beam_x[b] - s * beam_y[b];
    const double v = origin.y + s * beam_x[b] + c * beam_y[b];
    steps[b] = (u >= 0.0 && v >= 0.0 && u < w && v < h)
                   ? field[static_cast<size_t>(static_cast<int>(v)) * w + static_cast<int>(u)]
                   : max_steps_;
  }
}

void LikelihoodFieldModel::LogLikelihoods(const LaserScan& scan, const std::vector<Particle>& particles,
                                          std::vector<double>* log_likelihoods) {
  const std::vector<SelectedBeam> selected = SelectBeams(scan, options_.beams);
  const double max_range = EffectiveMaxRange(scan, options_.beams);
  const double inv_res = 1.0 / grid_->resolution_m();
  std::vector<double> beam_x, beam_y;  // end points in base_link, in cells
  for (const SelectedBeam& beam : selected) {
    if (beam.kind != BeamKind::kHit) continue;  // the field model ignores max-range readings (amcl)
    const Vec2 e = scan.laser_pose.TransformPoint({beam.range_m * std::cos(beam.angle_rad),
                                                   beam.range_m * std::sin(beam.angle_rad)});
    beam_x.push_back(e.x * inv_res);
    beam_y.push_back(e.y * inv_res);
  }
  const size_t nb = beam_x.size(), np = particles.size();
  // Per-scan table: a beam's contribution for every possible distance step.
  const bool cube = options_.combination == BeamCombination::kAmclCubeSum;
  const double z_rand_part = options_.z_rand / max_range;
  const double denom = 2.0 * options_.sigma_hit_m * options_.sigma_hit_m;
  const double step_m = grid_->resolution_m() / kStepsPerCell;
  std::vector<double> contribution(max_steps_ + 1);
  for (int i = 0; i <= max_steps_; ++i) {
    const double d = std::min(i * step_m, options_.laser_likelihood_max_dist_m);
    const double pz = options_.z_hit * std::exp(-d * d / denom) + z_rand_part;
    contribution[i] = cube ? pz * pz * pz : std::log(pz);
  }
  const int skip_steps = static_cast<int>(options_.beam_skip_distance_m / step_m);
  std::vector<char> use_beam(nb, 1);
  const bool skipping = options_.do_beamskip && nb > 0 && np > 0;
  scratch_steps_.resize(skipping ? np * nb : nb);
  last_skipped_beams_ = 0;
  if (skipping) {
    for (size_t i = 0; i < np; ++i) EndPointSteps(particles[i].pose, beam_x, beam_y, &scratch_steps_[i * nb]);
    std::vector<int> near_count(nb, 0);
    for (size_t i = 0; i < np; ++i) {
      for (size_t b = 0; b < nb; ++b) near_count[b] += scratch_steps_[i * nb + b] < skip_steps;
    }
    for (size_t b = 0; b < nb; ++b) {
      use_beam[b] = near_count[b] > options_.beam_skip_threshold * np;
      last_skipped_beams_ += !use_beam[b];
    }
    if (last_skipped_beams_ >= options_.beam_skip_error_threshold * nb) {
      std::fill(use_beam.begin(), use_beam.end(), 1);  // most beams disagree: likely a wrong convergence
      last_skipped_beams_ = 0;
    }
  }
  last_used_beams_ = static_cast<int>(nb) - last_skipped_beams_;
  log_likelihoods->resize(np);
  for (size_t i = 0; i < np; ++i) {
    const std::uint16_t* steps = scratch_steps_.data();
    if (skipping) {
      steps += i * nb;
    } else {
      EndPointSteps(particles[i].pose, beam_x, beam_y, scratch_steps_.data());
    }
    double sum = 0.0;
    for (size_t b = 0; b < nb; ++b) sum += use_beam[b] ? contribution[steps[b]] : 0.0;
    (*log_likelihoods)[i] = cube ? std::log1p(sum) : sum;
  }
}

}  // namespace doorplate_localization
