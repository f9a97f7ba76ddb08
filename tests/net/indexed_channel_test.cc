// The indexed channel: its grid finds every radio within a distance, with the floor at the
// receivers' sensitivity it gives exactly Yans's receptions and fingerprint, and above it a
// frame never reaches a radio farther than where its power falls under the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "net/spatial_grid.h"
#include "support/test_world.h"

namespace sanet {
namespace {

using namespace sanet::testing;
using robots::ModelKind;

ParamValue Text(const std::string& text) {
  ParamValue p;
  p.rows = {{text}};
  return p;
}

TEST(SpatialGrid, OffersEveryItemWithinTheDistanceInIdOrder) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-300, 300);
  net::SpatialGrid grid(40);
  std::vector<std::pair<double, double>> at(500);
  for (std::uint32_t id = 0; id < at.size(); ++id) {
    at[id] = {coordinate(random), coordinate(random)};
    grid.Place(id, at[id].first, at[id].second);
  }
  for (int round = 0; round < 3; ++round) {
    for (std::uint32_t id = 0; id < at.size(); id += 3) {  // a third of them move
      at[id] = {coordinate(random), coordinate(random)};
      grid.Place(id, at[id].first, at[id].second);
    }
    for (double r : {5.0, 40.0, 95.0, 1000.0}) {
      const double x = coordinate(random), y = coordinate(random);
      std::vector<std::uint32_t> near;
      grid.Near(x, y, r, near);
      EXPECT_TRUE(std::is_sorted(near.begin(), near.end()));
      EXPECT_EQ(std::adjacent_find(near.begin(), near.end()), near.end()) << "an item offered twice";
      for (std::uint32_t id = 0; id < at.size(); ++id) {
        if (std::hypot(at[id].first - x, at[id].second - y) <= r) {
          EXPECT_TRUE(std::binary_search(near.begin(), near.end(), id)) << "item " << id << " within " << r;
        }
      }
      if (r == 5.0) {
        EXPECT_LT(near.size(), at.size() / 10) << "a small disc offered most of the items";
      }
    }
  }
}

nlohmann::json Summary(const sim::RunSpec& spec, const std::string& tag, std::string* fingerprint) {
  const std::string dir = ::testing::TempDir() + "/sanet-indexed-" + tag;
  std::filesystem::remove_all(dir);
  sim::World world(spec, BuiltinRegistry());
  *fingerprint = world.Run({dir, ""}).fingerprint;
  return nlohmann::json::parse(ReadFile(dir + "/summary.json"));
}

// 100 motes 25 m apart with AODV and traffic, and three robots driving across the field, with a
// radio whose sensitivity (-101 dBm) reaches about 65 m: the grid (cells of that size) offers
// each frame a fraction of the radios.
sim::RunSpec CrowdedField(net::ChannelModel channel) {
  sim::RunSpec spec;
  spec.duration = 12;
  spec.world_size = {400, 400};
  spec.network = net::NetworkSpec{};
  spec.network->tx_power = 0;
  spec.network->rx_threshold = -95;
  spec.network->packet_log = false;
  spec.network->channel = channel;
  spec.network->channel_floor = -101;
  for (int i = 0; i < 100; ++i) {
    sim::NodeSpec mote = Robot("m" + std::to_string(i), ModelKind::kMote, {25.0 * (i % 10), 25.0 * (i / 10), 0});
    if (i % 7 == 0)
      mote.controller = UseController(
          "pinger", {{"to", Text("m" + std::to_string(99 - i))}, {"interval", Scalar(0.5)}, {"size", Scalar(64)}});
    spec.nodes.push_back(mote);
  }
  for (int r = 0; r < 3; ++r)
    spec.nodes.push_back(Robot("r" + std::to_string(r), ModelKind::kOmni3, {-70.0, 40.0 + 70 * r, 0},
                               UseController("constant_velocity", {{"vx", Scalar(1.0 + r)}})));
  return spec;
}

TEST(IndexedChannel, WithTheFloorAtTheSensitivityReceivesExactlyWhatYansReceives) {
  std::string yans_fingerprint, indexed_fingerprint;
  const nlohmann::json yans = Summary(CrowdedField(net::ChannelModel::kYans), "yans", &yans_fingerprint);
  const nlohmann::json indexed = Summary(CrowdedField(net::ChannelModel::kIndexed), "exact", &indexed_fingerprint);
  const nlohmann::json& y = yans["network"];
  const nlohmann::json& i = indexed["network"];
  ASSERT_GT(y["channel"]["frames_received"].get<int>(), 1000);
  EXPECT_EQ(i["channel"]["frames_sent"], y["channel"]["frames_sent"]);
  EXPECT_EQ(i["channel"]["frames_received"], y["channel"]["frames_received"]);
  EXPECT_EQ(i["packets"], y["packets"]);
  EXPECT_EQ(i["route_discoveries"], y["route_discoveries"]);
  EXPECT_EQ(indexed_fingerprint, yans_fingerprint);
  // ...while handing each frame to a fraction of the 102 other radios.
  EXPECT_LT(i["channel"]["receivers_considered_per_frame"].get<double>(), 60);
}

// Concrete walls across the crowded field cut its links; the indexed channel's ranges come from
// the wall-free loss, so it still hands every frame Yans delivers: the same receptions.
TEST(IndexedChannel, WithWallsReceivesExactlyWhatYansReceives) {
  const auto walled = [](net::ChannelModel channel, net::Material material) {
    sim::RunSpec spec = CrowdedField(channel);
    for (double x : {37.5, 87.5, 137.5, 187.5}) {
      spec.obstacles.push_back(Wall({x, -12.5}, {x, 237.5}, 3.0, 0.3));
      spec.obstacles.back().material = material;
    }
    return spec;
  };
  std::string open_fingerprint, yans_fingerprint, indexed_fingerprint;
  const nlohmann::json open =
      Summary(walled(net::ChannelModel::kYans, net::Material::kNone), "open", &open_fingerprint);
  const nlohmann::json yans =
      Summary(walled(net::ChannelModel::kYans, net::Material::kConcrete), "walls-yans", &yans_fingerprint);
  const nlohmann::json indexed =
      Summary(walled(net::ChannelModel::kIndexed, net::Material::kConcrete), "walls-indexed", &indexed_fingerprint);
  const nlohmann::json& y = yans["network"];
  const nlohmann::json& i = indexed["network"];
  EXPECT_LT(y["channel"]["frames_received"].get<double>(),
            0.9 * open["network"]["channel"]["frames_received"].get<double>())
      << "the walls cut links";
  EXPECT_EQ(i["channel"]["frames_sent"], y["channel"]["frames_sent"]);
  EXPECT_EQ(i["channel"]["frames_received"], y["channel"]["frames_received"]);
  EXPECT_EQ(i["packets"], y["packets"]);
  EXPECT_EQ(indexed_fingerprint, yans_fingerprint);
  EXPECT_NE(yans_fingerprint, open_fingerprint);
}

// A grey-zone radio (shadowing correlated over 10 m, Nakagami fading, hardware spread) on the
// crowded field with its robots driving through: the indexed channel's ranges widen by the
// shadowing's clip and the fading's cap, and fading is drawn the same whoever asks, so it still
// receives exactly what Yans receives; and the grey zone changes what is received.
TEST(IndexedChannel, WithShadowingAndFadingReceivesExactlyWhatYansReceives) {
  const auto grey = [](net::ChannelModel channel) {
    sim::RunSpec spec = CrowdedField(channel);
    spec.network->shadowing.sigma_db = 6;
    spec.network->fading.model = net::FadingModel::kNakagami;
    spec.network->fading.m = 1.5;
    spec.network->spread.tx_power_db = 1;
    spec.network->spread.noise_figure_db = 1;
    return spec;
  };
  std::string plain_fingerprint, yans_fingerprint, indexed_fingerprint;
  const nlohmann::json plain = Summary(CrowdedField(net::ChannelModel::kYans), "plain", &plain_fingerprint);
  const nlohmann::json yans = Summary(grey(net::ChannelModel::kYans), "grey-yans", &yans_fingerprint);
  const nlohmann::json indexed = Summary(grey(net::ChannelModel::kIndexed), "grey-indexed", &indexed_fingerprint);
  const nlohmann::json& y = yans["network"];
  const nlohmann::json& i = indexed["network"];
  ASSERT_GT(y["channel"]["frames_received"].get<int>(), 1000);
  EXPECT_NE(y["channel"]["frames_received"], plain["network"]["channel"]["frames_received"]);
  EXPECT_NE(yans_fingerprint, plain_fingerprint);
  EXPECT_EQ(i["channel"]["frames_sent"], y["channel"]["frames_sent"]);
  EXPECT_EQ(i["channel"]["frames_received"], y["channel"]["frames_received"]);
  EXPECT_EQ(i["packets"], y["packets"]);
  EXPECT_EQ(i["route_discoveries"], y["route_discoveries"]);
  EXPECT_EQ(indexed_fingerprint, yans_fingerprint);
}

// Shadowing of sigma 0 (whatever its other keys) and no fading build no model at all: the same
// run as the plain radio, byte for byte.
TEST(IndexedChannel, ShadowingOfSigmaZeroChangesNothing) {
  sim::RunSpec quiet = CrowdedField(net::ChannelModel::kIndexed);
  quiet.duration = 4;
  sim::RunSpec zero = quiet;
  zero.network->shadowing.sigma_db = 0;
  zero.network->shadowing.correlation_m = 3;
  zero.network->shadowing.symmetric = false;
  std::string plain_fingerprint, zero_fingerprint;
  Summary(quiet, "sigma-plain", &plain_fingerprint);
  const nlohmann::json z = Summary(zero, "sigma-zero", &zero_fingerprint);
  EXPECT_EQ(zero_fingerprint, plain_fingerprint);
  EXPECT_FALSE(z["network"]["channel"].contains("shadowing"));
}

// Radios on a line 10, 20, ... 150 m from a mote that broadcasts once a second, no routing (so
// its frames are the only ones): with the default radio (16 dBm, log-distance exponent 3,
// 46.6777 dB at 1 m) a frame arrives at the default floor (-91 dBm) at 102.6 m.
TEST(IndexedChannel, AFrameNeverReachesARadioBeyondTheFloorsRange) {
  const double floor = net::NetworkSpec{}.ChannelFloor();
  const double floor_range = std::pow(10.0, (16 - 46.6777 - floor) / 30);
  sim::RunSpec spec;
  spec.duration = 5.5;
  spec.network = net::NetworkSpec{};
  spec.network->routing = net::Routing::kNone;
  spec.network->packet_log = false;
  spec.nodes.push_back(Robot("source", ModelKind::kMote, {0, 0, 0},
                             UseController("pinger", {{"to", Text("broadcast")}, {"interval", Scalar(1)}})));
  int within = 0;
  for (int d = 10; d <= 150; d += 10) {
    spec.nodes.push_back(Robot("at" + std::to_string(d), ModelKind::kMote, {double(d), 0, 0}));
    within += d <= floor_range;
  }
  ASSERT_EQ(floor, -91);
  ASSERT_EQ(within, 10);
  std::string fingerprint;
  const nlohmann::json c = Summary(spec, "floor", &fingerprint)["network"]["channel"];
  EXPECT_EQ(c["floor_dbm"].get<double>(), floor);
  EXPECT_EQ(c["frames_sent"].get<int>(), 5);
  EXPECT_DOUBLE_EQ(c["receivers_per_frame"].get<double>(), within);
  EXPECT_GT(c["receivers_considered_per_frame"].get<double>(), within) << "the grid offered only radios in range";
  // Detected (over -82 dBm, 51.6 m): the radios at 10 ... 50 m, as with Yans.
  EXPECT_EQ(c["frames_received"].get<int>(), 5 * 5);
}

// broadcast_jitter: each broadcast waits up to the jitter before it goes to the radio, so the
// delays in messages.csv spread over [0, jitter] plus the air time; without it they are equal.
TEST(BroadcastJitter, SpreadsBroadcastsOverTheJitter) {
  auto delays = [](double jitter) {
    sim::RunSpec spec;
    spec.duration = 20.5;
    spec.network = net::NetworkSpec{};
    spec.network->routing = net::Routing::kNone;
    spec.network->packet_log = false;
    spec.network->broadcast_jitter = jitter;
    spec.nodes.push_back(Robot("source", ModelKind::kMote, {0, 0, 0},
                               UseController("pinger", {{"to", Text("broadcast")}, {"interval", Scalar(1)}})));
    spec.nodes.push_back(Robot("sink", ModelKind::kMote, {10, 0, 0}));
    const std::string dir = ::testing::TempDir() + "/sanet-jitter";
    std::filesystem::remove_all(dir);
    sim::World world(spec, BuiltinRegistry());
    world.Run({dir, ""});
    std::vector<double> out;
    std::istringstream csv(ReadFile(dir + "/messages.csv"));
    std::string line;
    std::getline(csv, line);
    while (std::getline(csv, line)) out.push_back(std::stod(line.substr(line.rfind(",", line.rfind(",") - 1) + 1)));
    return out;
  };
  const std::vector<double> steady = delays(0), jittered = delays(0.05);
  ASSERT_EQ(steady.size(), 20u);
  ASSERT_EQ(jittered.size(), 20u);
  const auto [low, high] = std::minmax_element(steady.begin(), steady.end());
  EXPECT_LT(*high - *low, 1e-6) << "without jitter every broadcast takes the same time";
  const auto [first, last] = std::minmax_element(jittered.begin(), jittered.end());
  EXPECT_GE(*first, *low - 1e-9);
  EXPECT_LE(*last, *low + 0.05 + 1e-6) << "no broadcast waits longer than the jitter";
  EXPECT_GT(*last - *first, 0.02) << "the waits spread over the jitter";
}

}  // namespace
}  // namespace sanet
