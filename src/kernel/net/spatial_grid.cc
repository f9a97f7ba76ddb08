#include "net/spatial_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sanet::net {
namespace {
// Cell coordinates are kept within 31 bits each so that one 64-bit key holds both.
constexpr std::int64_t kCoordinateLimit = (std::int64_t{1} << 30) - 1;
}  // namespace

SpatialGrid::SpatialGrid(double cell_size) : cell_size_(cell_size) {
  if (!(cell_size > 0) || !std::isfinite(cell_size)) throw std::invalid_argument("grid cell size must be positive");
}

std::int64_t SpatialGrid::Coordinate(double v) const {
  const double c = std::floor(v / cell_size_);
  return static_cast<std::int64_t>(std::clamp(c, double(-kCoordinateLimit), double(kCoordinateLimit)));
}

std::int64_t SpatialGrid::Key(std::int64_t cx, std::int64_t cy) {
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(cx) << 32) | static_cast<std::uint32_t>(cy));
}

std::int64_t SpatialGrid::CellOf(double x, double y) const { return Key(Coordinate(x), Coordinate(y)); }

void SpatialGrid::Place(std::uint32_t id, double x, double y) {
  if (id >= where_.size()) where_.resize(id + 1);
  const std::int64_t cell = CellOf(x, y);
  Slot& slot = where_[id];
  if (slot.placed && slot.cell == cell) return;
  if (slot.placed) Remove(id);
  std::vector<std::uint32_t>& members = cells_[cell];
  slot = {cell, static_cast<std::uint32_t>(members.size()), true};
  members.push_back(id);
}

// Swap-and-pop: the last member of the cell takes the removed one's place.
void SpatialGrid::Remove(std::uint32_t id) {
  Slot& slot = where_[id];
  auto found = cells_.find(slot.cell);
  std::vector<std::uint32_t>& members = found->second;
  const std::uint32_t last = members.back();
  members[slot.index] = last;
  where_[last].index = slot.index;
  members.pop_back();
  if (members.empty()) cells_.erase(found);
  slot.placed = false;
}

void SpatialGrid::Near(double x, double y, double r, std::vector<std::uint32_t>& out) const {
  const std::size_t first = out.size();
  const std::int64_t x0 = Coordinate(x - r), x1 = Coordinate(x + r);
  const std::int64_t y0 = Coordinate(y - r), y1 = Coordinate(y + r);
  // A disc wider than the populated cells: walking the cells is cheaper than walking the disc.
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > static_cast<std::int64_t>(cells_.size())) {
    for (const auto& [key, members] : cells_) {
      const std::int64_t cx = key >> 32, cy = static_cast<std::int32_t>(key & 0xffffffff);
      if (cx >= x0 && cx <= x1 && cy >= y0 && cy <= y1) out.insert(out.end(), members.begin(), members.end());
    }
  } else {
    for (std::int64_t cx = x0; cx <= x1; ++cx)
      for (std::int64_t cy = y0; cy <= y1; ++cy)
        if (auto found = cells_.find(Key(cx, cy)); found != cells_.end())
          out.insert(out.end(), found->second.begin(), found->second.end());
  }
  std::sort(out.begin() + first, out.end());
}

}  // namespace sanet::net
