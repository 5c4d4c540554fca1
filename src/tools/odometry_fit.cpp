// doorplate_odometry_fit: how real wheel odometry slips (issue 20, item 3). Reads an MRPT rawlog's odometry
// (CActionRobotMovement2D increments, or CObservationOdometry readings) and its laser scans with MRPT's
// CRawlog; the reference motion between consecutive scans is the package's point-to-line ICP
// (slam/scan_icp.h) started from the odometry, i.e. a laser-odometry path; steps whose ICP leaves the
// travel direction unconstrained (corridors) are left out. Cuts the steps into segments of travel and fits
// the simulator's slip model (odometry_fit/odometry_slip_fit.h); writes the segments and the fit as JSON
// (nlohmann-json, result_json.h) and prints a summary. --seed drives the bootstrap intervals only.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>
#include <string>

#include <Eigen/Dense>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "cli_app.h"
#include "output_guard.h"
#include "rawlog_reader.h"
#include "result_json.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/odometry_fit/odometry_slip_fit.h"
#include "doorplate_localization/slam/scan_icp.h"

namespace dl = doorplate_localization;
namespace tools = dl::tools;

namespace {

const char kDescription[] =
    "How real wheel odometry slips: fits the simulator's slip model to an MRPT rawlog against laser odometry (ICP).";
const char kNotes[] =
    "e.g. --rawlog /usr/share/mrpt/datasets/'2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog'";

struct Args {
  std::string rawlog, json, sensor_label;
  std::uint64_t seed = 1;
  double max_along_sigma_m = 0.02;
  bool sync_odometry = true;
  dl::OdometrySegmentOptions segments;
  dl::OdometrySlipFitOptions fit;
};

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("--rawlog", args->rawlog, "the MRPT rawlog")->required();
  app->add_option("--json", args->json, "write the segments and the fit here")->required();
  app->add_option("--seed", args->seed, "the bootstrap intervals' draws")->capture_default_str()->transform(tools::Seed());
  app->add_option("--segment-length-m", args->segments.segment_length_m, "reference travel per segment")
      ->capture_default_str()->check(tools::PositiveNumber());
  app->add_option("--max-along-sigma-m", args->max_along_sigma_m, "an ICP step whose standard deviation along the "
                  "travel exceeds this is not a reference")->capture_default_str()->check(tools::PositiveNumber());
  app->add_option("--zones", args->fit.num_zones, "slip zones to fit")->capture_default_str()
      ->transform(tools::WholeNumber(1));
  app->add_option("--sensor-label", args->sensor_label, "use only the scans of this sensor label");
  app->add_option("--sync-odometry", args->sync_odometry, "1: odometry interpolated to each scan's time stamp")
      ->default_str("1")->transform(tools::WholeNumber(0, 1));
}

// One laser scan: the latest odometry pose (odom frame) and its time, the scan's time, echoes in base_link.
struct Scan {
  dl::Pose2D odometry;
  double odometry_time_s = 0.0;  // 0: unknown
  double time_s = 0.0;
  std::vector<dl::Vec2> points;
};

std::vector<dl::Vec2> Points(const mrpt::obs::CObservation2DRangeScan& obs) {
  const dl::Pose2D mount{obs.sensorPose.x(), obs.sensorPose.y(), obs.sensorPose.yaw()};
  std::vector<dl::Vec2> points;
  for (std::size_t i = 0; i < obs.getScanSize(); ++i) {
    if (!obs.getScanRangeValidity(i)) continue;
    const double r = obs.getScanRange(i), a = obs.getScanAngle(i);
    points.push_back(mount.TransformPoint({r * std::cos(a), r * std::sin(a)}));
  }
  return points;
}

std::vector<Scan> ReadScans(const Args& args) {
  mrpt::obs::CRawlog rawlog;
  tools::LoadRawlog(args.rawlog, &rawlog);  // RawlogError naming the file, without MRPT's call stack
  std::vector<Scan> scans;
  dl::Pose2D odometry;
  double odometry_time_s = 0.0;
  std::optional<dl::Pose2D> odometry_reading;  // observation-only rawlogs: absolute odometry readings
  mrpt::obs::CActionCollection::Ptr actions;
  mrpt::obs::CSensoryFrame::Ptr frame;
  mrpt::obs::CObservation::Ptr observation;
  std::size_t entry = 0;
  auto take = [&](const mrpt::obs::CObservation::Ptr& obs) {
    if (const auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs)) {
      odometry_reading = dl::Pose2D{odo->odometry.x(), odo->odometry.y(), odo->odometry.phi()};
      odometry_time_s = mrpt::Clock::toDouble(odo->timestamp);
      return false;
    }
    const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs);
    if (!scan || scan->getScanSize() < 2) return false;
    if (!args.sensor_label.empty() && scan->sensorLabel != args.sensor_label) return false;
    scans.push_back({odometry_reading ? *odometry_reading : odometry, odometry_time_s,
                     mrpt::Clock::toDouble(scan->timestamp), Points(*scan)});
    return true;
  };
  while (entry < rawlog.size()) {
    if (rawlog.getType(entry) == mrpt::obs::CRawlog::etObservation) {
      take(rawlog.getAsObservation(entry++));
      continue;
    }
    if (!rawlog.getActionObservationPair(actions, frame, entry)) break;
    if (actions) {
      if (const auto move = actions->getBestMovementEstimation()) {
        const mrpt::poses::CPose2D d = move->poseChange->getMeanVal();
        odometry = odometry.Compose({d.x(), d.y(), d.phi()});
        odometry_time_s = mrpt::Clock::toDouble(move->timestamp);
      }
    }
    if (!frame) continue;
    for (const auto& obs : *frame) {
      if (take(obs)) break;  // one scan per step
    }
  }
  return scans;
}

// The odometry at each scan's own time: interpolated between the odometry readings before and after it
// (linearly in the relative pose; the Málaga rawlog's odometry is read 0.10-0.16 s before each scan, at
// 1.5 m/s up to 0.24 m of travel, so scale errors of single metres would otherwise be timing jitter).
// Returns the number of scans moved; a scan without a later reading, or unknown times, keeps its pose.
int SyncOdometryToScans(std::vector<Scan>* scans) {
  std::vector<dl::Pose2D> synced;
  int moved = 0;
  for (std::size_t k = 0; k < scans->size(); ++k) {
    const Scan& s = (*scans)[k];
    synced.push_back(s.odometry);
    if (k + 1 >= scans->size() || s.odometry_time_s <= 0.0) continue;
    const Scan& next = (*scans)[k + 1];
    const double span = next.odometry_time_s - s.odometry_time_s;
    if (!(span > 0.0)) continue;
    const double f = (s.time_s - s.odometry_time_s) / span;
    if (f < 0.0 || f > 1.0) continue;
    const dl::Pose2D d = s.odometry.Between(next.odometry);
    synced.back() = s.odometry.Compose({f * d.x_m, f * d.y_m, f * d.theta_rad});
    ++moved;
  }
  for (std::size_t k = 0; k < scans->size(); ++k) (*scans)[k].odometry = synced[k];
  return moved;
}

// Standard deviation of the ICP translation along `direction` (unit), from the information's inverse;
// +inf where the information is singular. A near-zero step (no direction) uses the worst direction.
double AlongSigma(const Eigen::Matrix3d& information, dl::Vec2 step) {
  Eigen::FullPivLU<Eigen::Matrix3d> lu(information);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  const Eigen::Matrix2d cov = lu.inverse().topLeftCorner<2, 2>();
  const double norm = dl::Norm(step);
  if (norm < 0.01) return std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvalues().maxCoeff());
  const Eigen::Vector2d u(step.x / norm, step.y / norm);
  return std::sqrt(std::max(0.0, u.dot(cov * u)));
}

dl::Json FittedJson(const dl::FittedValue& v) { return {{"value", v.value}, {"ci95", {v.low, v.high}}}; }

void WriteJson(const Args& args, int scans, int synced, int aligned, int constrained,
               const std::vector<dl::OdometrySegment>& segs, const dl::OdometrySlipFit& fit) {
  dl::Json f;
  f["segments_used"] = fit.segments_used;
  f["segments_rejected"] = fit.segments_rejected;
  f["mean_segment_length_m"] = fit.mean_segment_length_m;
  f["mean_scale_error"] = fit.mean_scale_error;
  f["median_scale_error"] = fit.median_scale_error;
  f["scale_error"] = FittedJson(fit.scale_error);
  f["turn_scale_error_m_per_rad"] = FittedJson(fit.turn_scale_error_m_per_rad);
  f["turn_rotation_error_rad_per_rad"] = FittedJson(fit.turn_rotation_error);
  f["heading_drift_rad_per_m"] = FittedJson(fit.heading_drift_rad_per_m);
  f["residual_stddev"] = fit.residual_stddev;
  f["lag1_correlation"] = fit.lag1_correlation;
  f["lag1_pairs"] = fit.lag1_pairs;
  f["lag2_correlation"] = fit.lag2_correlation;
  f["lag2_pairs"] = fit.lag2_pairs;
  f["ou_stddev"] = fit.ou_stddev;
  f["ou_correlation_length_m"] = fit.ou_correlation_length_m;
  f["zone_chi2"] = fit.zone_chi2;
  f["zone_dof"] = fit.zone_dof;
  f["zones"] = dl::Json::array();
  for (const dl::ZoneScaleError& zone : fit.zones) {
    f["zones"].push_back({{"start_arc_m", zone.start_arc_m}, {"end_arc_m", zone.end_arc_m}, {"segments", zone.segments},
                          {"mean_scale_error", zone.mean}, {"standard_error", zone.standard_error}});
  }
  dl::Json j;
  j["rawlog"] = args.rawlog;
  j["seed"] = args.seed;
  j["segment_length_m"] = args.segments.segment_length_m;
  j["max_along_sigma_m"] = args.max_along_sigma_m;
  j["scans"] = scans;
  j["scans_odometry_synced"] = synced;
  j["steps_icp_aligned"] = aligned;
  j["steps_along_constrained"] = constrained;
  j["fit"] = f;
  j["segments"] = dl::Json::array();
  for (const dl::OdometrySegment& g : segs) {
    j["segments"].push_back({{"first_step", g.first_step}, {"steps", g.num_steps}, {"start_arc_m", g.start_arc_m},
                             {"x_m", g.start_position.x}, {"y_m", g.start_position.y},
                             {"reference_m", g.reference_distance_m}, {"odometry_m", g.odometry_distance_m},
                             {"reference_rad", g.reference_rotation_rad}, {"odometry_rad", g.odometry_rotation_rad},
                             {"duration_s", g.duration_s}});
  }
  dl::WriteFileAtomically(args.json, dl::ResultJsonText(j));
}

int Run(const Args& args) {
  tools::RefuseOverwritingInputs({{"--rawlog", args.rawlog}}, {{"--json", args.json}});
  std::vector<Scan> scans = ReadScans(args);
  if (scans.size() < 2) throw std::runtime_error(args.rawlog + ": fewer than two laser scans");
  const int synced = args.sync_odometry ? SyncOdometryToScans(&scans) : 0;
  const dl::ScanIcpOptions icp;
  std::vector<dl::OdometryStep> steps;
  int aligned = 0, constrained = 0;
  for (std::size_t i = 1; i < scans.size(); ++i) {
    dl::OdometryStep step;
    step.odometry = scans[i - 1].odometry.Between(scans[i].odometry);
    step.dt_s = scans[i].time_s - scans[i - 1].time_s;
    if (!(step.dt_s > 0.0)) step.dt_s = 0.0;
    const dl::IcpReference reference(scans[i - 1].points, icp);
    const dl::ScanIcpResult r = dl::AlignScans(reference, scans[i].points, step.odometry, icp);
    step.reference_valid = r.aligned;
    step.reference = r.aligned ? r.relative : step.odometry;
    step.along_constrained =
        r.aligned && AlongSigma(r.information, step.odometry.Position()) <= args.max_along_sigma_m;
    aligned += r.aligned;
    constrained += step.along_constrained;
    steps.push_back(step);
  }
  const std::vector<dl::OdometrySegment> segments = dl::SplitIntoSegments(steps, args.segments);
  std::mt19937_64 rng(args.seed);
  const dl::OdometrySlipFit fit = dl::FitOdometrySlip(segments, args.fit, rng);
  WriteJson(args, static_cast<int>(scans.size()), synced, aligned, constrained, segments, fit);
  std::printf("odometry interpolated to the scan time for %d scans\n", synced);
  std::printf("scans %zu, ICP aligned %d of %zu steps, along-constrained %d; segments used %d (rejected %d)\n",
              scans.size(), aligned, steps.size(), constrained, fit.segments_used, fit.segments_rejected);
  auto line = [](const char* name, const dl::FittedValue& v) {
    std::printf("%-34s %+.5f  [%+.5f, %+.5f]\n", name, v.value, v.low, v.high);
  };
  std::printf("mean / median scale error         %+.5f / %+.5f\n", fit.mean_scale_error, fit.median_scale_error);
  line("scale_error (turn rate 0)", fit.scale_error);
  line("turn_scale_error_m_per_rad", fit.turn_scale_error_m_per_rad);
  line("turn_rotation_error_rad_per_rad", fit.turn_rotation_error);
  line("heading_drift_rad_per_m", fit.heading_drift_rad_per_m);
  std::printf("residual sd %.5f, lag1 r %.3f (%d pairs), lag2 r %.3f (%d pairs), OU sd %.5f L %.2f m\n",
              fit.residual_stddev, fit.lag1_correlation, fit.lag1_pairs, fit.lag2_correlation, fit.lag2_pairs,
              fit.ou_stddev, fit.ou_correlation_length_m);
  for (const dl::ZoneScaleError& z : fit.zones) {
    std::printf("zone %6.1f-%6.1f m: %3d segments, mean scale error %+.5f ± %.5f\n", z.start_arc_m, z.end_arc_m,
                z.segments, z.mean, z.standard_error);
  }
  std::printf("zone chi2 %.2f on %d dof\n", fit.zone_chi2, fit.zone_dof);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_odometry_fit", kDescription, AddOptions, Run, argc, argv);
}
