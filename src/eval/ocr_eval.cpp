#include "ocr_eval.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/text/mser_band_detector.h"
#include "eval_args.h"
#include "progress_line.h"

namespace doorplate_localization {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time of the calling thread, seconds: per-frame costs measured with it do not grow when other
// processes share the cores (the extractor and detectors run in this thread; OMP_THREAD_LIMIT=1).
double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The three detector modes of Figure 12, sharing every option but the band and NMS switches.
struct Fig12Detector {
  DetectorModeStats stats;
  std::unique_ptr<MserBandDetector> detector;
};

std::vector<Fig12Detector> MakeFig12Detectors(const MserBandDetectorOptions& base) {
  std::vector<Fig12Detector> detectors;
  for (const auto& [name, band, nms] : {std::tuple<const char*, bool, bool>{"mser_full", false, false},
                                        {"mser_nms_full", false, true},
                                        {"mser_nms_band", true, true}}) {
    MserBandDetectorOptions options = base;
    options.band.enabled = band;
    options.nms_enabled = nms;
    Fig12Detector d;
    d.stats.name = name;
    d.stats.band = band;
    d.stats.nms = nms;
    d.detector = std::make_unique<MserBandDetector>(options);
    detectors.push_back(std::move(d));
  }
  return detectors;
}

// The frame with every text box of the extractor (green: valid reading, grey: none) and its raw OCR text,
// the event's box (red) and the true plate projections (blue crosses).
cv::Mat Annotate(const cv::Mat& frame, const std::vector<PlateObservation>& observations, const cv::Rect& box,
                 const PlateScorer& scorer, const Pose2D& true_pose) {
  cv::Mat image = frame.clone();
  for (const PlateObservation& o : observations) {
    const cv::Scalar colour = o.text.empty() ? cv::Scalar(160, 160, 160) : cv::Scalar(0, 180, 0);
    cv::rectangle(image, o.box_px, colour, 1);
    cv::putText(image, "'" + o.raw_text + "'", o.box_px.tl() + cv::Point(0, -3), cv::FONT_HERSHEY_PLAIN, 1.0,
                colour, 1);
  }
  if (box.area() > 0) cv::rectangle(image, box, cv::Scalar(0, 0, 255), 2);
  for (size_t i = 0; i < scorer.plates().size(); ++i) {
    cv::Point2d px;
    if (scorer.Visible(static_cast<int>(i), true_pose, &px)) {
      cv::drawMarker(image, cv::Point(px), cv::Scalar(255, 0, 0), cv::MARKER_CROSS, 12, 2);
    }
  }
  return image;
}

std::string SafeName(std::string text) {
  for (char& c : text) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return text.empty() ? "none" : text;
}

std::string DumpImage(const std::string& dir, const std::string& world, const OcrEvalEvent& event,
                      const cv::Mat& image) {
  char name[256];
  std::snprintf(name, sizeof(name), "%s_pass%d_t%07.2f_%s_%s_vs_%s.png", world.c_str(), event.pass, event.stamp_s,
                event.kind.c_str(), SafeName(event.reported).c_str(), SafeName(event.truth).c_str());
  cv::imwrite((std::filesystem::path(dir) / name).string(), image);
  return name;
}

TextExtractorOptions ExtractorOptions(const World& world, const CameraRenderer& camera, const OcrEvalOptions& o) {
  TextExtractorOptions options = o.extractor;
  options.detector.band.enabled = o.band;
  options.tracker.fx_px = camera.intrinsics().fx_px;
  options.tracker.cx_px = camera.intrinsics().cx_px;
  if (o.known_rooms) {
    std::set<std::string> rooms;
    for (const TextSign* plate : world.Plates()) rooms.insert(plate->text);
    options.validator.known_rooms.assign(rooms.begin(), rooms.end());
  }
  return options;
}

}  // namespace

int OcrEvalResult::Frames() const {
  int frames = 0;
  for (const OcrPassResult& p : passes) frames += p.frames;
  return frames;
}

int OcrEvalResult::PlatesTotal() const {
  int total = 0;
  for (const OcrPassResult& p : passes) total += p.score.plates_passed;
  return total;
}

int OcrEvalResult::PlatesCorrect() const {
  int correct = 0;
  for (const OcrPassResult& p : passes) correct += p.score.plates_correct;
  return correct;
}

OcrEvalResult RunOcrEval(const World& world, const OcrEvalOptions& options) {
  if (options.passes < 1) throw std::invalid_argument("OcrEvalOptions.passes must be >= 1");
  if (options.detector_every_n_frames < 0) throw std::invalid_argument("OcrEvalOptions.detector_every_n_frames must be >= 0");
  if (!options.dump_dir.empty()) std::filesystem::create_directories(options.dump_dir);
  OcrEvalResult result;
  result.world_name = world.name;
  std::vector<Fig12Detector> fig12 = MakeFig12Detectors(options.extractor.detector);
  CorridorSweepOptions sweep_options = options.sweep;
  sweep_options.follower.cruise_speed_mps = options.speed_mps;

  tools::ProgressLine progress({options.progress_every_s});
  double run_sim_s = 0.0;  // simulated seconds of the earlier passes
  for (int pass = 0; pass < options.passes; ++pass) {
    SimulatorOptions sim_options;
    sim_options.seed = PassSeed(options.seed, pass);
    Simulator sim(world, sim_options);
    const World& sim_world = sim.world();  // with surfaces built
    PlateScorer scorer(sim_world, sim.camera());
    if (pass == 0) result.plates = scorer.plates();
    TextExtractor extractor(ExtractorOptions(sim_world, sim.camera(), options));
    CorridorSweep sweep(sweep_options);
    OcrPassResult pass_result;
    pass_result.seed = sim_options.seed;
    std::map<int, double> crossing_stamps;   // plate → time it was passed
    std::map<int, cv::Mat> crossing_frames;  // plate → annotated frame where it was passed (dumps only)
    const long long steps_per_scan = std::llround(1.0 / (sim_world.sensors.laser.rate_hz * sim_options.physics_step_s));
    const double frame_period_s = 1.0 / sim_world.sensors.camera.rate_hz;
    const Clock::time_point pass_start = Clock::now();
    int next_frame = 0;
    for (long long step = 0; sim.time_s() < options.max_pass_time_s; ++step) {
      if (step % std::max(1LL, steps_per_scan) == 0) {
        const LaserScan scan = sim.Scan();
        const VelocityCommand cmd = sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.odom_pose(),
                                                   sim.time_s());
        if (sweep.phase() == SweepPhase::kDone) break;
        sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
      }
      if (sim.time_s() + 1e-9 >= next_frame * frame_period_s) {
        ++next_frame;
        const cv::Mat frame = sim.CameraImage();
        const Pose2D pose = sim.true_pose();
        const double stamp = sim.time_s();
        ++pass_result.frames;
        const bool on_leg = sweep.phase() == SweepPhase::kFollowOut || sweep.phase() == SweepPhase::kFollowBack;
        const std::vector<int> passed_now = scorer.ObserveFrame(pose, on_leg);
        const double t0 = ThreadCpuSeconds();
        const std::vector<PlateReport> reports = extractor.Process(frame, stamp);
        result.extractor_seconds += ThreadCpuSeconds() - t0;
        result.extractor_boxes += static_cast<int>(extractor.last_observations().size());
        for (const PlateReport& report : reports) {
          const ReportVerdict verdict = scorer.ScoreReport(report, pose);
          if (verdict.kind == ReportKind::kCorrect && !verdict.duplicate) continue;
          OcrEvalEvent event;
          event.kind = verdict.kind == ReportKind::kFalseRead ? "false_read"
                       : verdict.kind == ReportKind::kSpurious ? "spurious" : "duplicate";
          event.pass = pass;
          event.stamp_s = stamp;
          event.reported = report.text;
          event.box_px = report.box_px;
          if (verdict.plate >= 0) {
            event.truth = scorer.plates()[verdict.plate].text;
            event.plate = scorer.plates()[verdict.plate].label;
          }
          if (!options.dump_dir.empty()) {
            event.image = DumpImage(options.dump_dir, world.name, event,
                                    Annotate(frame, extractor.last_observations(), report.box_px, scorer, pose));
          }
          result.events.push_back(event);
        }
        for (const int plate : passed_now) {
          crossing_stamps[plate] = stamp;
          if (!options.dump_dir.empty()) {
            crossing_frames[plate] = Annotate(frame, extractor.last_observations(), {}, scorer, pose);
          }
        }
        if (options.detector_every_n_frames > 0 && (pass_result.frames - 1) % options.detector_every_n_frames == 0) {
          cv::Mat grey;
          cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
          const bool plate_in_view = scorer.CountVisible(pose) > 0;
          for (Fig12Detector& d : fig12) {
            const double t1 = ThreadCpuSeconds();
            const size_t boxes = d.detector->Detect(grey).size();
            d.stats.seconds += ThreadCpuSeconds() - t1;
            ++d.stats.frames;
            d.stats.boxes += static_cast<long long>(boxes);
            if (plate_in_view) {
              ++d.stats.frames_plate_in_view;
              d.stats.boxes_plate_in_view += static_cast<long long>(boxes);
            }
          }
        }
      }
      sim.Step();
      if (progress.Due(run_sim_s + sim.time_s())) {
        const PassScore& score = scorer.pass();
        progress.Show("ocr: pass %d/%d, %.0f s simulated, %.1f m driven, %d frames, %d plates passed, %d read right, "
                      "%d false reads, %s", pass + 1, options.passes, run_sim_s + sim.time_s(),
                      sim.distance_travelled_m(), pass_result.frames, score.plates_passed, score.plates_correct,
                      score.false_reads, SweepPhaseName(sweep.phase()));
      }
    }
    run_sim_s += sim.time_s();
    pass_result.sweep_done = sweep.phase() == SweepPhase::kDone;
    pass_result.sim_seconds = sim.time_s();
    pass_result.wall_seconds = SecondsSince(pass_start);
    pass_result.score = scorer.pass();
    for (size_t i = 0; i < scorer.plates().size(); ++i) {
      const PlatePassRecord& record = pass_result.score.plates[i];
      if (!record.passed || record.correct_reports > 0) continue;
      OcrEvalEvent event;
      event.kind = "missed";
      event.pass = pass;
      event.truth = scorer.plates()[i].text;
      event.plate = scorer.plates()[i].label;
      event.stamp_s = crossing_stamps[static_cast<int>(i)];
      for (const std::string& text : record.reported_texts) event.reported += (event.reported.empty() ? "" : ",") + text;
      const auto frame = crossing_frames.find(static_cast<int>(i));
      if (frame != crossing_frames.end()) event.image = DumpImage(options.dump_dir, world.name, event, frame->second);
      result.events.push_back(event);
    }
    result.passes.push_back(pass_result);
  }
  progress.Finish();
  for (Fig12Detector& d : fig12) result.detectors.push_back(d.stats);
  return result;
}

}  // namespace doorplate_localization
