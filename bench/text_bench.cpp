// Text extractor throughput on 640×480 frames, with the fixed band (the paper's method) and on the full
// image, on one core (cv::setNumThreads(1); run with OMP_THREAD_LIMIT=1 for Tesseract). Also prints the
// mean number of text boxes per frame for MSER, MSER + NMS and band + MSER + NMS (paper Fig. 12).
// Usage: doorplate_text_bench [--frames N] [--size WxH] [--recognizer tesseract|ppocr] [image ...]
//   Without images: N synthetic corridor frames (seeded) — wall, door, handle, a moving doorplate, a
//   poster and a sign — drawn at 640×480 and scaled to --size (e.g. 1280x720: a USB camera; the band
//   fractions are kept). With images: they are processed in turn until N frames have been processed.
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_app.h"
#include "doorplate_localization/text/text_extractor.h"

namespace dl = doorplate_localization;

namespace {

void Text(cv::Mat& image, const std::string& text, cv::Point center, double scale, cv::Scalar plate) {
  int baseline = 0;
  const cv::Size s = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 2, &baseline);
  const cv::Rect t(center.x - s.width / 2, center.y - s.height / 2, s.width, s.height);
  cv::rectangle(image, cv::Rect(t.x - t.height, t.y - t.height / 2, t.width + 2 * t.height, 2 * t.height),
                plate, cv::FILLED);
  cv::putText(image, text, cv::Point(t.x, t.y + t.height), cv::FONT_HERSHEY_SIMPLEX, scale,
              cv::Scalar(25, 25, 25), 2, cv::LINE_AA);
}

// A corridor wall seen sideways; everything slides left by 12 px per frame.
cv::Mat SyntheticFrame(int i, cv::RNG& rng) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(200, 205, 210));
  const int shift = (i * 12) % 900;
  const int door_x = 700 - shift;
  cv::rectangle(image, cv::Rect(door_x - 110, 120, 220, 360), cv::Scalar(60, 95, 140), cv::FILLED);
  cv::rectangle(image, cv::Rect(door_x - 116, 114, 232, 366), cv::Scalar(90, 90, 90), 4);
  cv::circle(image, cv::Point(door_x + 80, 400), 10, cv::Scalar(50, 50, 50), cv::FILLED);
  Text(image, std::to_string(201 + 2 * (i / 75)), cv::Point(door_x + 200, 228), 1.0, cv::Scalar(240, 245, 245));
  Text(image, "FIRE EXIT", cv::Point(door_x + 420, 70), 0.9, cv::Scalar(60, 160, 60));
  Text(image, "NO 5 PARKING", cv::Point(door_x - 300, 440), 0.7, cv::Scalar(230, 230, 230));
  cv::Mat noise(image.size(), CV_16SC3);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 3.0);
  cv::Mat noisy;
  image.convertTo(noisy, CV_16SC3);
  noisy += noise;
  noisy.convertTo(image, CV_8UC3);
  return image;
}

// Wall-clock and process CPU time (the CPU figure is robust to other processes sharing the cores).
class Timer {
 public:
  Timer() : wall_(std::chrono::steady_clock::now()), cpu_(std::clock()) {}
  double WallS() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count(); }
  double CpuS() const { return static_cast<double>(std::clock() - cpu_) / CLOCKS_PER_SEC; }

 private:
  std::chrono::steady_clock::time_point wall_;
  std::clock_t cpu_;
};

struct Result {
  double fps = 0.0;      // frames per wall-clock second
  double cpu_fps = 0.0;  // frames per CPU second of this process
  double boxes_per_frame = 0.0;
  std::string reports;  // texts reported, in order
};

// Whole extractor (detection + OCR + validation + tracking).
Result RunExtractor(const std::vector<cv::Mat>& frames, bool band, dl::TextRecognizerType recognizer) {
  dl::TextExtractorOptions options;
  options.detector.band.enabled = band;
  options.recognizer_type = recognizer;
  dl::UseReadingScheduleFor(recognizer, &options.tracker);
  const double scale = frames[0].cols / 640.0;  // the tracker's intrinsics follow the size (same field of view)
  options.tracker.fx_px *= scale;
  options.tracker.cx_px = frames[0].cols / 2.0;
  options.tracker.max_center_jump_px *= scale;
  // (the detector scales its pixel sizes itself: MserBandDetectorOptions::reference_width_px)
  dl::TextExtractor extractor(options);
  Result result;
  size_t boxes = 0;
  const Timer timer;
  for (size_t i = 0; i < frames.size(); ++i) {
    for (const dl::PlateReport& r : extractor.Process(frames[i], 0.1 * i)) result.reports += r.text + " ";
    boxes += extractor.last_observations().size();
  }
  result.fps = frames.size() / timer.WallS();
  result.cpu_fps = frames.size() / timer.CpuS();
  result.boxes_per_frame = static_cast<double>(boxes) / frames.size();
  return result;
}

// Detector only.
Result RunDetector(const std::vector<cv::Mat>& frames, bool band, bool nms) {
  dl::MserBandDetectorOptions options;
  options.band.enabled = band;
  options.nms_enabled = nms;
  const dl::MserBandDetector detector(options);
  Result result;
  size_t boxes = 0;
  const Timer timer;
  for (const cv::Mat& frame : frames) {
    cv::Mat grey;
    cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
    boxes += detector.Detect(grey).size();
  }
  result.fps = frames.size() / timer.WallS();
  result.cpu_fps = frames.size() / timer.CpuS();
  result.boxes_per_frame = static_cast<double>(boxes) / frames.size();
  return result;
}

struct Args {
  int num_frames = 300;
  std::string size_text = "640x480", recognizer_name = "tesseract";
  cv::Size size{640, 480};
  dl::TextRecognizerType recognizer = dl::TextRecognizerType::kTesseract;
  std::vector<std::string> paths;
};

void AddOptions(CLI::App* app, Args* args) {
  app->add_option("--frames", args->num_frames, "frames to process")->capture_default_str()
      ->transform(dl::tools::WholeNumber(1));
  app->add_option("--size", args->size_text, "WIDTHxHEIGHT of the synthetic frames (at least 64x48)")
      ->capture_default_str();
  app->add_option("--recognizer", args->recognizer_name, "tesseract or ppocr")->capture_default_str();
  app->add_option("IMAGE", args->paths, "images to process in turn (default: synthetic frames)");
  app->callback([args] {
    char x = 0, extra = 0;
    if (std::sscanf(args->size_text.c_str(), "%d%c%d%c", &args->size.width, &x, &args->size.height, &extra) != 3 ||
        x != 'x' || args->size.width < 64 || args->size.height < 48) {
      throw dl::tools::UsageError("--size: '" + args->size_text + "' must be WIDTHxHEIGHT, at least 64x48");
    }
    try {
      args->recognizer = dl::ParseTextRecognizerType(args->recognizer_name, "--recognizer");
    } catch (const std::invalid_argument& e) {
      throw dl::tools::UsageError(e.what());
    }
  });
}

int Run(const Args& args) {
  const int num_frames = args.num_frames;
  const cv::Size size = args.size;
  const dl::TextRecognizerType recognizer = args.recognizer;
  const std::vector<std::string>& paths = args.paths;
  cv::setNumThreads(1);
  const char* omp = std::getenv("OMP_THREAD_LIMIT");
  std::printf("OMP_THREAD_LIMIT=%s, cv::getNumThreads()=%d\n", omp ? omp : "(unset)", cv::getNumThreads());

  std::vector<cv::Mat> frames;
  cv::RNG rng(42);
  for (int i = 0; i < num_frames; ++i) {
    if (paths.empty()) {
      cv::Mat frame = SyntheticFrame(i, rng);
      if (frame.size() != size) cv::resize(frame, frame, size, 0, 0, cv::INTER_LINEAR);
      frames.push_back(frame);
      continue;
    }
    const std::string& path = paths[i % paths.size()];
    cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
    if (image.empty()) {
      std::fprintf(stderr, "cannot read image %s\n", path.c_str());
      return 1;
    }
    frames.push_back(image);
  }
  std::printf("%d frames of %dx%d (%s)\n", num_frames, frames[0].cols, frames[0].rows,
              paths.empty() ? "synthetic" : "from files");

  const Result mser = RunDetector(frames, false, false);
  const Result mser_nms = RunDetector(frames, false, true);
  const Result band = RunDetector(frames, true, true);
  std::printf("fps = frames per wall-clock second (frames per CPU second of this process)\n");
  std::printf("detector only     : MSER %.1f (%.1f) fps %.2f boxes/frame | MSER+NMS %.1f (%.1f) fps %.2f "
              "boxes/frame | band+MSER+NMS %.1f (%.1f) fps %.2f boxes/frame\n",
              mser.fps, mser.cpu_fps, mser.boxes_per_frame, mser_nms.fps, mser_nms.cpu_fps,
              mser_nms.boxes_per_frame, band.fps, band.cpu_fps, band.boxes_per_frame);
  std::printf("recognizer: %s\n", dl::ToString(recognizer).c_str());
  const Result full = RunExtractor(frames, false, recognizer);
  const Result banded = RunExtractor(frames, true, recognizer);
  std::printf("extractor (w/ OCR): full image %.1f (%.1f) fps %.2f boxes/frame | band %.1f (%.1f) fps %.2f "
              "boxes/frame\n",
              full.fps, full.cpu_fps, full.boxes_per_frame, banded.fps, banded.cpu_fps, banded.boxes_per_frame);
  std::printf("reports: full image [ %s] | band [ %s]\n", full.reports.c_str(), banded.reports.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dl::tools::RunTool("doorplate_text_bench", "Text extractor throughput on 640x480 (or --size) frames, band and full "
                            "image, one core.", AddOptions, Run, argc, argv);
}
