// Sideways camera renderer. The scene is made of vertical rectangles (World::surfaces), so a camera with a
// horizontal optical axis sees every image column as one vertical plane: each column casts one 2D ray,
// sorts the surfaces it crosses by depth and fills its rows near to far (Wolfenstein-style ray casting,
// exact for this scene). The camera's pitch is a pure rotation, i.e. the homography K·R·K⁻¹, applied by
// one remap from a taller unpitched image. Signs are sampled from mip-mapped textures drawn once with
// OpenCV's anti-aliased Hershey fonts, so digits stay crisp at any distance.
// Sign textures live in sign_texture.cpp; blur, gain and pixel noise in image_noise.cpp.
#include "doorplate_localization/sim/camera_renderer.h"

#include "image_noise.h"
#include "sign_texture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxHitsPlain = 12;       // nearest surfaces kept per column (enough for rooms behind doors)
constexpr int kMaxHitsDetailed = 24;    // ... in worlds with clutter, door frames, glass or people
constexpr int kMaxGlassPerColumn = 4;   // glass panes blended per column (nearest first)
constexpr double kNearDepthM = 0.02;    // surfaces closer than this along the optical axis are clipped
constexpr double kDoorFrameM = 0.05;
constexpr int kNoiseTableSize = 4096;   // indexed by 12 bits of a 16-bit random number

// The camera's horizontal frame in the world: position, optical axis on the floor, image x axis.
struct CameraFrame {
  Vec2 position;
  Vec2 forward;
  Vec2 right;
};

CameraFrame FrameAt(const CameraOptions& options, const Pose2D& robot_pose) {
  const double yaw = robot_pose.theta_rad + (options.side == "right" ? -kPi / 2 : kPi / 2);
  CameraFrame frame;
  frame.position = robot_pose.TransformPoint({options.mount_x_m, options.mount_y_m});
  frame.forward = {std::cos(yaw), std::sin(yaw)};
  frame.right = {frame.forward.y, -frame.forward.x};
  return frame;
}

// Brightness falls off slowly with distance (ceiling lights are spread along the corridor).
double DistanceShade(double distance_m) { return std::max(0.55, 1.0 / (1.0 + 0.03 * distance_m)); }

cv::Vec3b Bgr(const ColorRgb& c, double gain) {
  return {cv::saturate_cast<uchar>(c[2] * gain), cv::saturate_cast<uchar>(c[1] * gain),
          cv::saturate_cast<uchar>(c[0] * gain)};
}

}  // namespace

// One surface crossed by a column's ray.
struct CameraRenderer::Hit {
  double depth_m = 0.0;      // along the optical axis
  double s = 0.0;            // position on the surface segment: 0 at a, 1 at b
  double wall_step_m = 0.0;  // how far the hit moves along the surface from one column to the next
  double shade = 1.0;        // brightness factor from distance and incidence
  int surface = -1;
};

CameraIntrinsics IntrinsicsFromOptions(const CameraOptions& options) {
  CameraIntrinsics k;
  k.width_px = options.width_px;
  k.height_px = options.height_px;
  k.fx_px = options.fx_px > 0.0 ? options.fx_px
                                : 0.5 * options.width_px / std::tan(0.5 * options.horizontal_fov_deg * kPi / 180.0);
  k.fy_px = options.fy_px > 0.0 ? options.fy_px : k.fx_px;
  k.cx_px = options.cx_px > 0.0 ? options.cx_px : 0.5 * (options.width_px - 1);
  k.cy_px = options.cy_px > 0.0 ? options.cy_px : 0.5 * (options.height_px - 1);
  return k;
}

CameraRenderer::CameraRenderer(const World& world, const CameraOptions& options)
    : world_(world), options_(options), intrinsics_(IntrinsicsFromOptions(options)) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("CameraRenderer: " + what); };
  const int min_side = std::min(options.width_px, options.height_px);
  if (min_side < 16 || std::max(options.width_px, options.height_px) > 8192) {
    fail("camera width_px and height_px must be in [16, 8192]");
  }
  if (!(options.horizontal_fov_deg > 1.0 && options.horizontal_fov_deg < 170.0)) {
    fail("camera horizontal_fov_deg must be in (1, 170)");
  }
  if (!(options.fx_px >= 0.0) || !(options.fy_px >= 0.0) || !(options.cx_px >= 0.0) || !(options.cy_px >= 0.0) ||
      options.cx_px > options.width_px || options.cy_px > options.height_px) {
    fail("camera fx_px, fy_px must be >= 0 (0: derived), cx_px, cy_px in [0, width_px], [0, height_px]");
  }
  if (options.side != "left" && options.side != "right") {
    fail("camera side must be 'left' or 'right', got '" + options.side + "'");
  }
  if (!(options.lens_blur_sigma_px >= 0.0) || !(options.exposure_s >= 0.0) ||
      !(options.pixel_noise_stddev >= 0.0) || !(options.lighting_gain_stddev >= 0.0)) {
    fail("camera lens_blur_sigma_px, exposure_s, pixel_noise_stddev, lighting_gain_stddev must be >= 0");
  }
  pitch_rad_ = options.pitch_deg * kPi / 180.0;

  // Output pixel → unpitched pixel: X_unpitched = Rᵀ·K⁻¹·(u, v, 1) with R the pitch rotation.
  const CameraIntrinsics& k = intrinsics_;
  const double cp = std::cos(pitch_rad_), sp = std::sin(pitch_rad_);
  cv::Mat xs(k.height_px, k.width_px, CV_32F), ys(k.height_px, k.width_px, CV_32F);
  for (int v = 0; v < k.height_px; ++v) {
    const double y_p = (v - k.cy_px) / k.fy_px;
    const double y_u = cp * y_p - sp, z_u = sp * y_p + cp;
    if (z_u < 0.05) fail("camera pitch_deg " + std::to_string(options.pitch_deg) + " is too steep");
    for (int u = 0; u < k.width_px; ++u) {
      xs.at<float>(v, u) = static_cast<float>((u - k.cx_px) / z_u);
      ys.at<float>(v, u) = static_cast<float>(k.fy_px * y_u / z_u);
    }
  }
  double x_min, x_max, y_min, y_max;
  cv::minMaxLoc(xs, &x_min, &x_max);
  cv::minMaxLoc(ys, &y_min, &y_max);
  const int col0 = static_cast<int>(std::floor(x_min)) - 2, row0 = static_cast<int>(std::floor(y_min)) - 2;
  unpitched_cols_ = static_cast<int>(std::ceil(x_max)) + 3 - col0;
  unpitched_rows_ = static_cast<int>(std::ceil(y_max)) + 3 - row0;
  unpitched_cx_px_ = -col0;
  unpitched_cy_px_ = -row0;
  // The unpitched image is stored transposed (a column per row), so remap's x is the unpitched row.
  cv::convertMaps(ys - row0, xs - col0, pitch_map1_, pitch_map2_, CV_16SC2);

  background_column_.create(1, unpitched_rows_, CV_8UC3);
  const double h = options.mount_height_m, above = std::max(world.wall_height_m - h, 0.05);
  for (int r = 0; r < unpitched_rows_; ++r) {
    const double dy = r - unpitched_cy_px_;
    const bool floor = dy > -0.5;
    const double distance = floor ? h * k.fy_px / std::max(dy, 0.5) : above * k.fy_px / -dy;
    background_column_.at<cv::Vec3b>(0, r) =
        Bgr(floor ? world.floor_color : world.ceiling_color, DistanceShade(distance));
  }

  wall_doors_.assign(world.walls.size(), {});
  wall_signs_.assign(world.walls.size(), {});
  const int num_walls = static_cast<int>(world.walls.size());
  for (std::size_t i = 0; i < world.doors.size(); ++i) {
    const int w = world.doors[i].wall_index;
    if (w < 0 || w >= num_walls) fail("world doors[" + std::to_string(i) + "].wall_index out of range");
    if (!world.doors[i].open) wall_doors_[w].push_back(static_cast<int>(i));
  }
  for (std::size_t i = 0; i < world.signs.size(); ++i) {
    const int w = world.signs[i].wall_index;
    if (w < 0 || w >= num_walls) fail("world signs[" + std::to_string(i) + "].wall_index out of range");
    wall_signs_[w].push_back(static_cast<int>(i));
    sign_textures_.push_back({MakeSignPyramid(world.signs[i], i)});
  }
  for (std::size_t i = 0; i < world.surfaces.size(); ++i) {
    if (world.surfaces[i].wall_index >= num_walls) {
      fail("world surfaces[" + std::to_string(i) + "].wall_index out of range");
    }
  }
  if (options.pixel_noise_stddev > 0.0) {
    noise_table_ = GaussianQuantiles(kNoiseTableSize, options.pixel_noise_stddev);
  }
  const bool detailed = !world.people.empty() || std::any_of(world.surfaces.begin(), world.surfaces.end(),
                                                             [](const Surface& s) { return s.kind != SurfaceKind::kStructure; });
  max_hits_ = detailed ? kMaxHitsDetailed : kMaxHitsPlain;
}

double CameraRenderer::RenderUnpitchedTransposed(const Pose2D& robot_pose, cv::Mat* transposed) const {
  const CameraFrame cam = FrameAt(options_, robot_pose);
  const int cols = unpitched_cols_, rows = unpitched_rows_;
  const double fx = intrinsics_.fx_px, cx = unpitched_cx_px_;
  transposed->create(cols, rows, CV_8UC3);

  // Collect, per column, the nearest surfaces its ray crosses (sorted by depth).
  const int max_hits = max_hits_;
  std::vector<Hit> hits(static_cast<std::size_t>(cols) * max_hits);
  std::vector<int> hit_count(cols, 0);
  for (std::size_t si = 0; si < world_.surfaces.size(); ++si) {
    const Surface& surface = world_.surfaces[si];
    const Vec2 a = surface.segment.a - cam.position, b = surface.segment.b - cam.position;
    const double xa = Dot(a, cam.right), za = Dot(a, cam.forward);
    const double xb = Dot(b, cam.right), zb = Dot(b, cam.forward);
    if (za < kNearDepthM && zb < kNearDepthM) continue;
    const double dx = xb - xa, dz = zb - za, length = std::hypot(dx, dz);
    if (length <= 0.0) continue;
    // Columns spanned by the part in front of the near plane.
    const auto clipped_column = [&](double x, double z, double x_other, double z_other) {
      if (z < kNearDepthM) {
        x += (kNearDepthM - z) / (z_other - z) * (x_other - x);
        z = kNearDepthM;
      }
      return std::clamp(cx + fx * x / z, -1.0, static_cast<double>(cols));
    };
    const double ua = clipped_column(xa, za, xb, zb), ub = clipped_column(xb, zb, xa, za);
    const int c0 = std::max(0, static_cast<int>(std::ceil(std::min(ua, ub))));
    const int c1 = std::min(cols - 1, static_cast<int>(std::floor(std::max(ua, ub))));
    for (int c = c0; c <= c1; ++c) {
      const double xn = (c - cx) / fx;  // the column's ray: (x, z) = depth · (xn, 1)
      const double denom = dx - xn * dz;
      if (std::fabs(denom) < 1e-12) continue;
      const double s = (xn * za - xa) / denom;
      const double depth = za + s * dz;
      if (s < -1e-9 || s > 1.0 + 1e-9 || depth < kNearDepthM) continue;
      const double xn1 = xn + 1.0 / fx, denom1 = dx - xn1 * dz;
      const double s1 = std::fabs(denom1) < 1e-12 ? s + 1.0 : (xn1 * za - xa) / denom1;
      const double ray_norm = std::sqrt(1.0 + xn * xn);
      const double cos_incidence = std::fabs(dx - dz * xn) / (length * ray_norm);
      const double lit = world_.lighting.empty() ? 1.0 : world_.LightingGain(
          surface.segment.a + std::clamp(s, 0.0, 1.0) * (surface.segment.b - surface.segment.a));
      const Hit hit{depth, std::clamp(s, 0.0, 1.0), std::min(std::fabs(s1 - s) * length, 1.0),
                    lit * DistanceShade(depth * ray_norm) * (0.8 + 0.2 * cos_incidence), static_cast<int>(si)};
      Hit* list = &hits[static_cast<std::size_t>(c) * max_hits];
      int& n = hit_count[c];
      if (n == max_hits && depth >= list[n - 1].depth_m) continue;
      int i = std::min(n, max_hits - 1);
      for (; i > 0 && list[i - 1].depth_m > depth; --i) list[i] = list[i - 1];
      list[i] = hit;
      n = std::min(n + 1, max_hits);
    }
  }

  // Fill each column near to far: a surface paints only the rows no nearer surface covered.
  const double fy = intrinsics_.fy_px, cy = unpitched_cy_px_, h = options_.mount_height_m;
  const int center_col = static_cast<int>(std::lround(cx));
  double center_depth_m = std::numeric_limits<double>::infinity();
  for (int c = 0; c < cols; ++c) {
    cv::Vec3b* column = transposed->ptr<cv::Vec3b>(c);
    std::memcpy(transposed->ptr(c), background_column_.ptr(), static_cast<std::size_t>(rows) * 3);
    using Spans = std::array<std::pair<int, int>, kMaxHitsDetailed + 2>;
    Spans open, next;
    int n_open = 1;
    open[0] = {0, rows};
    // Glass does not cover what lies behind it: it is blended over the rows it had open, afterwards.
    struct GlassRows {
      int hit, r0, r1, n_open;
      Spans open;
    };
    std::array<GlassRows, kMaxGlassPerColumn> glass;
    int n_glass = 0;
    const Hit* list = &hits[static_cast<std::size_t>(c) * max_hits];
    if (c == center_col && hit_count[c] > 0) center_depth_m = list[0].depth_m;
    for (int k = 0; k < hit_count[c] && n_open > 0; ++k) {
      const Surface& surface = world_.surfaces[list[k].surface];
      const double scale = fy / list[k].depth_m;
      const auto row_of = [&](double z) {
        return static_cast<int>(std::clamp(std::ceil(cy + (h - z) * scale), 0.0, 1.0 * rows));
      };
      const int r0 = row_of(surface.z_max_m), r1 = row_of(surface.z_min_m);
      if (r0 >= r1) continue;
      if (surface.kind == SurfaceKind::kGlass) {
        if (n_glass < kMaxGlassPerColumn) glass[n_glass++] = {k, r0, r1, n_open, open};
        continue;
      }
      int n_next = 0;
      for (int i = 0; i < n_open; ++i) {
        const auto [a, b] = open[i];
        const int pa = std::max(a, r0), pb = std::min(b, r1);
        if (pa >= pb) {
          next[n_next++] = open[i];
          continue;
        }
        PaintHit(list[k], scale, cam.position, pa, pb, column);
        if (a < pa) next[n_next++] = {a, pa};
        if (pb < b) next[n_next++] = {pb, b};
      }
      open = next;
      n_open = n_next;
    }
    for (int g = n_glass - 1; g >= 0; --g) {  // far to near
      const Surface& pane = world_.surfaces[list[glass[g].hit].surface];
      const cv::Vec3b tint = Bgr(pane.color, list[glass[g].hit].shade);
      const double a = pane.camera_opacity;
      for (int i = 0; i < glass[g].n_open; ++i) {
        const int pa = std::max(glass[g].open[i].first, glass[g].r0), pb = std::min(glass[g].open[i].second, glass[g].r1);
        for (int r = pa; r < pb; ++r) {
          for (int ch = 0; ch < 3; ++ch) column[r][ch] = cv::saturate_cast<uchar>((1.0 - a) * column[r][ch] + a * tint[ch]);
        }
      }
    }
  }
  return center_depth_m;
}

void CameraRenderer::PaintHit(const Hit& hit, double depth_scale, const Vec2& camera_xy, int row_begin,
                              int row_end, cv::Vec3b* column) const {
  const Surface& surface = world_.surfaces[hit.surface];
  std::fill(column + row_begin, column + row_end, Bgr(surface.color, hit.shade));
  if (surface.wall_index < 0) return;

  const double cy = unpitched_cy_px_, h = options_.mount_height_m;
  const auto row_of = [&](double z) { return cy + (h - z) * depth_scale; };  // row seeing height z
  int first = 0, last = 0;  // rows whose centres see heights in [z0, z1], within the span
  const auto rows_for = [&](double z0, double z1) {
    first = static_cast<int>(std::clamp(std::ceil(row_of(z1)), 1.0 * row_begin, 1.0 * row_end));
    last = static_cast<int>(std::clamp(std::ceil(row_of(z0)), 1.0 * row_begin, 1.0 * row_end));
    return first < last;
  };
  const Wall& wall = world_.walls[surface.wall_index];
  const Vec2 along_wall = wall.segment.b - wall.segment.a;
  if (!(Norm(along_wall) > 0.0)) return;
  const Vec2 point = surface.segment.a + hit.s * (surface.segment.b - surface.segment.a);
  const double offset = Dot(point - wall.segment.a, along_wall) / Norm(along_wall);

  for (int d : wall_doors_[surface.wall_index]) {  // closed doors: a panel with a darker frame
    const Door& door = world_.doors[d];
    const double across = std::fabs(offset - door.offset_m);
    if (across > door.width_m / 2) continue;
    const cv::Vec3b panel = Bgr(door.color, hit.shade), frame = Bgr(door.color, 0.55 * hit.shade);
    const bool side_frame = across > door.width_m / 2 - kDoorFrameM;
    if (rows_for(0.0, door.height_m)) std::fill(column + first, column + last, side_frame ? frame : panel);
    if (!side_frame && rows_for(door.height_m - kDoorFrameM, door.height_m)) {
      std::fill(column + first, column + last, frame);
    }
  }
  const bool camera_on_left = Cross(along_wall, camera_xy - wall.segment.a) > 0.0;
  for (int si : wall_signs_[surface.wall_index]) {  // signs only face their corridor side
    const TextSign& sign = world_.signs[si];
    const double along = offset - sign.offset_m, half_width = sign.width_m / 2, step = hit.wall_step_m;
    if (sign.corridor_side_left != camera_on_left || std::fabs(along) > half_width + step / 2) continue;
    const double coverage_u =
        std::clamp((std::min(along + step / 2, half_width) - std::max(along - step / 2, -half_width)) /
                       std::max(step, 1e-9), 0.0, 1.0);
    const double top = sign.center_height_m + sign.height_m / 2;
    const double top_row = row_of(top), bottom_row = row_of(top - sign.height_m);
    const int first_row = std::max(row_begin, static_cast<int>(std::ceil(top_row - 0.5)));
    const int last_row = std::min(row_end, static_cast<int>(std::floor(bottom_row + 0.5)) + 1);
    if (first_row >= last_row) continue;
    // Seen from a wall's left side, wall offsets grow to the viewer's left.
    const double u_m = sign.corridor_side_left ? half_width - along : half_width + along;
    SampleSignColumn(sign_textures_[si].levels, sign, u_m, step, coverage_u, top_row, depth_scale,
                     hit.shade, first_row, last_row, column);
  }
}

cv::Mat CameraRenderer::RenderClean(const Pose2D& robot_pose) const {
  cv::Mat transposed, image;
  RenderUnpitchedTransposed(robot_pose, &transposed);
  cv::remap(transposed, image, pitch_map1_, pitch_map2_, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return image;
}

cv::Mat CameraRenderer::Render(const Pose2D& robot_pose, double speed_mps, double yaw_rate_rps,
                               std::mt19937_64& rng) const {
  cv::Mat transposed, image;
  const double center_depth_m = RenderUnpitchedTransposed(robot_pose, &transposed);
  cv::remap(transposed, image, pitch_map1_, pitch_map2_, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  Degrade(center_depth_m, speed_mps, yaw_rate_rps, rng, &image);
  return image;
}

void CameraRenderer::Degrade(double center_depth_m, double speed_mps, double yaw_rate_rps,
                             std::mt19937_64& rng, cv::Mat* image) const {
  // Image-plane speed at the centre: translation sweeps the scene against the camera's x axis (the
  // left camera's x axis is the robot's forward direction), turning left sweeps it to the right.
  const double fx = intrinsics_.fx_px, side = options_.side == "left" ? -1.0 : 1.0;
  const double translation_px_s =
      std::isfinite(center_depth_m) ? side * speed_mps * fx / center_depth_m : 0.0;
  const double motion_px = std::fabs(translation_px_s + yaw_rate_rps * fx) * options_.exposure_s;
  const cv::Mat kernel_x = BlurKernel(options_.lens_blur_sigma_px, motion_px);
  const cv::Mat kernel_y = BlurKernel(options_.lens_blur_sigma_px, 0.0);
  if (kernel_x.cols > 1 || kernel_y.cols > 1) {
    cv::sepFilter2D(*image, *image, -1, kernel_x, kernel_y, cv::Point(-1, -1), 0.0, cv::BORDER_REFLECT_101);
  }

  double gain = 1.0;
  if (options_.lighting_gain_stddev > 0.0) {
    gain = std::max(0.2, std::normal_distribution<double>(1.0, options_.lighting_gain_stddev)(rng));
  }
  ApplyGainAndNoise(gain, options_.lighting_gradient, noise_table_, rng(), image);  // one draw from `rng`
}

bool CameraRenderer::Project(const Pose2D& robot_pose, const Point3& world_point, cv::Point2d* pixel) const {
  const CameraFrame cam = FrameAt(options_, robot_pose);
  const Vec2 d = Vec2{world_point.x, world_point.y} - cam.position;
  const double forward = Dot(d, cam.forward), right = Dot(d, cam.right);
  const double up = world_point.z - options_.mount_height_m;
  const double cp = std::cos(pitch_rad_), sp = std::sin(pitch_rad_);
  const double z = cp * forward + sp * up, y = sp * forward - cp * up;  // pitched optical frame
  if (z <= 1e-9) return false;
  if (pixel != nullptr) {
    pixel->x = intrinsics_.cx_px + intrinsics_.fx_px * right / z;
    pixel->y = intrinsics_.cy_px + intrinsics_.fy_px * y / z;
  }
  return true;
}

void CameraRenderer::MountPose(double* x, double* y, double* z, double* yaw_rad, double* pitch_rad) const {
  *x = options_.mount_x_m;
  *y = options_.mount_y_m;
  *z = options_.mount_height_m;
  *yaw_rad = options_.side == "right" ? -kPi / 2 : kPi / 2;
  *pitch_rad = -pitch_rad_;
}

}  // namespace doorplate_localization
