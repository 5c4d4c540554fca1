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

#include "cli_args.h"
#include "output_guard.h"
#include "doorplate_localization/text/text_extractor.h"
#include "json_writer.h"

namespace dl = doorplate_localization;
namespace tools = doorplate_localization::tools;

namespace {

const char* kUsage =
    "Usage: doorplate_read_image [options] IMAGE...\n"
    "  --width PX            scale each image to this width first (0: native size; default 0)\n"
    "  --detector mser|db    text detector (default mser; db needs scripts/fetch_ocr_models.sh)\n"
    "  --recognizer tesseract|ppocr   recogniser (default tesseract; ppocr needs the same models)\n"
    "  --band                search only the band of docs/parameters.md (default: the whole image)\n"
    "  --pattern REGEX       room-number grammar (default: the reader's default)\n"
    "  --known-rooms A,B,..  known rooms (the validator then maps readings to them)\n"
    "  --max-regions N       text boxes read per image, largest first (default 32)\n"
    "  --whitelist CHARS     Tesseract's character whitelist (default: the reader's)\n"
    "  --model-dir DIR       folder of the learned models (default: DOORPLATE_OCR_MODEL_DIR or "
    "/usr/local/share/doorplate_localization/ocr_models)\n"
    "  --json FILE           also write every read as JSON to FILE ('-': stdout, text output off)\n"
    "Exit status: 0 done, 1 an image or model could not be read, 2 bad command line.\n";

struct Args {
  std::vector<std::string> images;
  int width_px = 0;
  int max_regions = 32;
  std::string json;
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

Args Parse(int argc, char** argv) {
  Args args;
  args.options.detector.band.enabled = false;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    tools::ExitIfHelp(option, kUsage);
    try {
      if (option == "--width") {
        args.width_px = static_cast<int>(tools::ParseWholeNumber(option, tools::TakeValue(argc, argv, &i), 0));
      } else if (option == "--detector") {
        args.options.detector_type = dl::ParseTextDetectorType(tools::TakeValue(argc, argv, &i), option);
      } else if (option == "--recognizer") {
        args.options.recognizer_type = dl::ParseTextRecognizerType(tools::TakeValue(argc, argv, &i), option);
      } else if (option == "--band") {
        args.options.detector.band.enabled = true;
      } else if (option == "--pattern") {
        args.options.validator.pattern = tools::TakeValue(argc, argv, &i);
      } else if (option == "--known-rooms") {
        args.options.validator.known_rooms = SplitComma(tools::TakeValue(argc, argv, &i));
      } else if (option == "--max-regions") {
        args.max_regions = static_cast<int>(tools::ParseWholeNumber(option, tools::TakeValue(argc, argv, &i), 1));
      } else if (option == "--whitelist") {
        args.options.ocr.whitelist = tools::TakeValue(argc, argv, &i);
      } else if (option == "--model-dir") {
        args.options.ppocr.model_dir = args.options.db_detector.model_dir = tools::TakeValue(argc, argv, &i);
      } else if (option == "--json") {
        args.json = tools::TakeValue(argc, argv, &i);
      } else if (!option.empty() && option[0] == '-') {
        throw tools::UsageError("unknown option " + option);
      } else {
        args.images.push_back(option);
      }
    } catch (const std::invalid_argument& e) {
      throw tools::UsageError(e.what());
    }
  }
  if (args.images.empty()) throw tools::UsageError("no image given");
  args.options.max_regions_per_frame = args.max_regions;
  return args;
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

void WriteJson(const Args& args, const std::vector<ImageResult>& results, std::ostream* out) {
  dl::JsonWriter json(out);
  json.BeginObject()
      .Field("detector", dl::ToString(args.options.detector_type))
      .Field("recognizer", dl::ToString(args.options.recognizer_type))
      .Field("band", args.options.detector.band.enabled)
      .Field("width_px", args.width_px)
      .Key("images")
      .BeginArray();
  for (const ImageResult& r : results) {
    json.BeginObject()
        .Field("file", r.file)
        .Field("width_px", r.size_px.width)
        .Field("height_px", r.size_px.height)
        .Field("cpu_seconds", r.cpu_seconds)
        .Field("wall_seconds", r.wall_seconds)
        .Key("reads")
        .BeginArray();
    for (const dl::PlateObservation& o : r.reads) {
      json.BeginObject()
          .Field("raw_text", o.raw_text)
          .Field("raw_confidence", o.raw_confidence)
          .Field("room", o.text)
          .Field("confidence", o.confidence)
          .Key("box_px")
          .BeginArray()
          .Value(o.box_px.x)
          .Value(o.box_px.y)
          .Value(o.box_px.width)
          .Value(o.box_px.height)
          .EndArray()
          .EndObject();
    }
    json.EndArray().EndObject();
  }
  json.EndArray().EndObject();
  *out << "\n";
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
    WriteJson(args, results, &std::cout);
  } else if (!args.json.empty()) {
    std::ofstream out(args.json);
    if (!out) throw std::runtime_error("cannot write " + args.json);
    WriteJson(args, results, &out);
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_read_image", kUsage, &Parse, &Run, argc, argv);
}
