// doorplate_laser_fit's plot: real and simulated laser statistics side by side, drawn with OpenCV.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "laser_fit_report.h"
#include "doorplate_localization/laser_fit/distribution_distance.h"

namespace doorplate_localization::tools {
namespace {

struct Series {
  std::string name;
  cv::Scalar color;
  std::vector<double> x, y;
};

constexpr long kMinTrials = 50;  // rate points from fewer beams are not drawn

std::string Format(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof(b), format, v);
  return b;
}

void Text(cv::Mat& image, const std::string& text, cv::Point at, double scale = 0.45,
          cv::Scalar color = cv::Scalar(0, 0, 0)) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, color, 1, cv::LINE_AA);
}

// One panel: axes over [x0, x1] × [y0, y1] (log10 y when log_y), a polyline with dots per series, legend.
void DrawPanel(cv::Mat& image, cv::Rect area, const std::string& title, const std::string& x_label, double x0,
               double x1, double y0, double y1, bool log_y, const std::vector<Series>& series) {
  const cv::Rect plot(area.x + 70, area.y + 35, area.width - 90, area.height - 85);
  cv::rectangle(image, plot, cv::Scalar(0, 0, 0), 1);
  Text(image, title, {area.x + 70, area.y + 22}, 0.55);
  Text(image, x_label, {plot.x + plot.width / 2 - 60, plot.y + plot.height + 40});
  const auto fy = [&](double y) { return log_y ? std::log10(std::max(y, 1e-12)) : y; };
  const double ly0 = fy(y0), ly1 = fy(y1);
  const auto px = [&](double x) { return plot.x + static_cast<int>(std::lround((x - x0) / (x1 - x0) * plot.width)); };
  const auto py = [&](double y) {
    const double t = std::clamp((fy(y) - ly0) / (ly1 - ly0), 0.0, 1.0);
    return plot.y + plot.height - static_cast<int>(std::lround(t * plot.height));
  };
  for (int k = 0; k <= 4; ++k) {
    const double x = x0 + k * (x1 - x0) / 4;
    cv::line(image, {px(x), plot.y + plot.height}, {px(x), plot.y + plot.height + 5}, cv::Scalar(0, 0, 0));
    Text(image, Format(std::fabs(x1 - x0) < 2 ? "%.2f" : "%.0f", x), {px(x) - 15, plot.y + plot.height + 20});
    const double y = log_y ? std::pow(10.0, ly0 + k * (ly1 - ly0) / 4) : y0 + k * (y1 - y0) / 4;
    cv::line(image, {plot.x - 5, py(y)}, {plot.x, py(y)}, cv::Scalar(0, 0, 0));
    cv::line(image, {plot.x, py(y)}, {plot.x + plot.width, py(y)}, cv::Scalar(225, 225, 225));
    Text(image, Format(log_y ? "%.0e" : "%.3f", y), {area.x + 5, py(y) + 5}, 0.4);
  }
  int legend_y = plot.y + 18;
  for (const Series& s : series) {
    std::vector<cv::Point> points;
    for (size_t k = 0; k < s.x.size(); ++k) {
      if (s.x[k] < x0 || s.x[k] > x1 || (log_y && s.y[k] <= 0)) continue;
      points.emplace_back(px(s.x[k]), py(s.y[k]));
    }
    cv::polylines(image, points, false, s.color, 2, cv::LINE_AA);
    for (const cv::Point& p : points) cv::circle(image, p, 3, s.color, cv::FILLED, cv::LINE_AA);
    cv::line(image, {plot.x + plot.width - 330, legend_y - 4}, {plot.x + plot.width - 305, legend_y - 4}, s.color, 2);
    Text(image, s.name, {plot.x + plot.width - 300, legend_y}, 0.42);
    legend_y += 18;
  }
}

std::vector<double> Mids(const std::vector<double>& edges) {
  std::vector<double> m;
  for (size_t k = 0; k + 1 < edges.size(); ++k) m.push_back(0.5 * (edges[k] + edges[k + 1]));
  return m;
}

// Rate per bin; bins with too few trials are left out.
Series RateSeries(const std::string& name, cv::Scalar color, const std::vector<double>& mids, const BinnedRate& r) {
  Series s{name, color, {}, {}};
  for (size_t k = 0; k < mids.size(); ++k) {
    if (r.trials[k] < kMinTrials) continue;
    s.x.push_back(mids[k]), s.y.push_back(r.Rate(k));
  }
  return s;
}

double MaxY(const std::vector<Series>& series) {
  double m = 0.0;
  for (const Series& s : series) {
    for (const double y : s.y) m = std::max(m, y);
  }
  return m > 0 ? m * 1.1 : 1.0;
}

}  // namespace

void WriteLaserFitPlot(const LaserFitReport& r, const std::string& path) {
  const cv::Scalar kReal(0, 0, 0), kFitted(40, 40, 220), kGaussian(200, 120, 30);
  const int w = 760, h = 430;
  cv::Mat image(2 * h, 2 * w, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto label = [](const std::string& name, const std::string& distance) { return name + " " + distance; };
  // 1. Core error histograms.
  constexpr double kBinM = 0.005;
  const int bins = static_cast<int>(2 * kErrorWindowM / kBinM);
  const auto hist = [&](const NamedTally& n, cv::Scalar color, const std::string& name) {
    std::vector<float> e;
    for (const CoreReturn& c : n.tally->core) e.push_back(c.error_m);
    const std::vector<double> counts = Histogram(e, -kErrorWindowM, kErrorWindowM, bins);
    Series s{name, color, {}, {}};
    const double total = std::max<double>(1.0, e.size());
    for (int k = 0; k < bins; ++k) s.x.push_back(-kErrorWindowM + (k + 0.5) * kBinM), s.y.push_back(counts[k] / total);
    return s;
  };
  std::vector<Series> errors = {
      hist(r.real, kReal, "real (SICK, 4 CARMEN logs)"),
      hist(r.fitted_sim, kFitted, label("fitted", Format("JSD %.3f", r.fitted_distance.error_jsd))),
      hist(r.gaussian_sim, kGaussian, label("gaussian", Format("JSD %.3f", r.gaussian_distance.error_jsd)))};
  DrawPanel(image, {0, 0, w, h}, "core range error (reading - expected), fraction per 5 mm", "error, m",
            -kErrorWindowM, kErrorWindowM, 1e-4, 1.0, true, errors);
  // 2. Dropouts by range.
  const std::vector<double> range_mids = Mids(r.bins.range_bins_m), inc_mids = Mids(r.bins.incidence_bins_deg);
  std::vector<Series> by_range = {
      RateSeries("real", kReal, range_mids, r.real.tally->dropout_by_range),
      RateSeries(label("fitted", Format("mean |diff| %.4f", r.fitted_distance.dropout_range_w1)), kFitted, range_mids,
                 r.fitted_sim.tally->dropout_by_range),
      RateSeries(label("gaussian", Format("mean |diff| %.4f", r.gaussian_distance.dropout_range_w1)), kGaussian,
                 range_mids, r.gaussian_sim.tally->dropout_by_range)};
  DrawPanel(image, {w, 0, w, h}, "dropout rate vs expected range", "expected range, m", 0.0,
            r.bins.range_bins_m.back(), 0.0, MaxY(by_range), false, by_range);
  // 3. Dropouts by incidence.
  std::vector<Series> by_inc = {
      RateSeries("real", kReal, inc_mids, r.real.tally->dropout_by_incidence),
      RateSeries(label("fitted", Format("mean |diff| %.4f", r.fitted_distance.dropout_incidence_w1)), kFitted,
                 inc_mids, r.fitted_sim.tally->dropout_by_incidence),
      RateSeries(label("gaussian", Format("mean |diff| %.4f", r.gaussian_distance.dropout_incidence_w1)), kGaussian,
                 inc_mids, r.gaussian_sim.tally->dropout_by_incidence)};
  DrawPanel(image, {0, h, w, h}, "dropout rate vs incidence angle", "incidence, deg", 0.0, 90.0, 0.0, MaxY(by_inc),
            false, by_inc);
  // 4. Short returns by expected range.
  std::vector<Series> shorts = {
      RateSeries(label("real", Format("all %.4f", r.fitted_distance.short_rate_real)), kReal, range_mids,
                 r.real.tally->short_by_range),
      RateSeries(label("fitted", Format("all %.4f", r.fitted_distance.short_rate_sim) +
                                     Format(", W1 of ranges %.2f m", r.fitted_distance.short_range_w1_m)),
                 kFitted, range_mids, r.fitted_sim.tally->short_by_range),
      RateSeries(label("gaussian", Format("all %.4f", r.gaussian_distance.short_rate_sim)), kGaussian, range_mids,
                 r.gaussian_sim.tally->short_by_range)};
  DrawPanel(image, {w, h, w, h}, "spurious short-return rate vs expected range", "expected range, m", 0.0,
            r.bins.range_bins_m.back(), 0.0, MaxY(shorts), false, shorts);
  if (!cv::imwrite(path, image)) throw std::runtime_error(path + ": cannot write the plot");
}

}  // namespace doorplate_localization::tools
