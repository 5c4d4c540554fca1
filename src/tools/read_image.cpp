// doorplate_read_image: the doorplate reader on still images. Runs TextExtractor::ReadFrame (the same
// detection, recognition and validation the robot's stream runs, without the multi-frame tracker) on
// each image and prints every text box it read: box, recogniser output, validated room text (or "-"),
// confidence, and the time the image took. ROS-free.
#include <chrono>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli_app.h"
#include "output_guard.h"
#include "doorplate_localization/text/text_extractor.h"
#include "result_json.h"

namespace dl = doorplate_localization;
namespace tools = doorplate_localization::tools;

namespace {

const char kDescription[] =
    "The doorplate reader on still images: every text box read, its recogniser output and validated room.";
const char kNotes[] = "Exit status: 0 done, 1 an image or model could not be read, 2 bad command line.";

struct Args {
  std::vector<std::string> images;
  int width_px = 0;
  int max_regions = 32;
  std::string detector = "mser", recognizer = "tesseract", known_rooms, model_dir, json;
  dl::TextExtractorOptions options;
};

std::vector<std::string> SplitComma(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

void AddOptions(CLI::App* app, Args* args) {
  dl::TextExtractorOptions& o = args->options;
  o.detector.band.enabled = false;
  app->footer(kNotes);
  app->add_option("IMAGE", args->images, "images to read")->required();
  app->add_option("--width", args->width_px, "scale each image to this width first (0: native size)")
      ->capture_default_str()->transform(tools::WholeNumber(0));
  app->add_option("--detector", args->detector, "text detector: mser or db (db needs scripts/fetch_ocr_models.sh)")
      ->capture_default_str();
  app->add_option("--recognizer", args->recognizer, "recogniser: tesseract or ppocr (ppocr needs the same models)")
      ->capture_default_str();
  app->add_flag("--band", o.detector.band.enabled, "search only the band of docs/parameters.md (default: the "
                "whole image)");
  app->add_option("--pattern", o.validator.pattern, "room-number grammar")->capture_default_str();
  app->add_option("--known-rooms", args->known_rooms, "A,B,..: known rooms (the validator then maps readings to them)");
  app->add_option("--max-regions", args->max_regions, "text boxes read per image, largest first")
      ->capture_default_str()->transform(tools::WholeNumber(1));
  app->add_option("--whitelist", o.ocr.whitelist, "Tesseract's character whitelist")->capture_default_str();
  app->add_option("--model-dir", args->model_dir, "folder of the learned models [DOORPLATE_OCR_MODEL_DIR or "
                  "/usr/local/share/doorplate_localization/ocr_models]");
  app->add_option("--json", args->json, "also write every read as JSON to FILE ('-': stdout, text output off)");
  app->callback([args] {
    dl::TextExtractorOptions& o = args->options;
    try {
      o.detector_type = dl::ParseTextDetectorType(args->detector, "--detector");
      o.recognizer_type = dl::ParseTextRecognizerType(args->recognizer, "--recognizer");
    } catch (const std::invalid_argument& e) {
      throw tools::UsageError(e.what());
    }
    if (!args->known_rooms.empty()) o.validator.known_rooms = SplitComma(args->known_rooms);
    if (!args->model_dir.empty()) o.ppocr.model_dir = o.db_detector.model_dir = args->model_dir;
    o.max_regions_per_frame = args->max_regions;
  });
}

struct ImageResult {
  std::string file;
  cv::Size size_px;
  double cpu_seconds = 0.0;
  double wall_seconds = 0.0;
  std::vector<dl::PlateObservation> reads;
};

double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

ImageResult ReadOne(dl::TextExtractor& extractor, const std::string& file, int width_px) {
  cv::Mat image = cv::imread(file, cv::IMREAD_COLOR);
  if (image.empty()) throw std::runtime_error(file + ": not an image OpenCV can read");
  if (width_px > 0 && width_px != image.cols) {
    const double scale = static_cast<double>(width_px) / image.cols;
    cv::resize(image, image, cv::Size(), scale, scale, scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  }
  ImageResult result;
  result.file = file;
  result.size_px = image.size();
  const double cpu0 = ThreadCpuSeconds();
  const auto wall0 = std::chrono::steady_clock::now();
  result.reads = extractor.ReadFrame(image);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  result.cpu_seconds = ThreadCpuSeconds() - cpu0;
  return result;
}

void PrintText(const ImageResult& r) {
  std::cout << r.file << " " << r.size_px.width << "x" << r.size_px.height << " " << std::fixed
            << std::setprecision(1) << 1e3 * r.cpu_seconds << " ms cpu\n";
  for (const dl::PlateObservation& o : r.reads) {
    std::cout << "  box " << o.box_px.x << "," << o.box_px.y << "," << o.box_px.width << "," << o.box_px.height
              << "  read '" << o.raw_text << "' " << std::setprecision(3) << o.raw_confidence << "  room "
              << (o.text.empty() ? "-" : o.text) << "\n";
  }
}

dl::Json ReadsJson(const Args& args, const std::vector<ImageResult>& results) {
  dl::Json json;
  json["detector"] = dl::ToString(args.options.detector_type);
  json["recognizer"] = dl::ToString(args.options.recognizer_type);
  json["band"] = args.options.detector.band.enabled;
  json["width_px"] = args.width_px;
  json["images"] = dl::Json::array();
  for (const ImageResult& r : results) {
    dl::Json image;
    image["file"] = r.file;
    image["width_px"] = r.size_px.width;
    image["height_px"] = r.size_px.height;
    image["cpu_seconds"] = r.cpu_seconds;
    image["wall_seconds"] = r.wall_seconds;
    image["reads"] = dl::Json::array();
    for (const dl::PlateObservation& o : r.reads) {
      image["reads"].push_back({{"raw_text", o.raw_text},
                                {"raw_confidence", o.raw_confidence},
                                {"room", o.text},
                                {"confidence", o.confidence},
                                {"box_px", {o.box_px.x, o.box_px.y, o.box_px.width, o.box_px.height}}});
    }
    json["images"].push_back(image);
  }
  return json;
}

int Run(const Args& args) {
  cv::setNumThreads(1);  // one core, as on the robot (OMP_THREAD_LIMIT=1 does the same for Tesseract)
  if (!args.json.empty() && args.json != "-") {
    std::vector<tools::NamedPath> inputs;
    for (const std::string& file : args.images) inputs.push_back({"IMAGE", file});
    tools::RefuseOverwritingInputs(inputs, {{"--json", args.json}});
  }
  dl::TextExtractor extractor(args.options);
  std::vector<ImageResult> results;
  int status = 0;
  for (const std::string& file : args.images) {
    try {
      results.push_back(ReadOne(extractor, file, args.width_px));
      if (args.json != "-") PrintText(results.back());
    } catch (const std::runtime_error& e) {
      std::cerr << "doorplate_read_image: " << e.what() << "\n";
      status = 1;
    }
  }
  if (args.json == "-") {
    std::cout << dl::ResultJsonText(ReadsJson(args, results));
  } else if (!args.json.empty()) {
    std::ofstream out(args.json);
    if (!out || !(out << dl::ResultJsonText(ReadsJson(args, results)))) throw std::runtime_error("cannot write " + args.json);
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_read_image", kDescription, AddOptions, Run, argc, argv);
}
