// doorplate_soak: one long simulated run (default one hour) of the robot sweeping a corridor back and
// forth with laser, camera, the text extractor and Text AMCL, as fast as the CPU goes (soak_run.h).
// Prints, and with --markdown writes, the resident memory at start and per window, the update rates per
// window and the errors. With --faults it injects issue 8's faults (fault_run.h: camera off 30 s, laser
// off 5 s, localizer restarted, kidnapped twice) one after another and reports how localization recovers
// from each. Exit status 1 if any error was counted or a fault did not recover, 2 on a bad command line.
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "cli_args.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/sim/world_loader.h"
#include "soak_run.h"

namespace dl = doorplate_localization;
using dl::tools::UsageError;

namespace {

const char kUsage[] =
    "usage: doorplate_soak --world FILE [--seconds 3600] [--window 300] [--camera-hz HZ] [--speed 0.4]\n"
    "                      [--particles 2000] [--no-localizer] [--seed 1] [--markdown OUT.md]\n"
    "                      [--faults [--first-fault 30] [--settle 10] [--max-recovery 180]]\n"
    "  Simulated seconds; --camera-hz 0 (default) uses the world's camera rate. --faults: the run ends\n"
    "  when the last fault has recovered (or given up), or at --seconds.\n";

struct Args {
  std::string world, markdown;
  dl::tools::SoakOptions soak;
};

double ParseNumber(const std::string& option, const std::string& text, double min) {
  const auto value = dl::tools::ParseFiniteNumber(text);
  if (!value || *value < min) throw UsageError(option + ": '" + text + "' is not a number >= " + std::to_string(min));
  return *value;
}

Args ParseArgs(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (option == "--no-localizer") {
      args.soak.localizer = false;
      continue;
    }
    if (option == "--faults") {
      args.soak.faults.schedule = dl::tools::IssueFaultSchedule();
      continue;
    }
    if (i + 1 >= argc) throw UsageError(option + " needs a value");
    const std::string value = argv[++i];
    if (option == "--world") args.world = value;
    else if (option == "--markdown") args.markdown = value;
    else if (option == "--seconds") args.soak.duration_s = ParseNumber(option, value, 1.0);
    else if (option == "--window") args.soak.window_s = ParseNumber(option, value, 1.0);
    else if (option == "--camera-hz") args.soak.camera_rate_hz = ParseNumber(option, value, 0.0);
    else if (option == "--speed") args.soak.speed_mps = ParseNumber(option, value, 0.01);
    else if (option == "--particles") args.soak.max_particles = static_cast<int>(ParseNumber(option, value, 100.0));
    else if (option == "--first-fault") args.soak.faults.first_fault_s = ParseNumber(option, value, 0.0);
    else if (option == "--settle") args.soak.faults.settle_s = ParseNumber(option, value, 0.0);
    else if (option == "--max-recovery") args.soak.faults.max_recovery_s = ParseNumber(option, value, 1.0);
    else if (option == "--seed") args.soak.seed = static_cast<std::uint64_t>(ParseNumber(option, value, 0.0));
    else throw UsageError("unknown option '" + option + "'");
  }
  if (args.world.empty()) throw UsageError("--world is required");
  if (args.soak.window_s > args.soak.duration_s) throw UsageError("--window must not exceed --seconds");
  if (!args.soak.faults.schedule.empty() && !args.soak.localizer) throw UsageError("--faults needs the localizer");
  return args;
}

std::string Table(const dl::tools::SoakResult& r, const dl::tools::SoakOptions& o) {
  std::ostringstream out;
  out << std::fixed;
  out << "| window end (sim s) | CPU s | scans / CPU s | frames / CPU s | wall s | real-time factor (wall) | "
         "filter updates | plate reports | mean / max error m | converged scans | RSS MB | errors |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  double previous_end = 0.0;
  for (const auto& w : r.windows) {
    const double sim_s = w.end_sim_s - previous_end;
    previous_end = w.end_sim_s;
    out << "| " << std::setprecision(0) << w.end_sim_s << " | " << std::setprecision(1) << w.cpu_s << " | "
        << w.scans / w.cpu_s << " | " << w.frames / w.cpu_s << " | " << w.wall_s << " | " << sim_s / w.wall_s
        << "× | " << w.filter_updates << " | " << w.plate_reports << " | ";
    if (o.localizer) {
      out << std::setprecision(2) << w.mean_error_m << " / " << w.max_error_m << " | " << w.converged_scans << "/"
          << w.scans;
    } else {
      out << "– | –";
    }
    out << " | " << std::setprecision(1) << w.rss_mb << " | " << w.errors << " |\n";
  }
  return out.str();
}

std::string FaultTable(const dl::tools::SoakResult& r, const dl::tools::FaultOptions& o) {
  std::ostringstream out;
  out << std::fixed << "Recovered: estimate within " << std::setprecision(2) << o.recovered_position_m << " m and "
      << std::setprecision(0) << o.recovered_heading_rad * 180.0 / M_PI
      << "° of the truth and the filter converged, measured from the fault's end.\n\n"
      << "| fault | start (sim s) | end (sim s) | recovered | recovery time (sim s) | recovery distance m | "
         "max error during fault m / ° | kidnap jump m to (x, y, θ) |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& f : r.faults) {
    out << "| " << dl::tools::ToString(f.kind) << " | " << std::setprecision(1) << f.start_s << " | " << f.end_s
        << " | " << (f.recovered ? "yes" : "**no**") << " | " << f.recovery_s << " | " << std::setprecision(2)
        << f.recovery_distance_m << " | " << f.max_error_m << " / " << std::setprecision(0)
        << f.max_heading_error_rad * 180.0 / M_PI << " | ";
    if (f.kind == dl::tools::FaultKind::kKidnap) {
      out << std::setprecision(2) << f.kidnap_jump_m << " to (" << f.kidnap_to.x_m << ", " << f.kidnap_to.y_m << ", "
          << std::setprecision(0) << f.kidnap_to.theta_rad * 180.0 / M_PI << "°)";
    }
    else out << "–";
    out << " |\n";
  }
  if (r.faults.size() < o.schedule.size())
    out << "\nOnly " << r.faults.size() << " of " << o.schedule.size() << " faults ended before --seconds.\n";
  return out.str();
}

bool AllRecovered(const dl::tools::SoakResult& r, const dl::tools::FaultOptions& o) {
  if (r.faults.size() != o.schedule.size()) return false;
  for (const auto& f : r.faults) if (!f.recovered) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  try {
    args = ParseArgs(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "doorplate_soak: " << e.what() << "\n" << kUsage;
    return 2;
  }
  try {
    const dl::World world = dl::LoadWorldFile(args.world);
    const dl::tools::SoakResult result = dl::tools::RunSoak(world, args.soak);
    std::ostringstream report;
    report << std::fixed << std::setprecision(1) << "World `" << world.name << "`, " << args.soak.duration_s
           << " simulated s in windows of " << args.soak.window_s << " s, seed " << args.soak.seed
           << ", localizer " << (args.soak.localizer ? "on" : "off") << ", driven " << result.distance_m
           << " m.\n\nRSS at start " << result.start_rss_mb << " MB, at end "
           << (result.windows.empty() ? 0.0 : result.windows.back().rss_mb) << " MB; errors: " << result.errors
           << ".\n\n"
           << Table(result, args.soak);
    if (!args.soak.faults.schedule.empty()) report << "\n" << FaultTable(result, args.soak.faults);
    for (const std::string& e : result.first_errors) report << "\n- error: " << e;
    std::cout << report.str();
    if (!args.markdown.empty()) dl::WriteFileAtomically(args.markdown, report.str());
    const bool faults_ok = args.soak.faults.schedule.empty() || AllRecovered(result, args.soak.faults);
    return result.errors == 0 && faults_ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "doorplate_soak: " << e.what() << "\n";
    return 1;
  }
}
