#include "sign_texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

constexpr double kSignPxPerM = 1500.0;  // sign texture resolution (the camera needs < 400 px/m at 1.5 m)
constexpr double kMaxSignTexturePx = 4096.0;

int HersheyFace(SignFont font) {
  switch (font) {
    case SignFont::kDuplex: return cv::FONT_HERSHEY_DUPLEX;
    case SignFont::kComplex: return cv::FONT_HERSHEY_COMPLEX;
    case SignFont::kTriplex: return cv::FONT_HERSHEY_TRIPLEX;
    case SignFont::kPlain: return cv::FONT_HERSHEY_PLAIN;
    case SignFont::kComplexSmall: return cv::FONT_HERSHEY_COMPLEX_SMALL;
    case SignFont::kScriptSimplex: return cv::FONT_HERSHEY_SCRIPT_SIMPLEX;
    case SignFont::kScriptComplex: return cv::FONT_HERSHEY_SCRIPT_COMPLEX;
    case SignFont::kSimplex: break;
  }
  return cv::FONT_HERSHEY_SIMPLEX;
}

std::string SignName(const TextSign& sign, std::size_t index) {
  return "signs[" + std::to_string(index) + "] ('" + sign.text + "')";
}

// The photographed face, stretched to w × h texels (area averaging when shrinking).
cv::Mat ImageFace(const TextSign& sign, std::size_t index, int w, int h) {
  const cv::Mat photo = cv::imread(sign.image_path, cv::IMREAD_COLOR);
  if (photo.empty()) {
    throw std::invalid_argument("CameraRenderer: world " + SignName(sign, index) + ".image: cannot read image '" +
                                sign.image_path + "'");
  }
  cv::Mat face;
  const bool shrink = w < photo.cols && h < photo.rows;
  cv::resize(photo, face, cv::Size(w, h), 0, 0, shrink ? cv::INTER_AREA : cv::INTER_CUBIC);
  return face;
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines(1);
  for (char c : text) {
    if (c == '\n') lines.emplace_back(); else lines.back() += c;
  }
  return lines;
}

// Filled background, thin border in the text colour, text lines centred.
cv::Mat DrawTextFace(const TextSign& sign, double px_per_m, int w, int h) {
  const cv::Scalar fg(sign.foreground[2], sign.foreground[1], sign.foreground[0]);
  cv::Mat texture(h, w, CV_8UC3, cv::Scalar(sign.background[2], sign.background[1], sign.background[0]));
  const int border_px = std::max(1, static_cast<int>(std::lround(0.004 * px_per_m)));
  cv::rectangle(texture, cv::Rect(0, 0, w, h), fg, 2 * border_px);  // centred on the edge: half shows

  const std::vector<std::string> lines = SplitLines(sign.text);
  const int face = HersheyFace(sign.font) | (sign.italic ? cv::FONT_ITALIC : 0);
  int baseline = 0;
  const double cap_unit = cv::getTextSize("H", face, 1.0, 1, &baseline).height;
  double width_unit = 0.0;
  for (const std::string& line : lines) {
    width_unit = std::max<double>(width_unit, cv::getTextSize(line, face, 1.0, 1, &baseline).width);
  }
  if (width_unit > 0.0) {
    const int n = static_cast<int>(lines.size());
    const double block_units = n + 0.6 * (n - 1);  // line gap: 0.6 cap heights
    const double fill = n == 1 ? 0.33 : 0.6;  // 4 cm digits on a 12 cm plate
    const double block_px = sign.text_height_m > 0.0 ? sign.text_height_m * px_per_m * block_units : fill * h;
    double scale = std::min(block_px / (cap_unit * block_units), 0.84 * w / width_unit);
    const int thickness =
        std::max(1, static_cast<int>(std::lround(sign.stroke_to_cap_height * cap_unit * scale)));
    for (const std::string& line : lines) {  // thick strokes widen the text: shrink to fit
      const double line_w = cv::getTextSize(line, face, scale, thickness, &baseline).width;
      if (line_w > 0.9 * w) scale *= 0.9 * w / line_w;
    }
    const double cap = cap_unit * scale;
    const double top = (h - cap * block_units) / 2.0;
    for (int i = 0; i < n; ++i) {
      const int line_w = cv::getTextSize(lines[i], face, scale, thickness, &baseline).width;
      const cv::Point origin((w - line_w) / 2, static_cast<int>(std::lround(top + cap * (1.6 * i + 1.0))));
      cv::putText(texture, lines[i], origin, face, scale, fg, thickness, cv::LINE_AA);
    }
  }
  return texture;
}

}  // namespace

std::vector<cv::Mat> MakeSignPyramid(const TextSign& sign, std::size_t index) {
  if (!(sign.width_m > 0.0) || !(sign.height_m > 0.0) || !(sign.text_height_m >= 0.0) ||
      !(sign.stroke_to_cap_height > 0.0)) {
    throw std::invalid_argument("CameraRenderer: world " + SignName(sign, index) +
                                ": width_m, height_m and stroke_to_cap_height must be > 0, text_height_m >= 0");
  }
  const double px_per_m = std::min(kSignPxPerM, kMaxSignTexturePx / std::max(sign.width_m, sign.height_m));
  const int w = std::max(8, static_cast<int>(std::lround(sign.width_m * px_per_m)));
  const int h = std::max(8, static_cast<int>(std::lround(sign.height_m * px_per_m)));
  std::vector<cv::Mat> levels;
  if (!sign.image_path.empty()) {
    levels.push_back(ImageFace(sign, index, w, h));
  } else {
    levels.push_back(DrawTextFace(sign, px_per_m, w, h));
  }
  while (std::min(levels.back().cols, levels.back().rows) >= 4 && levels.size() < 12) {
    cv::Mat smaller;
    cv::pyrDown(levels.back(), smaller);
    levels.push_back(smaller);
  }
  return levels;
}

void SampleSignColumn(const std::vector<cv::Mat>& levels, const TextSign& sign, double u_m,
                      double footprint_u_m, double coverage_u, double top_row, double rows_per_m,
                      double shade, int first, int last, cv::Vec3b* column) {
  const double footprint_v_m = 1.0 / rows_per_m;
  const double texels_per_px = footprint_v_m * levels[0].rows / sign.height_m;
  const int level = std::clamp(static_cast<int>(std::floor(std::log2(std::max(texels_per_px, 1.0)))), 0,
                               static_cast<int>(levels.size()) - 1);
  const cv::Mat& tex = levels[level];
  const double px_u = tex.cols / sign.width_m, px_v = tex.rows / sign.height_m;
  const int samples = std::clamp(static_cast<int>(std::lround(footprint_u_m / footprint_v_m)), 1, 8);
  std::array<int, 8> x0{}, x1{};
  std::array<float, 8> wx{};
  for (int i = 0; i < samples; ++i) {
    const double tx = (u_m + footprint_u_m * ((i + 0.5) / samples - 0.5)) * px_u - 0.5;
    const double fl = std::floor(tx);
    wx[i] = static_cast<float>(tx - fl);
    x0[i] = std::clamp(static_cast<int>(fl), 0, tex.cols - 1);
    x1[i] = std::clamp(static_cast<int>(fl) + 1, 0, tex.cols - 1);
  }
  const float gain = static_cast<float>(shade / samples);
  const double bottom_row = top_row + sign.height_m * rows_per_m;
  for (int r = first; r < last; ++r) {
    const double coverage_v = std::min(r + 0.5, bottom_row) - std::max(r - 0.5, top_row);
    const float alpha = static_cast<float>(coverage_u * std::clamp(coverage_v, 0.0, 1.0));
    const double ty = (r - top_row) / rows_per_m * px_v - 0.5;
    const double fl = std::floor(ty);
    const float wy = static_cast<float>(ty - fl);
    const cv::Vec3b* row0 = tex.ptr<cv::Vec3b>(std::clamp(static_cast<int>(fl), 0, tex.rows - 1));
    const cv::Vec3b* row1 = tex.ptr<cv::Vec3b>(std::clamp(static_cast<int>(fl) + 1, 0, tex.rows - 1));
    float acc[3] = {0.f, 0.f, 0.f};
    for (int i = 0; i < samples; ++i) {
      for (int ch = 0; ch < 3; ++ch) {
        const float top = row0[x0[i]][ch] + wx[i] * (row0[x1[i]][ch] - row0[x0[i]][ch]);
        const float bottom = row1[x0[i]][ch] + wx[i] * (row1[x1[i]][ch] - row1[x0[i]][ch]);
        acc[ch] += top + wy * (bottom - top);
      }
    }
    for (int ch = 0; ch < 3; ++ch) {
      column[r][ch] = cv::saturate_cast<uchar>(alpha * acc[ch] * gain + (1.f - alpha) * column[r][ch]);
    }
  }
}

}  // namespace doorplate_localization
