// The walls' cost per received-power computation (what every frame pays per receiver it is
// handed to), against the scenario's path loss alone measured in the same run: the 400-mote
// field of bench/walls_bench.py (motes 40 m apart, 0.2 m walls every 80 m with doorways),
// 2000 random pairs of neighbours up to 60 m apart, asked over and over.
//   path loss          log-distance alone: the baseline
//   walls, kept        the chain with the walls, the same pairs again (nodes at rest: the cache)
//   walls, computed    the chain with the walls, every pair moved since its last frame (the
//                      segment walked through the grid every time)
//
//   bench/obstacle_loss_bench [calls, default 2000000]
#include <ns3/constant-position-mobility-model.h>
#include <ns3/node.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <set>
#include <vector>

#include "net/obstacle_loss_model.h"
#include "net/path_loss.h"

namespace {

using namespace sanet;

std::vector<net::RadioObstacle> FieldWalls() {
  std::vector<net::RadioObstacle> walls;
  for (int k = 1; k < 10; ++k) {
    const double at = 80.0 * k - 20;
    for (double start = -20; start < 780; start += 40) {
      walls.push_back({{{at, start + 15, 1.25}, {30, 0.2, 2.5}, M_PI / 2}, 11.05, 0});
      walls.push_back({{{start + 15, at, 1.25}, {30, 0.2, 2.5}, 0}, 11.05, 0});
    }
  }
  return walls;
}

struct Field {
  std::vector<ns3::Ptr<ns3::ConstantPositionMobilityModel>> motes;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  Field() {
    for (int i = 0; i < 400; ++i) {
      auto node = ns3::CreateObject<ns3::Node>();
      auto at = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
      at->SetPosition({40.0 * (i % 20), 40.0 * (i / 20), 0.05});
      node->AggregateObject(at);
      motes.push_back(at);
    }
    std::mt19937 random(1);
    std::uniform_int_distribution<std::size_t> any(0, motes.size() - 1);
    std::set<std::pair<std::size_t, std::size_t>> seen;  // each pair once per round
    for (int tries = 0; tries < 1000000 && pairs.size() < 2000; ++tries) {
      const std::size_t a = any(random), b = any(random);
      if (a < b && ns3::CalculateDistance(motes[a]->GetPosition(), motes[b]->GetPosition()) <= 60 &&
          seen.insert({a, b}).second)
        pairs.push_back({a, b});
    }
  }
};

double NanosecondsPerCall(Field& field, ns3::Ptr<ns3::PropagationLossModel> loss, long calls, bool moving) {
  double sink = 0;
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < calls; ++i) {
    const auto& [a, b] = field.pairs[static_cast<std::size_t>(i) % field.pairs.size()];
    if (moving && i % field.pairs.size() == 0)  // a millimetre up or down: every pair has moved since last asked
      for (auto& mote : field.motes) mote->SetPosition(mote->GetPosition() + ns3::Vector(0, 0, i % 2 ? 1e-3 : -1e-3));
    sink += loss->CalcRxPower(16, field.motes[a], field.motes[b]);
  }
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  if (sink == 42) std::printf(" ");  // keeps the loop
  return ns / static_cast<double>(calls);
}

}  // namespace

int main(int argc, char** argv) {
  const long calls = argc > 1 ? std::atol(argv[1]) : 2000000;
  Field field;
  const net::NetworkSpec spec;
  const auto plain = net::PathLoss(spec);
  const auto walled = net::PathLoss(spec);
  auto walls = ns3::CreateObject<net::ObstacleLossModel>();
  walls->SetObstacles(std::make_shared<const net::ObstacleCrossings>(FieldWalls()));
  net::LastOf(walled)->SetNext(walls);
  std::printf("received power per call, 400 motes 40 m apart, %zu walls, %ld calls per case\n", FieldWalls().size(),
              calls);
  const double base = NanosecondsPerCall(field, plain, calls, true);
  const double kept = NanosecondsPerCall(field, walled, calls, false);
  const double computed = NanosecondsPerCall(field, walled, calls, true);
  std::printf("%-18s %8.1f ns  %6.2fx\n", "path loss", base, 1.0);
  std::printf("%-18s %8.1f ns  %6.2fx\n", "walls, kept", kept, kept / base);
  std::printf("%-18s %8.1f ns  %6.2fx\n", "walls, computed", computed, computed / base);
  std::printf("(asked %llu, computed %llu)\n", static_cast<unsigned long long>(walls->counters().asked),
              static_cast<unsigned long long>(walls->counters().walked));
  return 0;
}
