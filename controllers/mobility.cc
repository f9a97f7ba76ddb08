// Mobility models that mobility studies start from, as controllers of any robot: random
// waypoint, a tour through points (in the order given or nearest first) and a lawnmower sweep of
// a rectangle. Each drives omni3 and diffdrive robots with the Pilot of `waypoint`, going round
// the obstacles its laser or IR ring sees, and logs each point it reaches.
#include "mobility.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "controllers.h"
#include "navigation.h"

namespace sanet::controllers {
namespace {

// The rectangle `region: [[x0, y0], [x1, y1]]` (two opposite corners).
std::pair<Vec2, Vec2> ReadRectangle(const Params& p, const char* key) {
  const auto corners = p.Table(key, 2, {});
  if (corners.size() != 2)
    throw ParamError(key, p.Line(key), "parameter '" + std::string(key) + "' must be [[x0, y0], [x1, y1]]");
  const Vec2 low{std::min(corners[0][0], corners[1][0]), std::min(corners[0][1], corners[1][1])};
  const Vec2 high{std::max(corners[0][0], corners[1][0]), std::max(corners[0][1], corners[1][1])};
  if (low.x == high.x || low.y == high.y)
    throw ParamError(key, p.Line(key), "parameter '" + std::string(key) + "' encloses no area");
  return {low, high};
}

// Drives through a list of points with the Pilot, one after the other.
class Route {
 public:
  explicit Route(const Params& p)
      : pilot_(PilotSettings::FromParams(p)), tolerance_(p.Number("tolerance", 0.3, 0.01)) {}
  // Steers towards `goal`; true once the robot is within the tolerance of it.
  bool Steer(Node& node, const Pose2D& pose, Vec2 goal) {
    if (Norm(goal - pose.position()) < tolerance_) {
      pilot_.Reset();
      return true;
    }
    std::optional<RangeScan> scan = node.Laser();
    if (!scan) scan = node.Ir();
    node.Drive(pilot_.Steer(node.Now(), pose, goal, scan ? &*scan : nullptr, node.Holonomic()));
    return false;
  }
  void SetSpeed(double speed) { pilot_.SetSpeed(speed); }

 private:
  Pilot pilot_;
  double tolerance_;
};

// Random waypoint (Johnson and Maltz, "Dynamic source routing in ad hoc wireless networks",
// 1996): a point drawn uniformly in the region, a speed drawn uniformly in [speed_min,
// speed_max], the way there, a pause, again. A minimum speed above 0 keeps the average speed
// from decaying over the run (Yoon, Liu and Noble, "Random waypoint considered harmful", 2003).
class RandomWaypoint : public Controller {
 public:
  explicit RandomWaypoint(const Params& p)
      : route_(p),
        region_(ReadRectangle(p, "region")),
        speed_min_(p.Number("speed_min", 0.3, 0.01, 10)),
        speed_max_(p.Number("speed_max", 1.0, 0.01, 10)),
        pause_(p.Number("pause", 0, 0)) {
    if (speed_max_ < speed_min_)
      throw ParamError("speed_max", p.Line("speed_max"), "parameter 'speed_max' is under speed_min");
    if (p.Has("speed"))
      throw ParamError("speed", p.Line("speed"),
                       "parameter 'speed': random_waypoint draws each leg's speed in [speed_min, speed_max]");
  }

  void ControlStep(Node& node) override {
    const std::optional<Pose2D> pose = node.GroundTruth();
    if (!pose) return;
    if (node.Now() < paused_until_) return void(node.Drive({}));
    if (!goal_) NextLeg(node);
    if (!route_.Steer(node, *pose, *goal_)) return;
    node.Log("reached waypoint " + std::to_string(legs_));
    node.Drive({});
    goal_.reset();
    paused_until_ = node.Now() + pause_;
  }

 private:
  void NextLeg(Node& node) {
    goal_ = Vec2{region_.first.x + (region_.second.x - region_.first.x) * node.Random(),
                 region_.first.y + (region_.second.y - region_.first.y) * node.Random()};
    const double speed = speed_min_ + (speed_max_ - speed_min_) * node.Random();
    route_.SetSpeed(speed);
    node.Metric("leg_speed", speed);
    ++legs_;
  }

  Route route_;
  std::pair<Vec2, Vec2> region_;
  double speed_min_, speed_max_, pause_;
  std::optional<Vec2> goal_;
  double paused_until_ = 0;
  int legs_ = 0;
};

// Visits `points` in turn (with `loop`, again and again); `order: nearest` reorders them first:
// from where the robot starts, always the nearest point not yet visited.
class Tour : public Controller {
 public:
  Tour(const Params& p, std::vector<Vec2> points, bool loop, bool nearest)
      : route_(p), points_(std::move(points)), loop_(loop), nearest_(nearest) {
    if (points_.empty()) throw ParamError("points", p.Line("points"), "parameter 'points' is required: [[x, y], ...]");
    for (std::size_t i = 0; i < points_.size(); ++i) order_.push_back(i);
  }

  void ControlStep(Node& node) override {
    const std::optional<Pose2D> pose = node.GroundTruth();
    if (!pose || next_ >= points_.size()) return;
    if (nearest_ && !ordered_) Order(pose->position());
    if (!route_.Steer(node, *pose, points_[next_])) return;
    node.Log("reached point " + std::to_string(order_[next_]));
    if (++next_ < points_.size()) return;
    if (loop_) return void(next_ = 0);
    node.Drive({});
    node.Log("tour done");
  }

 private:
  void Order(Vec2 from) {
    std::vector<bool> taken(points_.size(), false);
    std::vector<Vec2> ordered;
    order_.clear();
    for (std::size_t k = 0; k < points_.size(); ++k) {
      std::size_t best = 0;
      double best_distance = HUGE_VAL;
      for (std::size_t i = 0; i < points_.size(); ++i)
        if (!taken[i] && Norm(points_[i] - from) < best_distance) best = i, best_distance = Norm(points_[i] - from);
      taken[best] = true;
      ordered.push_back(from = points_[best]);
      order_.push_back(best);
    }
    points_ = ordered;
    ordered_ = true;
  }

  Route route_;
  std::vector<std::size_t> order_;  // the index each point to visit had in `points`
  std::vector<Vec2> points_;
  bool loop_, nearest_, ordered_ = false;
  std::size_t next_ = 0;
};

}  // namespace

std::unique_ptr<Controller> MakeTour(const Params& p) {
  std::vector<Vec2> points;
  for (const auto& row : p.Table("points", 2, {})) points.push_back({row[0], row[1]});
  const std::string order = p.Text("order", "given");
  if (order != "given" && order != "nearest")
    throw ParamError("order", p.Line("order"), "parameter 'order' must be given or nearest");
  return std::make_unique<Tour>(p, points, p.Flag("loop", false), order == "nearest");
}

namespace {

// Boustrophedon lines `spacing` apart across the region, along x (or y), turning at each end.
std::vector<Vec2> LawnmowerLines(std::pair<Vec2, Vec2> region, double spacing, bool along_y) {
  const auto [low, high] = region;
  std::vector<Vec2> points;
  const double across_low = along_y ? low.x : low.y, across_high = along_y ? high.x : high.y;
  const double along_low = along_y ? low.y : low.x, along_high = along_y ? high.y : high.x;
  bool forwards = true;
  for (double c = across_low + spacing / 2; c <= across_high - spacing / 2 + 1e-9 || points.empty(); c += spacing) {
    const double from = forwards ? along_low : along_high, to = forwards ? along_high : along_low;
    for (double a : {from, to}) points.push_back(along_y ? Vec2{c, a} : Vec2{a, c});
    forwards = !forwards;
  }
  return points;
}

std::unique_ptr<Controller> MakeLawnmower(const Params& p) {
  const auto region = ReadRectangle(p, "region");
  const double spacing = p.Number("spacing", 2.0, 0.05, 1e4);
  const std::string axis = p.Text("along", "x");
  if (axis != "x" && axis != "y") throw ParamError("along", p.Line("along"), "parameter 'along' must be x or y");
  return std::make_unique<Tour>(p, LawnmowerLines(region, spacing, axis == "y"), p.Flag("loop", false), false);
}

}  // namespace

ControllerInfo RandomWaypointInfo() {
  return {"random_waypoint",
          "random waypoint: drives to a point drawn uniformly in `region` ([[x0, y0], [x1, y1]] m) at a speed "
          "drawn in [`speed_min`, `speed_max`], waits `pause` s, and again; goes round obstacles as waypoint does",
          [](const Params& p) { return std::make_unique<RandomWaypoint>(p); }};
}

ControllerInfo TourInfo() {
  return {"tour",
          "visits `points` ([[x, y], ...] m) in the `order` given or `nearest` first (from where it starts), "
          "once or with `loop` again and again, going round obstacles as waypoint does",
          MakeTour};
}

ControllerInfo LawnmowerInfo() {
  return {"lawnmower",
          "sweeps `region` ([[x0, y0], [x1, y1]] m) in lines `spacing` m apart along `along` (x or y), turning at "
          "each end: a coverage pattern; with `loop` it starts over",
          MakeLawnmower};
}

}  // namespace sanet::controllers
