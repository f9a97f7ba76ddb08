// The grey zone's parts, each against its definition: shadowing is a Gaussian field with
// Gudmundson's exponential correlation, the same both ways and from the seed alone; fading is
// Nakagami's distribution as ns-3 draws it, the same whoever asks; the hardware spread is drawn
// per node; and the loss models give ns-3 channels exactly those values.
#include <gtest/gtest.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/double.h>
#include <ns3/node.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/rng-seed-manager.h>
#include <ns3/simulator.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "net/fading.h"
#include "net/hardware_spread.h"
#include "net/link_loss_models.h"
#include "net/shadowing.h"

namespace sanet::net {
namespace {

double Mean(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return sum / v.size();
}

double Deviation(const std::vector<double>& v) {
  const double mean = Mean(v);
  double sum = 0;
  for (double x : v) sum += (x - mean) * (x - mean);
  return std::sqrt(sum / (v.size() - 1));
}

double Correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double ma = Mean(a), mb = Mean(b);
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

// Kolmogorov-Smirnov distance between a sample and a distribution function.
template <typename Cdf>
double KsDistance(std::vector<double> sample, Cdf cdf) {
  std::sort(sample.begin(), sample.end());
  double worst = 0;
  const double n = sample.size();
  for (std::size_t i = 0; i < sample.size(); ++i)
    worst = std::max({worst, std::abs(cdf(sample[i]) - i / n), std::abs(cdf(sample[i]) - (i + 1) / n)});
  return worst;
}

double TwoSampleKs(std::vector<double> a, std::vector<double> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  double worst = 0;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    worst = std::max(worst, std::abs(double(i) / a.size() - double(j) / b.size()));
  }
  return worst;
}

double NormalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

Shadowing Sigma(double sigma_db, double correlation_m = 10) {
  Shadowing s;
  s.sigma_db = sigma_db;
  s.correlation_m = correlation_m;
  return s;
}

constexpr int kLinks = 4000;

TEST(Shadowing, IsGaussianWithItsSigmaAcrossLinksAndClipped) {
  const ShadowingField field(7, Sigma(6));
  std::vector<double> gains;
  for (std::uint32_t link = 0; link < kLinks; ++link)
    gains.push_back(field.GainDb(2 * link, 3, 4, 2 * link + 1, 20, -5));
  EXPECT_NEAR(Mean(gains), 0, 0.25);
  EXPECT_NEAR(Deviation(gains), 6, 0.25);
  EXPECT_LT(KsDistance(gains, [](double x) { return NormalCdf(x / 6); }), 0.025);
  for (double g : gains) EXPECT_LE(std::abs(g), 18 + 1e-9) << "clipped at 3 sigma";
  Shadowing tight = Sigma(6);
  tight.clip_sigmas = 1;
  const ShadowingField clipped(7, tight);
  int at_clip = 0;
  for (std::uint32_t link = 0; link < kLinks; ++link) {
    const double g = clipped.GainDb(2 * link, 3, 4, 2 * link + 1, 20, -5);
    EXPECT_LE(std::abs(g), 6 + 1e-9);
    at_clip += std::abs(g) == 6;
  }
  EXPECT_NEAR(at_clip / double(kLinks), 2 * (1 - NormalCdf(1)), 0.03) << "a third of a Gaussian lies beyond 1 sigma";
}

TEST(Shadowing, IsTheSameBothWaysUnlessAskedAndComesFromTheSeed) {
  const ShadowingField field(7, Sigma(6)), same(7, Sigma(6)), other_seed(8, Sigma(6));
  Shadowing apart = Sigma(6);
  apart.symmetric = false;
  const ShadowingField asymmetric(7, apart);
  std::vector<double> ours, theirs, forth, back;
  for (std::uint32_t link = 0; link < kLinks; ++link) {
    const double g = field.GainDb(link, 1, 2, link + 5000, 30, 40);
    EXPECT_EQ(g, field.GainDb(link + 5000, 30, 40, link, 1, 2)) << "symmetric";
    EXPECT_EQ(g, same.GainDb(link, 1, 2, link + 5000, 30, 40)) << "the same seed gives the same links";
    ours.push_back(g);
    theirs.push_back(other_seed.GainDb(link, 1, 2, link + 5000, 30, 40));
    forth.push_back(asymmetric.GainDb(link, 1, 2, link + 5000, 30, 40));
    back.push_back(asymmetric.GainDb(link + 5000, 30, 40, link, 1, 2));
  }
  EXPECT_LT(std::abs(Correlation(ours, theirs)), 0.06) << "another seed gives other links";
  EXPECT_LT(std::abs(Correlation(forth, back)), 0.06) << "symmetric: false draws each way apart";
  EXPECT_NEAR(Deviation(back), 6, 0.3);
}

// Gudmundson's model: moving one end by x keeps exp(-x / d) of the correlation; moving both
// multiplies their decays. Measured over many links, as the field is defined over its ensemble.
TEST(Shadowing, IsCorrelatedOverTheDecorrelationDistance) {
  const double d = 8;
  const ShadowingField field(3, Sigma(5, d));
  for (double moved : {0.1 * d, 0.5 * d, d, 2 * d}) {
    std::vector<double> before, after, both_before, both_after;
    for (std::uint32_t link = 0; link < kLinks; ++link) {
      before.push_back(field.GainDb(link, 0, 0, link + kLinks, 10, 0));
      after.push_back(field.GainDb(link, 0, 0, link + kLinks, 10 + moved * 0.6, moved * 0.8));
      both_after.push_back(field.GainDb(link, moved, 0, link + kLinks, 10, moved));
    }
    EXPECT_NEAR(Correlation(before, after), std::exp(-moved / d), 0.05) << "one end moved " << moved << " m";
    EXPECT_NEAR(Correlation(before, both_after), std::exp(-2 * moved / d), 0.05) << "both ends moved " << moved;
  }
}

// ns-3 nodes with mobility models, as the channel sees them. Tests that make them end with
// Simulator::Destroy, which empties ns-3's node list for the tests after them.
struct Placed {
  ns3::Ptr<ns3::Node> node = ns3::CreateObject<ns3::Node>();
  ns3::Ptr<ns3::ConstantPositionMobilityModel> at = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  explicit Placed(ns3::Vector p) {
    at->SetPosition(p);
    node->AggregateObject(at);
  }
};

// A robot drives past motes 5 m off its track, 0.1 m per frame: each link's strength, as the
// channel's loss model gives it, changes little from frame to frame and decorrelates over d.
TEST(Shadowing, ARobotPassingAMoteSeesALinkThatFadesAndReturns) {
  const double d = 5, step = 0.1;
  const ShadowingField field(11, Sigma(6, d));
  auto model = ns3::CreateObject<ShadowingLossModel>();
  model->SetField(field);
  Placed robot({-20, 0, 0});
  std::vector<Placed> motes;
  for (int i = 0; i < 400; ++i) motes.emplace_back(ns3::Vector(0, 5, 0));
  std::vector<std::vector<double>> strength(motes.size());
  for (int frame = 0; frame <= 400; ++frame) {
    robot.at->SetPosition({-20 + frame * step, 0, 0});
    for (std::size_t m = 0; m < motes.size(); ++m) {
      const double dbm = model->CalcRxPower(0, robot.at, motes[m].at);
      EXPECT_EQ(dbm, model->CalcRxPower(0, robot.at, motes[m].at)) << "the same place, the same strength";
      strength[m].push_back(dbm);
    }
  }
  for (int lag : {1, 10, 50, 100}) {
    std::vector<double> now, later;
    for (const auto& series : strength)
      for (std::size_t t = 0; t + lag < series.size(); t += 100)
        now.push_back(series[t]), later.push_back(series[t + lag]);
    EXPECT_NEAR(Correlation(now, later), std::exp(-lag * step / d), 0.07) << "frames apart: " << lag;
  }
  ns3::Simulator::Destroy();
}

TEST(Fading, NakagamiWithMOneIsRayleighInPower) {
  const NakagamiFading fading(5, Fading{FadingModel::kRayleigh, 1});
  std::vector<double> gains;
  for (int frame = 0; frame < 20000; ++frame) gains.push_back(fading.Draw(1, 2, frame * 1000));
  EXPECT_NEAR(Mean(gains), 1, 0.03);
  EXPECT_LT(KsDistance(gains, [](double g) { return 1 - std::exp(-g); }), 0.015) << "exponential power";
}

// The reference: ns-3's own NakagamiPropagationLossModel, with one m at every distance.
std::vector<double> Ns3NakagamiGains(double m, int n) {
  auto model = ns3::CreateObject<ns3::NakagamiPropagationLossModel>();
  for (const char* name : {"m0", "m1", "m2"}) model->SetAttribute(name, ns3::DoubleValue(m));
  model->AssignStreams(17);
  Placed a({0, 0, 0}), b({10, 0, 0});
  std::vector<double> gains;
  for (int i = 0; i < n; ++i) gains.push_back(std::pow(10, model->CalcRxPower(0, a.at, b.at) / 10));
  return gains;
}

TEST(Fading, DrawsAsNs3sNakagamiModel) {
  for (double m : {0.75, 1.0, 1.5, 3.0}) {
    const NakagamiFading fading(5, Fading{FadingModel::kNakagami, m});
    std::vector<double> ours;
    for (int frame = 0; frame < 20000; ++frame) ours.push_back(fading.Draw(3, 4, frame));
    EXPECT_LT(TwoSampleKs(ours, Ns3NakagamiGains(m, 20000)), 0.02) << "m = " << m;
  }
  ns3::Simulator::Destroy();
}

TEST(Fading, AFramesGainIsTheSameWhoeverAsksAndCappedAtItsQuantile) {
  const NakagamiFading fading(5, Fading{FadingModel::kNakagami, 1.5});
  std::vector<double> forwards, backwards;
  for (int frame = 0; frame < 100; ++frame) forwards.push_back(fading.GainDb(1, 2, frame));
  for (int frame = 99; frame >= 0; --frame) backwards.push_back(fading.GainDb(1, 2, frame));
  std::reverse(backwards.begin(), backwards.end());
  EXPECT_EQ(forwards, backwards);
  EXPECT_NE(fading.GainDb(1, 2, 0), fading.GainDb(2, 1, 0)) << "each way fades apart";
  EXPECT_NE(fading.GainDb(1, 2, 0), NakagamiFading(6, Fading{FadingModel::kNakagami, 1.5}).GainDb(1, 2, 0));
  int above = 0;
  const int n = 1000000;
  for (int frame = 0; frame < n; ++frame) {
    EXPECT_LE(fading.GainDb(7, 8, frame), fading.MaxGainDb());
    above += 10 * std::log10(fading.Draw(7, 8, frame)) > fading.MaxGainDb();
  }
  EXPECT_NEAR(above / double(n), NakagamiFading::kCapTail, 0.3 * NakagamiFading::kCapTail);
  EXPECT_NEAR(NakagamiFading(5, Fading{FadingModel::kRayleigh, 1}).MaxGainDb(), 10 * std::log10(std::log(1e4)), 1e-9)
      << "Rayleigh's power is exponential: its 1 - 1e-4 quantile is ln(1e4)";
}

TEST(HardwareSpread, GivesEachNodeItsOwnOffsetsFromTheSeed) {
  NetworkSpec spec;
  spec.seed = 9;
  spec.spread.tx_power_db = 2;
  spec.spread.noise_figure_db = 1;
  std::vector<double> tx, noise;
  for (std::uint32_t node = 0; node < kLinks; ++node) {
    tx.push_back(TxPowerOffsetDb(spec, node));
    noise.push_back(NoiseFigureOffsetDb(spec, node));
    EXPECT_LE(std::abs(tx.back()), 6 + 1e-9);
    EXPECT_LE(std::abs(noise.back()), 3 + 1e-9);
  }
  EXPECT_NEAR(Deviation(tx), 2, 0.1);
  EXPECT_NEAR(Deviation(noise), 1, 0.05);
  EXPECT_LT(std::abs(Correlation(tx, noise)), 0.06);
  NetworkSpec again = spec;
  EXPECT_EQ(TxPowerOffsetDb(again, 17), tx[17]);
  again.seed = 10;
  EXPECT_NE(TxPowerOffsetDb(again, 17), tx[17]);
  EXPECT_EQ(TxPowerOffsetDb(NetworkSpec{}, 17), 0) << "no spread, no offset";
}

}  // namespace
}  // namespace sanet::net
