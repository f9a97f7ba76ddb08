#include "net/obstacle_crossings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace sanet::net {
namespace {

// The box's footprint corners seen from above, for the cells it touches.
void FootprintBounds(const physics::StaticBox& box, double& lo_x, double& lo_y, double& hi_x, double& hi_y) {
  const double c = std::fabs(std::cos(box.yaw)), s = std::fabs(std::sin(box.yaw));
  const double half_x = (box.size.x * c + box.size.y * s) / 2, half_y = (box.size.x * s + box.size.y * c) / 2;
  lo_x = box.center.x - half_x, hi_x = box.center.x + half_x;
  lo_y = box.center.y - half_y, hi_y = box.center.y + half_y;
}

}  // namespace

std::pair<double, double> EnterLeave(const physics::StaticBox& box, const physics::Vec3& a, const physics::Vec3& b) {
  // Both ends in the box's own frame, where it is axis-aligned about the origin.
  const double c = std::cos(-box.yaw), s = std::sin(-box.yaw);
  const auto local = [&](const physics::Vec3& p) {
    const double x = p.x - box.center.x, y = p.y - box.center.y;
    return physics::Vec3{x * c - y * s, x * s + y * c, p.z - box.center.z};
  };
  const physics::Vec3 p = local(a), q = local(b);
  const double from[3] = {p.x, p.y, p.z}, d[3] = {q.x - p.x, q.y - p.y, q.z - p.z};
  const double half[3] = {box.size.x / 2, box.size.y / 2, box.size.z / 2};
  double t0 = 0, t1 = 1;  // the slabs' clipping of the segment
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(d[i]) < 1e-15) {
      if (std::fabs(from[i]) >= half[i]) return {1, 0};
      continue;
    }
    double enter = (-half[i] - from[i]) / d[i], leave = (half[i] - from[i]) / d[i];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter), t1 = std::min(t1, leave);
    if (t0 >= t1) return {1, 0};
  }
  return {t0, t1};
}

double LengthInside(const physics::StaticBox& box, const physics::Vec3& a, const physics::Vec3& b) {
  const auto [enter, leave] = EnterLeave(box, a, b);
  if (enter >= leave) return 0;
  const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
  return (leave - enter) * std::sqrt(dx * dx + dy * dy + dz * dz);
}

ObstacleCrossings::ObstacleCrossings(std::vector<RadioObstacle> obstacles, double cell)
    : obstacles_(std::move(obstacles)), cell_(cell), seen_(obstacles_.size(), 0) {
  if (obstacles_.empty()) return;
  std::vector<std::array<std::int64_t, 4>> spans;  // each obstacle's cells: x0, y0, x1, y1
  min_x_ = min_y_ = INT64_MAX, max_x_ = max_y_ = INT64_MIN;
  for (const RadioObstacle& o : obstacles_) {
    double lo_x, lo_y, hi_x, hi_y;
    FootprintBounds(o.box, lo_x, lo_y, hi_x, hi_y);
    spans.push_back({Cell(lo_x), Cell(lo_y), Cell(hi_x), Cell(hi_y)});
    min_x_ = std::min(min_x_, spans.back()[0]), min_y_ = std::min(min_y_, spans.back()[1]);
    max_x_ = std::max(max_x_, spans.back()[2]), max_y_ = std::max(max_y_, spans.back()[3]);
  }
  const std::int64_t rows = max_y_ - min_y_ + 1;
  cells_.resize(static_cast<std::size_t>((max_x_ - min_x_ + 1) * rows));
  for (std::size_t i = 0; i < spans.size(); ++i)
    for (std::int64_t x = spans[i][0]; x <= spans[i][2]; ++x)
      for (std::int64_t y = spans[i][1]; y <= spans[i][3]; ++y)
        cells_[static_cast<std::size_t>((x - min_x_) * rows + (y - min_y_))].push_back(i);
}

void ObstacleCrossings::Visit(std::int64_t cx, std::int64_t cy, std::vector<std::size_t>& found) const {
  if (cx < min_x_ || cx > max_x_ || cy < min_y_ || cy > max_y_) return;
  for (const std::size_t i : cells_[static_cast<std::size_t>((cx - min_x_) * (max_y_ - min_y_ + 1) + (cy - min_y_))])
    if (seen_[i] != query_) {
      seen_[i] = query_;
      found.push_back(i);
    }
}

// The obstacles whose cells the segment's shadow crosses, each once, into `found` (unsorted).
void ObstacleCrossings::Candidates(const physics::Vec3& a, const physics::Vec3& b,
                                   std::vector<std::size_t>& found) const {
  found.clear();
  if (obstacles_.empty()) return;
  ++query_;
  // Amanatides and Woo: the cells the segment's shadow crosses, in order.
  std::int64_t cx = Cell(a.x), cy = Cell(a.y);
  const std::int64_t end_x = Cell(b.x), end_y = Cell(b.y);
  const double dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  const auto boundary = [&](std::int64_t c, std::int64_t step) { return origin_ + (c + (step > 0 ? 1 : 0)) * cell_; };
  double next_x = dx != 0 ? (boundary(cx, step_x) - a.x) / dx : HUGE_VAL;
  double next_y = dy != 0 ? (boundary(cy, step_y) - a.y) / dy : HUGE_VAL;
  const double delta_x = dx != 0 ? cell_ / std::fabs(dx) : HUGE_VAL,
               delta_y = dy != 0 ? cell_ / std::fabs(dy) : HUGE_VAL;
  for (;;) {
    Visit(cx, cy, found);
    // At the end's cell, or past the segment's end (the parameters only grow: this ends).
    if ((cx == end_x && cy == end_y) || std::min(next_x, next_y) > 1) break;
    if (next_x < next_y) {
      cx += step_x, next_x += delta_x;
    } else {
      cy += step_y, next_y += delta_y;
    }
  }
}

std::vector<Crossing> ObstacleCrossings::Crossings(const physics::Vec3& a, const physics::Vec3& b) const {
  std::vector<Crossing> out;
  std::vector<std::size_t> found;
  Candidates(a, b, found);
  std::sort(found.begin(), found.end());
  for (const std::size_t i : found)
    if (const double length = LengthInside(obstacles_[i].box, a, b); length > 0) out.push_back({i, length});
  return out;
}

// As the sum over Crossings, without building it: a frame's loss allocates nothing. The sum is
// taken in the obstacles' order, as Crossings lists them, so both give the same bits.
double ObstacleCrossings::LossDb(const physics::Vec3& a, const physics::Vec3& b) const {
  Candidates(a, b, found_);
  std::sort(found_.begin(), found_.end());
  const double length = std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y) + (b.z - a.z) * (b.z - a.z));
  double loss = 0;
  std::vector<std::pair<double, double>>& pieces = pieces_;  // where pieces are crossed, along a-b
  pieces.clear();
  double piece_loss = 0, joined_within = 0;
  for (const std::size_t i : found_) {
    const RadioObstacle& o = obstacles_[i];
    const auto [enter, leave] = EnterLeave(o.box, a, b);
    if (enter >= leave) continue;
    loss += o.loss_db_per_m * (leave - enter) * length;
    if (!o.piece) {
      loss += o.loss_db;
      continue;
    }
    pieces.push_back({enter, leave});
    piece_loss = o.loss_db, joined_within = o.joined_within;
  }
  return loss + piece_loss * static_cast<double>(Runs(pieces, length > 0 ? joined_within / length : 0));
}

// The runs the crossed pieces make along the segment: crossings closer than `gap` (a fraction of
// the segment) are one.
std::size_t ObstacleCrossings::Runs(std::vector<std::pair<double, double>>& pieces, double gap) {
  std::sort(pieces.begin(), pieces.end());
  std::size_t runs = 0;
  double reach = -1;
  for (const auto& [enter, leave] : pieces) {
    if (enter > reach + gap) ++runs;
    reach = std::max(reach, leave);
  }
  return runs;
}

}  // namespace sanet::net
