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

#include "cli_app.h"
#include "output_guard.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/sim/world_loader.h"
#include "soak_run.h"

namespace dl = doorplate_localization;
using dl::tools::UsageError;

namespace {

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

const char kDescription[] =
    "One long simulated run of the robot sweeping a corridor with laser, camera, the text extractor and Text AMCL.";
const char kNotes[] =
    "Simulated seconds. --faults: the run ends when the last fault has recovered (or given up), or at --seconds.\n"
    "Exit status 1 if any error was counted or a fault did not recover, 2 on a bad command line.";

struct Args {
  std::string world, markdown;
  bool no_localizer = false, faults = false;
  dl::tools::SoakOptions soak;
};

void AddOptions(CLI::App* app, Args* args) {
  namespace tools = dl::tools;
  dl::tools::SoakOptions& o = args->soak;
  app->footer(kNotes);
  app->add_option("--world", args->world, "world file (worlds/*.yaml)")->required();
  app->add_option("--seconds", o.duration_s, "simulated seconds")->capture_default_str()->check(tools::Number(1.0));
  app->add_option("--window", o.window_s, "report window, simulated s")->capture_default_str()
      ->check(tools::Number(1.0));
  app->add_option("--camera-hz", o.camera_rate_hz, "camera rate (0: the world's)")->capture_default_str()
      ->check(tools::Number(0.0));
  app->add_option("--speed", o.speed_mps, "cruise speed, m/s")->capture_default_str()->check(tools::Number(0.01));
  app->add_option("--particles", o.max_particles, "filter max_particles")->capture_default_str()
      ->transform(tools::WholeNumber(100));
  app->add_flag("--no-localizer", args->no_localizer, "run without Text AMCL");
  app->add_option("--seed", o.seed, "simulator seed")->capture_default_str()->transform(tools::Seed());
  app->add_option("--markdown", args->markdown, "also write the report to this file");
  app->add_flag("--faults", args->faults, "inject issue 8's faults one after another (fault_run.h)");
  app->add_option("--first-fault", o.faults.first_fault_s, "simulated s before the first fault")
      ->capture_default_str()->check(tools::Number(0.0));
  app->add_option("--settle", o.faults.settle_s, "simulated s between a recovery and the next fault")
      ->capture_default_str()->check(tools::Number(0.0));
  app->add_option("--max-recovery", o.faults.max_recovery_s, "simulated s after which a fault did not recover")
      ->capture_default_str()->check(tools::Number(1.0));
  app->callback([args] {
    args->soak.localizer = !args->no_localizer;
    if (args->faults) args->soak.faults.schedule = dl::tools::IssueFaultSchedule();
    if (args->soak.window_s > args->soak.duration_s) throw UsageError("--window must not exceed --seconds");
    if (args->faults && !args->soak.localizer) throw UsageError("--faults needs the localizer");
  });
}

int Run(const Args& args) {
  dl::tools::RefuseOverwritingInputs({{"--world", args.world}}, {{"--markdown", args.markdown}});  // issue 18
  const dl::World world = dl::LoadWorldFile(args.world);
  const dl::tools::SoakResult result = dl::tools::RunSoak(world, args.soak);
  std::ostringstream report;
  report << std::fixed << std::setprecision(1) << "World `" << world.name << "`, " << args.soak.duration_s
         << " simulated s in windows of " << args.soak.window_s << " s, seed " << args.soak.seed << ", localizer "
         << (args.soak.localizer ? "on" : "off") << ", driven " << result.distance_m << " m.\n\nRSS at start "
         << result.start_rss_mb << " MB, at end " << (result.windows.empty() ? 0.0 : result.windows.back().rss_mb)
         << " MB; errors: " << result.errors << ".\n\n"
         << Table(result, args.soak);
  if (!args.soak.faults.schedule.empty()) report << "\n" << FaultTable(result, args.soak.faults);
  for (const std::string& e : result.first_errors) report << "\n- error: " << e;
  std::cout << report.str();
  if (!args.markdown.empty()) dl::WriteFileAtomically(args.markdown, report.str());
  const bool faults_ok = args.soak.faults.schedule.empty() || AllRecovered(result, args.soak.faults);
  return result.errors == 0 && faults_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return dl::tools::RunTool("doorplate_soak", kDescription, AddOptions, Run, argc, argv);
}
