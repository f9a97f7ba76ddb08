#include "map_command.h"

#include <cstdio>
#include <memory>
#include <optional>

#include "run_common.h"
#include "scenario/world_raster.h"

namespace sanet::cli {
namespace {

struct MapArgs {
  std::string file, output, name;
  std::optional<double> resolution;
  std::vector<std::string> sets;
  bool quiet = false;
};

int WriteMap(const MapArgs& a, hosting::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(a.file, a.sets, registry);
  // The world's map's cells by default: its walls come back as they were.
  const double resolution = a.resolution ? *a.resolution : sc.run.map ? sc.run.map->resolution : 0.05;
  scenario::OccupancyMap map;
  try {
    map = scenario::RasterizeWorld(sc.run, resolution);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--resolution", e.what());
  }
  const std::string name = a.name.empty() ? sc.run.name : a.name;
  try {
    scenario::WriteRosMap(map, a.output, name);
  } catch (const std::exception& e) {
    throw CLI::ValidationError("-o", e.what());
  }
  if (!a.quiet) {
    std::size_t occupied = 0;
    for (const std::int8_t c : map.cells) occupied += c == scenario::OccupancyMap::kOccupied;
    std::printf("sanet map: %s: %d x %d cells of %g m from (%g, %g), %zu occupied; %s/%s.yaml and %s.pgm\n",
                sc.run.name.c_str(), map.width, map.height, map.resolution, map.origin[0], map.origin[1], occupied,
                a.output.c_str(), name.c_str(), name.c_str());
  }
  return 0;
}

}  // namespace

Command AddMap(CLI::App& app) {
  auto a = std::make_shared<MapArgs>();
  CLI::App* cmd = app.add_subcommand(
      "map",
      "Write the scenario's world as a ROS map: map_server's YAML and a PGM image (occupied 0, free 254), the "
      "obstacles' footprints seen from above, for Nav2's map server and AMCL (docs/ros2.md)");
  cmd->add_option("file", a->file, "The scenario")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->output, "The folder to write NAME.yaml and NAME.pgm into")->required();
  cmd->add_option("--resolution", a->resolution, "Metres per cell")->default_val(0.05)->check(CLI::Range(0.001, 100.0));
  cmd->add_option("--name", a->name, "The files' name (default: the scenario's name)");
  AddSet(cmd, a->sets);
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing but errors");
  return {cmd, [a](hosting::Registry& registry) { return WriteMap(*a, registry); }};
}

}  // namespace sanet::cli
