// A uniform grid over the ground plane that answers "which items may lie within r of this
// point?" in time proportional to the answer, not to the number of items. Items are numbered
// 0, 1, 2 ... (a radio's index on its channel); the grid holds each one's cell only, so a query
// returns candidates, which the caller checks exactly. Cells are kept in a hash map: the world
// has no bounds, and empty cells cost nothing.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sanet::net {

class SpatialGrid {
 public:
  explicit SpatialGrid(double cell_size);

  double cell_size() const { return cell_size_; }
  std::size_t size() const { return where_.size(); }
  // Puts item `id` at (x, y); an item already in the grid moves there. Ids are dense: adding
  // id n grows the grid to n + 1 items (ids in between are absent until placed).
  void Place(std::uint32_t id, double x, double y);
  // Appends to `out`, in ascending id order, every item in a cell that a disc of radius `r`
  // around (x, y) touches: a superset of the items within r.
  void Near(double x, double y, double r, std::vector<std::uint32_t>& out) const;

 private:
  struct Slot {
    std::int64_t cell = 0;
    std::uint32_t index = 0;  // position in that cell's list
    bool placed = false;
  };
  std::int64_t CellOf(double x, double y) const;
  static std::int64_t Key(std::int64_t cx, std::int64_t cy);
  std::int64_t Coordinate(double v) const;
  void Remove(std::uint32_t id);

  double cell_size_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
  std::vector<Slot> where_;
};

}  // namespace sanet::net
