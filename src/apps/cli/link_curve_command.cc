#include "link_curve_command.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "interruption.h"
#include "run_common.h"
#include "sim/link_curve.h"
#include "sim/radio_calibration.h"

namespace sanet::cli {
namespace {

struct LinkCurveArgs {
  std::string file, output;
  std::vector<std::string> sets;
  std::optional<std::uint64_t> seed;
  std::vector<double> along;
  sim::LinkCurveOptions options;
  bool force = false, quiet = false;
};

std::string Metres(double m) {
  char text[40];
  std::snprintf(text, sizeof text, "%g m", m);
  return text;
}

// The folder is new, empty, or an earlier link curve's (replaced only with --force).
void ClaimCurveFolder(const std::string& dir, bool force) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::exists(dir, error) || fs::is_empty(dir, error)) return;
  if (!fs::exists(fs::path(dir) / "link_curve.json"))
    throw CLI::ValidationError("--output", dir + " holds other files than a link curve's: give another folder");
  if (!force)
    throw CLI::ValidationError("--output",
                               dir + " holds an earlier link curve: --force replaces it, or give another folder");
}

// A table interpolates between its rows: where all frames arrive at one distance and none at the
// next, it would make a grey zone of that step which the radio does not have.
void PrintSteepFall(const sim::LinkCurve& curve) {
  for (std::size_t i = 0; i + 1 < curve.rows.size(); ++i) {
    const sim::LinkCurveRow &near = curve.rows[i], &far = curve.rows[i + 1];
    if (near.Prr() < 0.99 || far.Prr() > 0) continue;
    std::printf(
        "  note: the PRR falls from %.2f to 0 between %g and %g m, one step: as a calibration the table would "
        "ramp between them. Measure the fall in finer steps (--from %g --to %g --step %g), as `calibration: "
        "measure` does\n",
        near.Prr(), near.distance, far.distance, near.distance, far.distance, (far.distance - near.distance) / 40);
    return;
  }
}

void PrintCurve(const sim::LinkCurve& curve, const std::string& dir, const std::string& no_calibration) {
  std::printf("  %-10s %-9s %-6s %-8s %-8s\n", "distance", "mean dBm", "PRR", ">=0.9", ">0.1");
  for (const sim::LinkCurveRow& r : curve.rows)
    std::printf("  %7.1f m %9.1f %6.3f %8.2f %8.2f\n", r.distance, r.mean_dbm, r.Prr(), r.share_90, r.share_10);
  auto bound = [](const std::optional<double>& v) {
    return v ? std::to_string(*v).substr(0, std::to_string(*v).find('.') + 2) + " m" : std::string("-");
  };
  std::printf("  connected up to %s, disconnected from %s (95 %% of links)", bound(curve.connected_to).c_str(),
              bound(curve.disconnected_from).c_str());
  if (curve.p50_dbm) std::printf("; half the frames arrive at a mean of %.1f dBm", *curve.p50_dbm);
  std::printf("\n");
  if (no_calibration.empty()) {
    std::printf("  calibration.csv: this curve as the abstract radio's network.calibration\n");
    PrintSteepFall(curve);
  } else {
    std::printf("  no calibration.csv: %s\n", no_calibration.c_str());
  }
  std::printf("  results in %s/\n", dir.c_str());
}

// The abstract radio is measured with the table it draws from (its own, the cached or a new one).
void Calibrate(net::NetworkSpec& network, const sim::RunSpec& spec, bool quiet) {
  if (network.radio_model != net::RadioModel::kAbstract) return;
  if (!quiet) std::printf("sanet: the abstract radio's calibration: %s\n", sim::DescribeCalibration(network).c_str());
  const sim::Calibration c = sim::CalibrationFor(spec);
  network.calibration = c.table, network.calibration_source = c.source;
}

int Measure(LinkCurveArgs& a, hosting::Registry& registry) {
  std::vector<std::string> sets = a.sets;
  if (a.seed) sets.push_back("seed=" + std::to_string(*a.seed));  // as the scenario's own: scattered nodes follow it
  scenario::Scenario sc = LoadChecked(a.file, sets, registry);
  if (!sc.run.network)
    throw CLI::ValidationError(a.file + ": the scenario has no `network`: there is no radio to measure");
  if (!a.along.empty()) {
    if (a.along.size() != 4)
      throw CLI::ValidationError("--along", "wants X0,Y0,X1,Y1: a line from one point towards another");
    if (a.along[0] == a.along[2] && a.along[1] == a.along[3])
      throw CLI::ValidationError("--along", "its two points are the same: no direction to lay the line in");
    a.options.along = {a.along[0], a.along[1], a.along[2], a.along[3]};
  }
  Calibrate(*sc.run.network, sc.run, a.quiet);
  const bool from_given = a.options.from > 0;
  sim::DefaultDistances(*sc.run.network, a.options);
  if (a.options.from > a.options.to)
    throw CLI::ValidationError(from_given ? "--from" : "--to", "the distances run from " + Metres(a.options.from) +
                                                                   (from_given ? "" : " (one step, the default)") +
                                                                   " to " + Metres(a.options.to) +
                                                                   ": the first is beyond the last");
  if (sim::DistanceCount(a.options) > sim::kMostDistances)
    throw CLI::ValidationError("--step", "asks for more than " + std::to_string(sim::kMostDistances) +
                                             " distances from " + Metres(a.options.from) + " to " +
                                             Metres(a.options.to) + ": take a longer step");
  const std::string dir = a.output.empty() ? "results/" + sc.run.name + "-link-curve" : a.output;
  ClaimCurveFolder(dir, a.force);
  if (!a.quiet)
    std::printf("sanet: link curve of %s: %d links per distance, %.4g to %.4g m every %.4g m, %d frames each%s\n",
                sc.run.name.c_str(), a.options.sets, a.options.from, a.options.to, a.options.step, a.options.frames,
                a.options.along ? ", through the scenario's walls" : "");
  InstallStopHandlers();
  const bool show = !a.quiet && isatty(STDERR_FILENO);
  const sim::LinkCurve curve = sim::MeasureLinkCurve(
      sc.run, a.options,
      [show](int done, int total) {
        if (show) std::fprintf(stderr, "\r  %d of %d links per distance measured", done, total);
      },
      [] { return !InterruptReason().empty(); });
  if (show) std::fprintf(stderr, "\r\033[K");
  sim::WriteLinkCurve(curve, sc.run, a.options, dir);
  if (curve.interrupted) {
    std::fprintf(stderr,
                 "sanet: %s after %d of %d links per distance; what was measured is in %s/ (status: interrupted)\n",
                 InterruptReason().c_str(), curve.sets_done, a.options.sets, dir.c_str());
    return 128 + InterruptSignal();
  }
  if (!a.quiet) PrintCurve(curve, dir, sim::WhyNoCalibration(sc.run, a.options));
  return 0;
}

}  // namespace

Command AddLinkCurve(CLI::App& app) {
  auto a = std::make_shared<LinkCurveArgs>();
  CLI::App* cmd = app.add_subcommand(
      "link-curve",
      "Measure the scenario's radio against distance: senders broadcast frames to receivers on a line, many "
      "independent links per distance; writes link_curve.csv, link_curve_links.csv, link_curve.svg and "
      "link_curve.json with the connected, transitional and disconnected regions (docs/network.md#link-curves)");
  AddScenario(cmd, a->file);
  AddSet(cmd, a->sets);
  cmd->add_option("--seed", a->seed, "Seed instead of the scenario's (each link draws its own from it)")
      ->check(kSeedText);
  cmd->add_option("--from", a->options.from, "First distance (m); default: one step")->check(CLI::Range(1e-3, 1e7));
  cmd->add_option("--to", a->options.to,
                  "Last distance (m); default: where a link 2.5 sigma above the mean shadowing and spread, in a "
                  "frame faded less than 99 % of frames, still arrives 3 dB under rx_threshold")
      ->check(CLI::Range(1e-3, 1e7));
  cmd->add_option("--step", a->options.step, "Between distances (m); default: about 40 distances")
      ->check(CLI::Range(1e-3, 1e7));
  cmd->add_option("--links", a->options.sets, "Independent links per distance")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--frames", a->options.frames, "Frames each sender broadcasts")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--interval", a->options.interval, "Seconds between a sender's frames")
      ->capture_default_str()
      ->check(CLI::Range(1e-4, 60.0));
  cmd->add_option("--size", a->options.size, "Bytes of each message")
      ->capture_default_str()
      ->check(CLI::Range(0, 1400));
  cmd->add_option("--along", a->along,
                  "X0,Y0,X1,Y1: the lines start at (X0, Y0) in the scenario's world and run towards (X1, Y1), "
                  "through its walls (default: free space)")
      ->delimiter(',')
      ->expected(4);
  cmd->add_option("-o,--output", a->output, "Folder for the results (default: results/<name>-link-curve)");
  cmd->add_flag("--force", a->force,
                "Replace an earlier link curve in the folder (a folder holding other files is refused)");
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing but errors");
  return {cmd, [a](hosting::Registry& registry) { return Measure(*a, registry); }};
}

}  // namespace sanet::cli
