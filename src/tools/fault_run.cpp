#include "fault_run.h"

#include <algorithm>
#include <stdexcept>

namespace doorplate_localization::tools {

const char* ToString(FaultKind kind) {
  switch (kind) {
    case FaultKind::kCameraOff: return "camera off";
    case FaultKind::kLaserOff: return "laser off";
    case FaultKind::kLocalizerRestart: return "localizer restarted";
    case FaultKind::kKidnap: return "kidnapped";
  }
  return "?";
}

std::vector<Fault> IssueFaultSchedule() {
  return {{FaultKind::kCameraOff, 30.0},
          {FaultKind::kLaserOff, 5.0},
          {FaultKind::kLocalizerRestart, 0.0},
          {FaultKind::kKidnap, 0.0},
          {FaultKind::kKidnap, 0.0}};
}

FaultSchedule::FaultSchedule(const FaultOptions& options) : options_(options), next_start_s_(options.first_fault_s) {
  const auto check = [](bool ok, const std::string& field) {
    if (!ok) throw std::invalid_argument("FaultOptions." + field + ": out of range");
  };
  check(options.first_fault_s >= 0.0, "first_fault_s");
  check(options.settle_s >= 0.0, "settle_s");
  check(options.max_recovery_s > 0.0, "max_recovery_s");
  check(options.recovered_position_m > 0.0, "recovered_position_m");
  check(options.recovered_heading_rad > 0.0, "recovered_heading_rad");
  check(options.kidnap_min_jump_m >= 0.0, "kidnap_min_jump_m");
  check(options.kidnap_clearance_m >= 0.0, "kidnap_clearance_m");
  check(options.kidnap_max_off_route_m > 0.0, "kidnap_max_off_route_m");
  for (size_t i = 0; i < options.schedule.size(); ++i) {
    const Fault& f = options.schedule[i];
    const bool outage = f.kind == FaultKind::kCameraOff || f.kind == FaultKind::kLaserOff;
    check(outage ? f.duration_s > 0.0 : f.duration_s == 0.0, "schedule[" + std::to_string(i) + "].duration_s");
  }
}

std::optional<FaultKind> FaultSchedule::Begin(double now_s, double distance_m) {
  if (current_ || next_ >= options_.schedule.size() || now_s + 1e-9 < next_start_s_) return std::nullopt;
  const Fault& fault = options_.schedule[next_++];
  FaultReport report;
  report.kind = fault.kind;
  report.start_s = now_s;
  report.end_s = now_s + fault.duration_s;
  current_ = report;
  end_seen_ = fault.duration_s == 0.0;
  end_distance_m_ = distance_m;
  if (fault.kind == FaultKind::kLocalizerRestart || fault.kind == FaultKind::kKidnap) return fault.kind;
  return std::nullopt;
}

void FaultSchedule::SetKidnap(const Pose2D& from, const Pose2D& to) {
  if (!current_) return;
  current_->kidnap_from = from;
  current_->kidnap_to = to;
  current_->kidnap_jump_m = Norm(to.Position() - from.Position());
}

void FaultSchedule::Observe(double now_s, double distance_m, double position_error_m, double heading_error_rad,
                            bool converged, bool localized) {
  if (!current_) return;
  FaultReport& r = *current_;
  r.max_error_m = std::max(r.max_error_m, position_error_m);
  r.max_heading_error_rad = std::max(r.max_heading_error_rad, std::fabs(heading_error_rad));
  if (now_s + 1e-9 < r.end_s) return;  // the outage goes on
  if (!end_seen_) {
    end_seen_ = true;
    end_distance_m_ = distance_m;
  }
  r.recovery_s = now_s - r.end_s;
  r.recovery_distance_m = distance_m - end_distance_m_;
  r.recovered = localized && converged && position_error_m <= options_.recovered_position_m &&
                std::fabs(heading_error_rad) <= options_.recovered_heading_rad;
  if (!r.recovered && r.recovery_s < options_.max_recovery_s) return;
  reports_.push_back(r);
  current_.reset();
  next_start_s_ = now_s + options_.settle_s;
}

bool FaultSchedule::Active(FaultKind kind, double now_s) const {
  return current_ && current_->kind == kind && now_s + 1e-9 < current_->end_s;
}

}  // namespace doorplate_localization::tools
