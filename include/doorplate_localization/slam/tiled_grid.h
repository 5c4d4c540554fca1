// Log-odds occupancy grid (the seed paper's eqs. 3-4) made of fixed-size tiles held by shared
// pointers, so that copying a grid (a particle inheriting its parent's map at resampling) copies
// pointers, and a tile is cloned only when a grid that shares it writes to it (copy-on-write).
// Unbounded: tiles appear where the grid is written. Besides log-odds, every cell keeps the squared
// distance to the nearest obstacle cell within a small radius, maintained incrementally, so a scan
// matcher reads a likelihood field in O(1). A cell becomes an obstacle when its log-odds rise above
// `occupied_log_odds` and stops being one when they fall below `cleared_log_odds` (hysteresis: cells at
// the edge of a wall do not flap). Log-odds are stored as 16-bit fixed point (3 bytes per cell).
// Frames and units: cell (i, j) covers [i·res, (i+1)·res) × [j·res, (j+1)·res) of the map frame, metres.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <climits>
#include <cstdint>
#include <memory>
#include <unordered_set>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"

namespace doorplate_localization {

struct TiledGridOptions {
  double resolution_m = 0.05;
  double hit_log_odds = 0.9;              // added to the cell where a beam ends on an obstacle
  double miss_log_odds = -0.4;            // added to every cell a beam passes through
  double min_log_odds = -2.0;             // clamps, so the map can change its mind
  double max_log_odds = 3.5;
  double occupied_log_odds = 0.5;         // a cell rising above this becomes an obstacle...
  double cleared_log_odds = -0.5;         // ...and stops being one when it falls below this
  double distance_field_radius_m = 0.25;  // distances are tracked up to this, at most 15 cells
};

struct CellIndex {
  int x = 0;
  int y = 0;
};

class TiledGrid {
 public:
  static constexpr int kTileBits = 5;
  static constexpr int kTileSize = 1 << kTileBits;  // cells per tile side
  static constexpr int kTileCells = kTileSize * kTileSize;
  static constexpr std::uint8_t kFar = 255;         // no obstacle cell within the radius
  static constexpr std::int16_t kUnknown = INT16_MIN; // log-odds of a cell never observed
  static constexpr double kLogOddsScale = 1000.0;     // stored value = log-odds × scale

  struct Tile {
    std::array<std::int16_t, kTileCells> log_odds;  // fixed point, kUnknown if never observed
    std::array<std::uint8_t, kTileCells> dist2;     // cells², 0 = an obstacle itself, kFar: none near
    Tile() {
      log_odds.fill(kUnknown);
      dist2.fill(kFar);
    }
  };

  explicit TiledGrid(const TiledGridOptions& options);

  const TiledGridOptions& options() const { return options_; }
  double resolution_m() const { return options_.resolution_m; }
  int field_radius_cells() const { return radius_cells_; }
  CellIndex CellOf(Vec2 p) const {
    return {static_cast<int>(std::floor(p.x * inv_resolution_)),
            static_cast<int>(std::floor(p.y * inv_resolution_))};
  }
  Vec2 CellCenter(CellIndex c) const {
    return {(c.x + 0.5) * options_.resolution_m, (c.y + 0.5) * options_.resolution_m};
  }

  // Read access; cells of absent tiles are unknown (log-odds 0, not observed, no obstacle near).
  const Tile* TileAt(int tile_x, int tile_y) const {
    const int i = tile_x - tile_x0_, j = tile_y - tile_y0_;
    if (i < 0 || j < 0 || i >= tiles_x_ || j >= tiles_y_) return nullptr;
    return tiles_[static_cast<std::size_t>(j) * tiles_x_ + i].get();
  }
  static int CellInTile(CellIndex c) {
    return ((c.y & (kTileSize - 1)) << kTileBits) | (c.x & (kTileSize - 1));
  }
  // Log-odds of a cell; 0 if it was never observed.
  double LogOdds(CellIndex c) const {
    const Tile* t = TileAt(c.x >> kTileBits, c.y >> kTileBits);
    const std::int16_t v = t ? t->log_odds[CellInTile(c)] : kUnknown;
    return v == kUnknown ? 0.0 : v / kLogOddsScale;
  }
  bool Observed(CellIndex c) const {
    const Tile* t = TileAt(c.x >> kTileBits, c.y >> kTileBits);
    return t && t->log_odds[CellInTile(c)] != kUnknown;
  }
  // True if the cell is an obstacle of the distance field.
  bool IsObstacle(CellIndex c) const { return Dist2Cells(c) == 0; }
  // Squared distance, in cells², from c's centre to the nearest obstacle cell centre, or kFar.
  std::uint8_t Dist2Cells(CellIndex c) const {
    const Tile* t = TileAt(c.x >> kTileBits, c.y >> kTileBits);
    return t ? t->dist2[CellInTile(c)] : kFar;
  }

  // Adds `delta` to a cell's log-odds (clamped) and keeps the distance field right.
  void UpdateCell(CellIndex c, double delta);
  // One beam from `from` to `to` (map frame): every cell on the way gets a miss, the last cell a hit
  // if `hit`, else a miss too (a beam without echo, or cut at the usable range).
  void IntegrateBeam(Vec2 from, Vec2 to, bool hit);
  // A beam without echo (+inf, REP-117: a dropout, glass, or nothing in range): misses from `from`
  // towards `to`, stopping before the first cell this grid already holds as an obstacle (or a diagonal
  // step past one: Bresenham lines cross a staircase wall between its cells). A missing echo says
  // nothing about what lies behind a wall the map knows, so it must not clear free space through it.
  void IntegrateNoReturnBeam(Vec2 from, Vec2 to);

  // Inclusive cell bounds of all observed tiles; false if the grid is empty.
  bool Bounds(CellIndex* min_cell, CellIndex* max_cell) const;
  std::size_t TileCount() const;
  // Adds this grid's tiles to `tiles` (for counting tiles shared between grids once).
  void CollectTiles(std::unordered_set<const Tile*>* tiles) const;
  // True if both grids hold the same tile object (not a copy) for cell c.
  bool SharesTileWith(const TiledGrid& other, CellIndex c) const;

  // The map as nav_msgs-style occupancy over the observed bounds: -1 unknown, 0 free (log-odds below
  // -`threshold`), 100 occupied (above `threshold`), else 50.
  OccupancyGrid ToOccupancyGrid(double threshold_log_odds = 0.5) const;

 private:
  Tile* MutableTile(int tile_x, int tile_y);
  std::uint8_t& MutableDist2(CellIndex c);
  void UpdateCellInTile(Tile* tile, CellIndex c, int delta);
  // Misses along the beam, `last_delta` on its last cell; with `stop_at_obstacle`, ends before the
  // first obstacle cell (which is left unchanged).
  void WalkBeam(Vec2 from, Vec2 to, int last_delta, bool stop_at_obstacle);
  void AddObstacle(CellIndex c);
  void RemoveObstacle(CellIndex c);
  void Grow(int tile_x, int tile_y);

  TiledGridOptions options_;
  double inv_resolution_;
  int radius_cells_;
  int hit_, miss_, min_, max_, occupied_, cleared_;  // fixed point
  int tile_x0_ = 0, tile_y0_ = 0, tiles_x_ = 0, tiles_y_ = 0;
  std::vector<std::shared_ptr<Tile>> tiles_;  // row-major directory, null = absent tile
};

}  // namespace doorplate_localization
