#include "report_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kText = 0.55;  // font scale of labels, legends and axes
const cv::Scalar kInk(40, 40, 40), kGridLine(215, 215, 215), kTrue(0, 150, 0), kMapped(0, 0, 210),
    kArrow(0, 110, 255);

std::string Format(const char* format, double value) {
  char text[160];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

int TextWidth(const std::string& text, double scale = kText, int thickness = 1) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, thickness, &baseline).width;
}

void Text(cv::Mat& image, const std::string& text, cv::Point at, const cv::Scalar& color, double scale = kText,
          int thickness = 1) {
  cv::putText(image, text, at, kFont, scale, color, thickness, cv::LINE_AA);
}

// A white title strip above `body`.
cv::Mat WithTitle(const cv::Mat& body, const std::string& title) {
  cv::Mat image(body.rows + 40, std::max(body.cols, TextWidth(title, 0.75, 2) + 24), CV_8UC3,
                cv::Scalar(255, 255, 255));
  body.copyTo(image(cv::Rect(0, 40, body.cols, body.rows)));
  Text(image, title, {12, 28}, kInk, 0.75, 2);
  return image;
}

// The grid, one pixel per cell, y up: unknown light grey, free white, occupied dark.
cv::Mat CellImage(const OccupancyGrid& grid) {
  cv::Mat cells(grid.height, grid.width, CV_8UC3);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const int v = grid.At(x, y);
      const unsigned char c = v < 0 ? 228 : v >= 65 ? 30 : v <= 20 ? 255 : 150;
      cells.at<cv::Vec3b>(grid.height - 1 - y, x) = {c, c, c};
    }
  }
  return cells;
}

// Map frame -> pixels of one panel showing `window` at `px_per_m`.
struct PanelProjection {
  MapWindow window;
  double px_per_m;
  cv::Point operator()(Vec2 p) const {
    return {static_cast<int>(std::lround((p.x - window.x0_m) * px_per_m)),
            static_cast<int>(std::lround((window.y1_m - p.y) * px_per_m))};
  }
  Vec2 ToMap(double px, double py) const { return {window.x0_m + px / px_per_m, window.y1_m - py / px_per_m}; }
};

cv::Mat RenderWindow(const OccupancyGrid& grid, const cv::Mat& cells, const PanelProjection& to_px) {
  const cv::Size size(static_cast<int>(std::lround(to_px.window.WidthM() * to_px.px_per_m)),
                      static_cast<int>(std::lround(to_px.window.HeightM() * to_px.px_per_m)));
  // Panel pixel centre -> cell image coordinates (pixel centres at integers), an affine map.
  const Pose2D grid_from_map = grid.origin.Inverse();
  const auto source = [&](double px, double py) {
    const Vec2 local = grid_from_map.TransformPoint(to_px.ToMap(px + 0.5, py + 0.5));
    return cv::Point2f(static_cast<float>(local.x / grid.resolution_m - 0.5),
                       static_cast<float>(grid.height - local.y / grid.resolution_m - 0.5));
  };
  const cv::Point2f dst[3] = {{0, 0}, {100, 0}, {0, 100}};
  const cv::Point2f src[3] = {source(0, 0), source(100, 0), source(0, 100)};
  cv::Mat panel;
  cv::warpAffine(cells, panel, cv::getAffineTransform(dst, src), size, cv::INTER_NEAREST | cv::WARP_INVERSE_MAP,
                 cv::BORDER_CONSTANT, cv::Scalar(228, 228, 228));
  return panel;
}

void DrawPanelAxes(cv::Mat& panel, const PanelProjection& to_px) {
  const MapWindow& w = to_px.window;
  for (const double x : NiceTicks(w.x0_m, w.x1_m, std::max(2, panel.cols / 140))) {
    const int px = to_px({x, w.y1_m}).x;
    cv::line(panel, {px, 0}, {px, 8}, kInk, 1);
    Text(panel, Format("%g m", x), {px + 3, 18}, kInk, 0.45);
  }
  for (const double y : NiceTicks(w.y0_m, w.y1_m, std::max(2, panel.rows / 90))) {
    const int py = to_px({w.x0_m, y}).y;
    cv::line(panel, {0, py}, {8, py}, kInk, 1);
    Text(panel, Format("%g", y), {10, py + 5}, kInk, 0.45);
  }
  cv::rectangle(panel, {0, 0}, {panel.cols - 1, panel.rows - 1}, kInk, 1);
}

void DrawPlates(cv::Mat& panel, const PanelProjection& to_px, const std::vector<PlateErrorRow>& plates,
                double magnification) {
  const double mid_y = 0.5 * (to_px.window.y0_m + to_px.window.y1_m);
  for (const PlateErrorRow& row : plates) {
    const cv::Point t = to_px(row.truth);
    cv::drawMarker(panel, t, kTrue, cv::MARKER_CROSS, 16, 2, cv::LINE_AA);
    if (row.mapped) {
      cv::circle(panel, to_px(row.estimate), 6, kMapped, 2, cv::LINE_AA);
      const cv::Point head = to_px(row.truth + magnification * (row.estimate - row.truth));
      if (cv::norm(head - t) >= 3.0) cv::arrowedLine(panel, t, head, kArrow, 2, cv::LINE_AA, 0, 0.25);
    }
    const bool above = row.truth.y > mid_y;  // label outside the corridor
    const std::string label = row.mapped ? row.text : row.text + " (not mapped)";
    const int width = TextWidth(label, 0.6, 2);
    Text(panel, label, {t.x - width / 2, above ? t.y - 16 : t.y + 30}, row.mapped ? kMapped : kInk, 0.6, 2);
  }
}

// Legend entries flowing left to right, wrapped at `width`: a swatch (drawn from its left end, on the text's
// middle line) and a label.
class Legend {
 public:
  using Swatch = std::function<void(cv::Mat&, cv::Point)>;
  explicit Legend(int width) : width_(width) {}
  void Add(const std::string& label, const Swatch& swatch, int swatch_px = 30) {
    entries_.push_back({label, swatch, swatch_px});
  }
  cv::Mat Draw() const {
    std::vector<cv::Point> at;
    cv::Point cursor(12, 26);
    for (const Entry& e : entries_) {
      const int w = e.swatch_px + 10 + TextWidth(e.label) + 30;
      if (cursor.x + w > width_ && cursor.x > 12) cursor = {12, cursor.y + 30};
      at.push_back(cursor);
      cursor.x += w;
    }
    cv::Mat image(cursor.y + 16, width_, CV_8UC3, cv::Scalar(255, 255, 255));
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      entries_[i].swatch(image, at[i] + cv::Point(0, -5));
      Text(image, entries_[i].label, at[i] + cv::Point(entries_[i].swatch_px + 10, 0), kInk);
    }
    return image;
  }

 private:
  struct Entry {
    std::string label;
    Swatch swatch;
    int swatch_px;
  };
  int width_;
  std::vector<Entry> entries_;
};

cv::Mat StackRows(const std::vector<cv::Mat>& rows, int gap_px) {
  int width = 0, height = 0;
  for (const cv::Mat& r : rows) width = std::max(width, r.cols), height += r.rows + gap_px;
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  int y = 0;
  for (const cv::Mat& r : rows) {
    r.copyTo(image(cv::Rect(0, y, r.cols, r.rows)));
    y += r.rows + gap_px;
  }
  return image;
}

}  // namespace

cv::Mat DrawMapFigure(const OccupancyGrid& grid, const MapFigure& figure, const FoldOptions& options) {
  const FoldedLayout layout = FoldExtent(KnownExtent(grid), options);
  double max_error_m = 0.0;
  for (const PlateErrorRow& row : figure.plates) max_error_m = std::max(max_error_m, row.error_m);
  const double magnification = ArrowMagnification(max_error_m, figure.arrow_target_px / layout.px_per_m);
  const cv::Mat cells = CellImage(grid);
  std::vector<cv::Mat> rows;
  for (const MapWindow& window : layout.windows) {
    const PanelProjection to_px{window, layout.px_per_m};
    cv::Mat panel = RenderWindow(grid, cells, to_px);
    for (const FigurePath& path : figure.paths) {
      std::vector<cv::Point> points;
      for (const Vec2& p : path.points) points.push_back(to_px(p));
      cv::polylines(panel, points, false, path.color, path.thickness_px, cv::LINE_AA);
    }
    DrawPlates(panel, to_px, figure.plates, magnification);
    for (const FigurePose& p : figure.poses) {
      cv::arrowedLine(panel, to_px(p.pose.Position()), to_px(p.pose.TransformPoint({0.8, 0.0})), p.color, 3,
                      cv::LINE_AA, 0, 0.35);
    }
    DrawPanelAxes(panel, to_px);
    rows.push_back(panel);
  }
  const int width = rows.front().cols;
  Legend legend(width);
  for (const FigurePath& path : figure.paths) {
    legend.Add(path.label, [path](cv::Mat& m, cv::Point c) {
      cv::line(m, c, c + cv::Point(30, 0), path.color, std::max(2, path.thickness_px), cv::LINE_AA);
    });
  }
  for (const FigurePose& pose : figure.poses) {
    legend.Add(pose.label, [pose](cv::Mat& m, cv::Point c) {
      cv::arrowedLine(m, c, c + cv::Point(30, 0), pose.color, 3, cv::LINE_AA, 0, 0.35);
    });
  }
  legend.Add("true plate", [](cv::Mat& m, cv::Point c) {
    cv::drawMarker(m, c + cv::Point(15, 0), kTrue, cv::MARKER_CROSS, 16, 2, cv::LINE_AA);
  });
  legend.Add("mapped plate (its text)", [](cv::Mat& m, cv::Point c) {
    cv::circle(m, c + cv::Point(15, 0), 6, kMapped, 2, cv::LINE_AA);
  });
  const double px_per_m = layout.px_per_m;
  const int error_px = std::max(4, static_cast<int>(std::lround(0.05 * magnification * px_per_m)));
  legend.Add(Format("plate error, true -> mapped, drawn x%g (this arrow: 5 cm)", magnification),
             [error_px](cv::Mat& m, cv::Point c) {
               cv::arrowedLine(m, c, c + cv::Point(error_px, 0), kArrow, 2, cv::LINE_AA, 0,
                               std::min(0.5, 12.0 / error_px));
             },
             error_px);
  double bar_m = 1.0;  // a scale bar at least 60 px long
  for (const double m : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0}) {
    bar_m = m;
    if (m * px_per_m >= 60.0) break;
  }
  const int bar_px = static_cast<int>(std::lround(bar_m * px_per_m));
  legend.Add(Format("%g m", bar_m), [bar_px](cv::Mat& m, cv::Point c) {
    cv::rectangle(m, c - cv::Point(0, 3), c + cv::Point(bar_px, 3), kInk, cv::FILLED);
  }, bar_px);
  rows.push_back(legend.Draw());
  std::string title = figure.title;
  if (layout.windows.size() > 1) {
    title += " (the map in " + std::to_string(layout.windows.size()) + " segments, left to right, top to bottom)";
  }
  return WithTitle(StackRows(rows, 10), title);
}

cv::Mat DrawPlateErrorChart(const std::vector<PlateErrorRow>& rows, const std::string& title) {
  if (rows.empty()) throw std::invalid_argument("DrawPlateErrorChart: no plates");
  double max_cm = 5.0, sum2 = 0.0;
  int mapped = 0;
  int slot = 48;
  for (const PlateErrorRow& r : rows) {
    if (r.mapped) max_cm = std::max(max_cm, 100.0 * r.error_m), sum2 += r.error_m * r.error_m, ++mapped;
    slot = std::max(slot, TextWidth(r.text) + 10);
  }
  const std::string footer =
      "bar: distance of the plate's mapped position from the truth (cm); none: not in the map" +
      (mapped > 0 ? Format("; dashed: RMS %.1f cm", 100.0 * std::sqrt(sum2 / mapped)) : std::string());
  const int left = 70, top = 20, plot_h = 300, bottom = 60;
  const int width = std::max({700, left + slot * static_cast<int>(rows.size()) + 20, left + TextWidth(footer, 0.45) + 20});
  cv::Mat image(top + plot_h + bottom, width, CV_8UC3, cv::Scalar(255, 255, 255));
  std::vector<double> ticks = NiceTicks(0.0, max_cm * 1.1, 6);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : max_cm;
  while (ticks.back() < max_cm * 1.05) ticks.push_back(ticks.back() + step);  // the top tick above every bar
  const double y_max = ticks.back();
  const auto to_py = [&](double cm) { return top + plot_h - static_cast<int>(std::lround(plot_h * cm / y_max)); };
  for (const double t : ticks) {
    cv::line(image, {left, to_py(t)}, {width - 10, to_py(t)}, kGridLine, 1);
    Text(image, Format("%g cm", t), {left - 8 - TextWidth(Format("%g cm", t), 0.45), to_py(t) + 5}, kInk, 0.45);
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PlateErrorRow& r = rows[i];
    const int x = left + static_cast<int>(i) * slot;
    if (r.mapped) {
      const double cm = 100.0 * r.error_m;
      const cv::Scalar color = cm <= 10.0 ? cv::Scalar(80, 170, 40) : cm <= 30.0 ? cv::Scalar(0, 160, 240) : kMapped;
      cv::rectangle(image, {x + 6, to_py(cm)}, {x + slot - 6, to_py(0.0)}, color, cv::FILLED);
      const std::string value = Format("%.1f", cm);
      Text(image, value, {x + (slot - TextWidth(value, 0.4)) / 2, to_py(cm) - 5}, kInk, 0.4);
    } else {
      Text(image, "none", {x + slot / 2 - 16, to_py(0.0) - 6}, kMapped, 0.45);
    }
    Text(image, r.text, {x + (slot - TextWidth(r.text)) / 2, top + plot_h + 22}, kInk);
  }
  cv::line(image, {left, to_py(0.0)}, {width - 10, to_py(0.0)}, kInk, 1);
  if (mapped > 0) {
    const double rms_cm = 100.0 * std::sqrt(sum2 / mapped);
    const int y = to_py(rms_cm);
    for (int x = left; x < width - 10; x += 12) cv::line(image, {x, y}, {std::min(x + 6, width - 10), y}, kInk, 1);
  }
  Text(image, footer, {left, top + plot_h + 48}, kInk, 0.45);
  return WithTitle(image, title);
}

cv::Mat DrawSpreadPlot(const std::vector<SpreadSample>& samples, const std::vector<SpreadEvent>& plates,
                       double converged_time_s, const std::string& title) {
  if (samples.empty()) throw std::invalid_argument("DrawSpreadPlot: no samples");
  constexpr double kFloorM = 0.01;  // the log axis starts at 1 cm
  double max_spread = kFloorM, max_driven = 1.0;
  for (const SpreadSample& s : samples) max_spread = std::max(max_spread, s.spread_m), max_driven = std::max(max_driven, s.driven_m);
  const int left = 80, right = 20, top = 40, plot_w = 900, plot_h = 320, bottom = 50;
  cv::Mat image(top + plot_h + bottom, left + plot_w + right, CV_8UC3, cv::Scalar(255, 255, 255));
  const double lo = std::log10(kFloorM), hi = std::ceil(std::log10(max_spread) + 1e-9);
  const auto to_px = [&](double driven_m, double spread_m) {
    const double v = (std::log10(std::max(spread_m, kFloorM)) - lo) / (hi - lo);
    return cv::Point(left + static_cast<int>(std::lround(plot_w * driven_m / max_driven)),
                     top + plot_h - static_cast<int>(std::lround(plot_h * v)));
  };
  for (double e = lo; e <= hi + 1e-9; e += 1.0) {
    const double value = std::pow(10.0, e);
    const int y = to_px(0.0, value).y;
    cv::line(image, {left, y}, {left + plot_w, y}, kGridLine, 1);
    const std::string label = value < 1.0 ? Format("%g cm", 100.0 * value) : Format("%g m", value);
    Text(image, label, {left - 8 - TextWidth(label, 0.45), y + 5}, kInk, 0.45);
  }
  for (const double x : NiceTicks(0.0, max_driven, 10)) {
    const int px = to_px(x, kFloorM).x;
    cv::line(image, {px, top + plot_h}, {px, top + plot_h + 6}, kInk, 1);
    Text(image, Format("%g", x), {px - 8, top + plot_h + 22}, kInk, 0.45);
  }
  Text(image, "distance driven since the start (m)", {left + plot_w / 2 - 150, top + plot_h + 44}, kInk);
  Text(image, "particle spread (RMS distance from their mean), log scale", {left, top - 12}, kInk);
  for (std::size_t i = 0; i < plates.size(); ++i) {
    const int x = to_px(DrivenAt(samples, plates[i].sim_time_s), kFloorM).x;
    cv::line(image, {x, top + plot_h}, {x, top + plot_h - 14}, kMapped, 2);
    Text(image, plates[i].label, {x - 12, top + plot_h - 20 - 16 * static_cast<int>(i % 3)}, kMapped, 0.45);
  }
  if (converged_time_s >= 0.0) {
    const int x = to_px(DrivenAt(samples, converged_time_s), kFloorM).x;
    for (int y = top; y < top + plot_h; y += 10) cv::line(image, {x, y}, {x, y + 5}, kTrue, 2);
    const int label_w = TextWidth("converged", 0.55, 2);
    Text(image, "converged", {x + 6 + label_w > left + plot_w ? x - 6 - label_w : x + 6, top + 16}, kTrue, 0.55, 2);
  }
  std::vector<cv::Point> line;
  for (const SpreadSample& s : samples) line.push_back(to_px(s.driven_m, s.spread_m));
  cv::polylines(image, line, false, cv::Scalar(160, 60, 0), 2, cv::LINE_AA);
  cv::rectangle(image, {left, top}, {left + plot_w, top + plot_h}, kInk, 1);
  return WithTitle(image, title);
}

}  // namespace doorplate_localization
