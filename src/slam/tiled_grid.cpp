#include "doorplate_localization/slam/tiled_grid.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace doorplate_localization {

TiledGrid::TiledGrid(const TiledGridOptions& options)
    : options_(options),
      inv_resolution_(1.0 / options.resolution_m),
      radius_cells_(static_cast<int>(std::lround(options.distance_field_radius_m / options.resolution_m))) {
  const auto fixed = [](double v) { return static_cast<int>(std::lround(v * kLogOddsScale)); };
  hit_ = fixed(options.hit_log_odds), miss_ = fixed(options.miss_log_odds);
  min_ = fixed(options.min_log_odds), max_ = fixed(options.max_log_odds);
  occupied_ = fixed(options.occupied_log_odds), cleared_ = fixed(options.cleared_log_odds);
  if (!(options.resolution_m > 0.0)) {
    throw std::invalid_argument("TiledGridOptions.resolution_m: must be > 0, got " +
                                std::to_string(options.resolution_m));
  }
  if (radius_cells_ < 1 || radius_cells_ > 15) {
    throw std::invalid_argument(
        "TiledGridOptions.distance_field_radius_m: must span 1..15 cells, got " +
        std::to_string(options.distance_field_radius_m) + " m");
  }
  if (!(options.min_log_odds <= options.cleared_log_odds &&
        options.cleared_log_odds < options.occupied_log_odds &&
        options.occupied_log_odds < options.max_log_odds && options.max_log_odds <= 30.0 &&
        options.min_log_odds >= -30.0)) {
    throw std::invalid_argument(
        "TiledGridOptions: need -30 <= min_log_odds <= cleared_log_odds < occupied_log_odds < "
        "max_log_odds <= 30");
  }
}

void TiledGrid::Grow(int tile_x, int tile_y) {
  constexpr int kMargin = 4;  // tiles added beyond the one needed, so growth is rare
  int x0 = tile_x0_, y0 = tile_y0_, x1 = tile_x0_ + tiles_x_, y1 = tile_y0_ + tiles_y_;
  if (tiles_.empty()) {
    x0 = tile_x - kMargin, y0 = tile_y - kMargin, x1 = tile_x + kMargin + 1, y1 = tile_y + kMargin + 1;
  } else {
    if (tile_x < x0) x0 = tile_x - kMargin;
    if (tile_y < y0) y0 = tile_y - kMargin;
    if (tile_x >= x1) x1 = tile_x + kMargin + 1;
    if (tile_y >= y1) y1 = tile_y + kMargin + 1;
  }
  std::vector<std::shared_ptr<Tile>> grown(static_cast<std::size_t>(x1 - x0) * (y1 - y0));
  for (int j = 0; j < tiles_y_; ++j) {
    for (int i = 0; i < tiles_x_; ++i) {
      grown[static_cast<std::size_t>(j + tile_y0_ - y0) * (x1 - x0) + (i + tile_x0_ - x0)] =
          std::move(tiles_[static_cast<std::size_t>(j) * tiles_x_ + i]);
    }
  }
  tiles_ = std::move(grown);
  tile_x0_ = x0, tile_y0_ = y0, tiles_x_ = x1 - x0, tiles_y_ = y1 - y0;
}

TiledGrid::Tile* TiledGrid::MutableTile(int tile_x, int tile_y) {
  if (tile_x < tile_x0_ || tile_y < tile_y0_ || tile_x >= tile_x0_ + tiles_x_ ||
      tile_y >= tile_y0_ + tiles_y_) {
    Grow(tile_x, tile_y);
  }
  std::shared_ptr<Tile>& slot =
      tiles_[static_cast<std::size_t>(tile_y - tile_y0_) * tiles_x_ + (tile_x - tile_x0_)];
  if (!slot) {
    slot = std::make_shared<Tile>();
  } else if (slot.use_count() > 1) {
    slot = std::make_shared<Tile>(*slot);  // copy-on-write: another grid still holds the original
  }
  return slot.get();
}

std::uint8_t& TiledGrid::MutableDist2(CellIndex c) {
  return MutableTile(c.x >> kTileBits, c.y >> kTileBits)->dist2[CellInTile(c)];
}

void TiledGrid::UpdateCell(CellIndex c, double delta) {
  UpdateCellInTile(MutableTile(c.x >> kTileBits, c.y >> kTileBits), c,
                   static_cast<int>(std::lround(delta * kLogOddsScale)));
}

void TiledGrid::UpdateCellInTile(Tile* tile, CellIndex c, int delta) {
  const int k = CellInTile(c);
  const int before = tile->log_odds[k] == kUnknown ? 0 : tile->log_odds[k];
  const int after = std::clamp(before + delta, min_, max_);
  tile->log_odds[k] = static_cast<std::int16_t>(after);
  const bool obstacle = tile->dist2[k] == 0;
  if (!obstacle && after > occupied_) AddObstacle(c);
  if (obstacle && after < cleared_) RemoveObstacle(c);
}

void TiledGrid::AddObstacle(CellIndex c) {
  const int r = radius_cells_;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int d2 = dx * dx + dy * dy;
      if (d2 > r * r) continue;
      std::uint8_t& cell = MutableDist2({c.x + dx, c.y + dy});
      if (d2 < cell) cell = static_cast<std::uint8_t>(d2);
    }
  }
}

void TiledGrid::RemoveObstacle(CellIndex c) {
  const int r = radius_cells_;
  MutableDist2(c) = kFar;  // no longer a source; recomputed below from the others
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int d2 = dx * dx + dy * dy;
      if (d2 > r * r) continue;
      const CellIndex q{c.x + dx, c.y + dy};
      if (d2 > 0 && Dist2Cells(q) != d2) continue;  // its nearest obstacle is another, nearer one
      int best = kFar;
      for (int ey = -r; ey <= r; ++ey) {
        for (int ex = -r; ex <= r; ++ex) {
          const int e2 = ex * ex + ey * ey;
          if (e2 < best && e2 <= r * r && IsObstacle({q.x + ex, q.y + ey})) best = e2;
        }
      }
      MutableDist2(q) = static_cast<std::uint8_t>(best);
    }
  }
}

void TiledGrid::IntegrateBeam(Vec2 from, Vec2 to, bool hit) { WalkBeam(from, to, hit ? hit_ : miss_, false); }

void TiledGrid::IntegrateNoReturnBeam(Vec2 from, Vec2 to) { WalkBeam(from, to, miss_, true); }

void TiledGrid::WalkBeam(Vec2 from, Vec2 to, int last_delta, bool stop_at_obstacle) {
  const CellIndex a = CellOf(from), b = CellOf(to);
  // Bresenham over cells from a to b; b itself is handled after the loop. The tile is looked up only
  // when the walk enters another one (a tile made writable stays the same object while we write).
  const int dx = std::abs(b.x - a.x), dy = -std::abs(b.y - a.y);
  const int sx = a.x < b.x ? 1 : -1, sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  CellIndex c = a;
  int tile_x = INT_MIN, tile_y = INT_MIN;
  Tile* tile = nullptr;
  while (true) {
    if ((c.x >> kTileBits) != tile_x || (c.y >> kTileBits) != tile_y) {
      tile_x = c.x >> kTileBits, tile_y = c.y >> kTileBits;
      tile = MutableTile(tile_x, tile_y);
    }
    if (stop_at_obstacle && tile->dist2[CellInTile(c)] == 0) return;
    if (c.x == b.x && c.y == b.y) break;
    UpdateCellInTile(tile, c, miss_);
    const int e2 = 2 * err;
    const bool step_x = e2 >= dy, step_y = e2 <= dx;
    // A diagonal step slips between two cells; a wall drawn as a staircase of obstacle cells has one of
    // them, so a beam that must stop at obstacles stops there too.
    if (stop_at_obstacle && step_x && step_y &&
        (IsObstacle({c.x + sx, c.y}) || IsObstacle({c.x, c.y + sy}))) {
      return;
    }
    if (step_x) err += dy, c.x += sx;
    if (step_y) err += dx, c.y += sy;
  }
  UpdateCellInTile(tile, b, last_delta);
}

bool TiledGrid::Bounds(CellIndex* min_cell, CellIndex* max_cell) const {
  bool any = false;
  for (int j = 0; j < tiles_y_; ++j) {
    for (int i = 0; i < tiles_x_; ++i) {
      if (!tiles_[static_cast<std::size_t>(j) * tiles_x_ + i]) continue;
      const CellIndex lo{(tile_x0_ + i) * kTileSize, (tile_y0_ + j) * kTileSize};
      const CellIndex hi{lo.x + kTileSize - 1, lo.y + kTileSize - 1};
      if (!any) *min_cell = lo, *max_cell = hi, any = true;
      min_cell->x = std::min(min_cell->x, lo.x), min_cell->y = std::min(min_cell->y, lo.y);
      max_cell->x = std::max(max_cell->x, hi.x), max_cell->y = std::max(max_cell->y, hi.y);
    }
  }
  return any;
}

std::size_t TiledGrid::TileCount() const {
  return static_cast<std::size_t>(
      std::count_if(tiles_.begin(), tiles_.end(), [](const auto& t) { return t != nullptr; }));
}

void TiledGrid::CollectTiles(std::unordered_set<const Tile*>* tiles) const {
  for (const auto& t : tiles_) {
    if (t) tiles->insert(t.get());
  }
}

bool TiledGrid::SharesTileWith(const TiledGrid& other, CellIndex c) const {
  const Tile* mine = TileAt(c.x >> kTileBits, c.y >> kTileBits);
  return mine != nullptr && mine == other.TileAt(c.x >> kTileBits, c.y >> kTileBits);
}

OccupancyGrid TiledGrid::ToOccupancyGrid(double threshold_log_odds) const {
  CellIndex lo, hi;
  if (!Bounds(&lo, &hi)) return OccupancyGrid(1, 1, resolution_m(), Pose2D{});
  OccupancyGrid grid(hi.x - lo.x + 1, hi.y - lo.y + 1, resolution_m(),
                     Pose2D{lo.x * resolution_m(), lo.y * resolution_m(), 0.0});
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!Observed({x, y})) continue;
      const double l = LogOdds({x, y});
      grid.At(x - lo.x, y - lo.y) = l > threshold_log_odds     ? OccupancyGrid::kOccupied
                                    : l < -threshold_log_odds ? OccupancyGrid::kFree
                                                              : std::int8_t{50};
    }
  }
  return grid;
}

}  // namespace doorplate_localization
