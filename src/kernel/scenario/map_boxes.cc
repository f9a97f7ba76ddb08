#include "scenario/map_boxes.h"

namespace sanet::scenario {

std::vector<CellRect> MergeCells(int width, int height, const std::function<bool(int, int)>& blocked) {
  std::vector<char> open(static_cast<std::size_t>(width) * height);  // blocked and not yet covered
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column)
      open[static_cast<std::size_t>(row) * width + column] = blocked(column, row) ? 1 : 0;
  const auto at = [&](int column, int row) -> char& { return open[static_cast<std::size_t>(row) * width + column]; };
  std::vector<CellRect> rects;
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      if (!at(column, row)) continue;
      CellRect r{column, row, 1, 1};
      while (r.column + r.columns < width && at(r.column + r.columns, row)) ++r.columns;
      for (bool whole = true; whole && r.row + r.rows < height;) {
        for (int c = r.column; c < r.column + r.columns && whole; ++c) whole = at(c, r.row + r.rows);
        if (whole) ++r.rows;
      }
      for (int y = r.row; y < r.row + r.rows; ++y)
        for (int x = r.column; x < r.column + r.columns; ++x) at(x, y) = 0;
      rects.push_back(r);
    }
  return rects;
}

}  // namespace sanet::scenario
