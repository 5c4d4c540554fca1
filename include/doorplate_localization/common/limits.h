// The named bounds on what the package accepts from files and messages (issue 18): finite but absurd input
// (a 20000 x 20000 map, 1e9 particles, a 1 MB plate text, a map origin at 1e300 m) is refused, before
// anything is allocated for it, with an error naming the file or field and the limit. Every loader and
// message check uses these constants; docs/reliability.md lists them with the reason for each value.
// Header-only, ROS-free.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace doorplate_localization {
namespace limits {

// Cells of one occupancy grid (width * height). The localizer keeps ~10 bytes per cell (the grid, its
// free/occupied reading, the free-cell index, the likelihood field's distances, the ROS message): 1e8
// cells is ~1 GB. 1e8 cells are 1 km x 1 km at 10 cm, 500 m x 500 m at 5 cm; the largest shipped map
// has 0.37 M. A 20000 x 20000 map (4e8 cells) is refused.
inline constexpr std::int64_t kMaxMapCells = 100'000'000;
// Cell side of a map (m). Below 1 mm no 2D laser resolves anything; above 100 m a cell is no map.
inline constexpr double kMinMapResolutionM = 0.001;
inline constexpr double kMaxMapResolutionM = 100.0;
// |x| and |y| of a map origin or an initial pose (m). A building map's frame (REP-105 `map`) is local:
// 1000 km covers any site, keeps doubles at < 1e-9 m resolution and cell indexes far from int overflow.
inline constexpr double kMaxCoordinateM = 1e6;
// Particles of one filter (max_particles, min_particles). A particle costs ~120 bytes over a run (the
// set, its resampled copy, the likelihood scratch, the particlecloud message): 1e6 is ~120 MB and ~0.5 s
// per laser update of 60 beams on one core; amcl's default is 5000.
inline constexpr int kMaxParticles = 1'000'000;
// Ranges of one LaserScan. The densest 2D lidars give ~10 000 per turn (0.036 deg); every scan is
// copied into the filter's history (the last two kept per floor).
inline constexpr std::size_t kMaxScanBeams = 100'000;
// Bytes of a plate text (a detection's `text`). A room number is a few characters; the longest in the
// room_id grammar is 10. Longer texts are refused before matching (edit distances cost
// length x plates) and before they are remembered or logged.
inline constexpr std::size_t kMaxPlateTextBytes = 64;
// Distinct unknown room numbers a localizer session remembers (to warn once per room). OCR garbage read
// over days must not grow the set without bound; past it, unknown rooms are still counted.
inline constexpr std::size_t kMaxRememberedUnknownRooms = 1000;
// Bytes of any user-supplied text quoted in a log line or error message; the rest is elided.
inline constexpr std::size_t kMaxLoggedTextBytes = 64;

// `text` for a log line: as it is when short, else its first kMaxLoggedTextBytes bytes and
// "... (N bytes)". Never cuts inside a UTF-8 sequence.
inline std::string TruncateForLog(const std::string& text, std::size_t max_bytes = kMaxLoggedTextBytes) {
  if (text.size() <= max_bytes) return text;
  std::size_t cut = max_bytes;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // continuation byte
  return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " bytes)";
}

// "" if a grid of width x height cells is within kMaxMapCells (and both are > 0), else the problem, e.g.
// "20000 x 20000 = 400000000 cells, more than the limit of 100000000 (limits::kMaxMapCells)". Takes 64-bit
// sizes so that a header's numbers are checked before any product can overflow.
inline std::string CheckMapCells(std::int64_t width, std::int64_t height) {
  std::ostringstream out;
  if (width <= 0 || height <= 0) {
    out << width << " x " << height << " cells: both must be > 0";
  } else if (width > kMaxMapCells || height > kMaxMapCells / width) {
    out << width << " x " << height << " = " << static_cast<double>(width) * static_cast<double>(height)
        << " cells, more than the limit of " << kMaxMapCells << " (limits::kMaxMapCells)";
  }
  return out.str();
}

// "" if `resolution_m` is finite and within [kMinMapResolutionM, kMaxMapResolutionM], else the problem.
inline std::string CheckMapResolution(double resolution_m) {
  if (std::isfinite(resolution_m) && resolution_m >= kMinMapResolutionM && resolution_m <= kMaxMapResolutionM) {
    return "";
  }
  std::ostringstream out;
  out << "must be finite and in [" << kMinMapResolutionM << ", " << kMaxMapResolutionM
      << "] m (limits::kMinMapResolutionM, kMaxMapResolutionM), got " << resolution_m;
  return out.str();
}

// "" if `value_m` is finite with |value_m| <= kMaxCoordinateM, else the problem.
inline std::string CheckCoordinate(double value_m) {
  if (std::isfinite(value_m) && std::fabs(value_m) <= kMaxCoordinateM) return "";
  std::ostringstream out;
  out << "must be finite and within +-" << kMaxCoordinateM << " m (limits::kMaxCoordinateM), got " << value_m;
  return out.str();
}

}  // namespace limits
}  // namespace doorplate_localization
