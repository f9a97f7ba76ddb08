// A grid's blocked cells as few axis-aligned rectangles as a greedy pass finds: from the
// bottom-left, each rectangle takes the longest run of blocked cells along its row not yet
// covered, then grows upwards while the whole run above is blocked and uncovered. Every blocked
// cell is in exactly one rectangle and no free cell is in any. On a SLAM map, whose walls are
// ragged lines of cells, this gives about a quarter as many boxes as cells
// (docs/scenario.md#worldmap).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace sanet::scenario {

struct CellRect {
  int column = 0, row = 0;    // the lower-left cell
  int columns = 1, rows = 1;  // its size in cells
  bool operator==(const CellRect& o) const {
    return column == o.column && row == o.row && columns == o.columns && rows == o.rows;
  }
};

std::vector<CellRect> MergeCells(int width, int height, const std::function<bool(int column, int row)>& blocked);

}  // namespace sanet::scenario
