#include "scenario/calibration_field.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenario/yaml_reader.h"

namespace sanet::scenario {
namespace {

constexpr const char* kColumns[] = {"mean_dbm", "prr", "access_delay_s", "unicast_prr"};

std::string ReadWhole(const Field& f, const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) f.Fail("cannot read the calibration file " + path.string());
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Rows of three numbers (unicasts take the broadcasts' PRR) or four.
net::LinkCalibration InlineRows(const Field& rows) {
  net::LinkCalibration c;
  const std::vector<Field> items = rows.Items();
  for (const Field& row : items) {
    const std::vector<double> v = row.IsSequence() && row.node().size() == 4 ? row.Numbers(4) : row.Numbers(3);
    c.rows.push_back({v[0], v[1], v[2], v.size() == 4 ? v[3] : v[1]});
  }
  net::CheckCalibration(c, [&](std::size_t i, int column, const std::string& message) {
    const Field& at = items.empty() ? rows : items[std::min(i, items.size() - 1)];
    at.Fail(std::string(kColumns[column]) + " " + message);
  });
  return c;
}

}  // namespace

net::LinkCalibration ParseCalibrationCsv(const std::string& text, const std::string& file) {
  try {
    return net::ParseLinkCalibrationCsv(text);
  } catch (const net::CalibrationCsvError& e) {
    throw ScenarioError(file, e.line(), e.column(), e.what());
  }
}

FieldInfo CalibrationEntry() {
  return {"calibration",
          "text or map",
          "",
          "`measure`",
          "`measure`, a CSV file, `{file, rows}`",
          "with `radio_model: abstract`: the table it draws from; `measure`: the full 802.11 model's link curve on "
          "this radio, measured at the first run and cached; a file: a CSV of `mean_dbm,prr,access_delay_s` rows "
          "(as `sanet link-curve` writes `calibration.csv`), printed with its rows (see "
          "[swarms.md](swarms.md#the-calibration))"};
}

void ReadCalibration(const Field& f, net::NetworkSpec& n) {
  if (f.IsScalar() && f.Text() == "measure") return;  // also under the full model: a printed scenario switched back
  if (n.radio_model != net::RadioModel::kAbstract) f.Fail("needs radio_model: abstract (the full model needs none)");
  if (f.IsScalar()) {
    n.calibration_file = f.Text();
    std::filesystem::path path(n.calibration_file);
    if (path.is_relative()) path = std::filesystem::path(f.file()).parent_path() / path;
    n.calibration = ParseCalibrationCsv(ReadWhole(f, path), path.string());
    return;
  }
  f.ExpectKeys({"file", "rows"});
  if (auto file = f.Get("file")) n.calibration_file = file->Text();
  n.calibration = InlineRows(f.Require("rows"));
}

YAML::Node PrintCalibration(const net::NetworkSpec& n) {
  if (n.radio_model != net::RadioModel::kAbstract) return YAML::Node();
  if (!n.calibration) return YAML::Node("measure");
  YAML::Node out(YAML::NodeType::Map);
  if (!n.calibration_file.empty()) out["file"] = n.calibration_file;
  YAML::Node rows(YAML::NodeType::Sequence);
  for (const auto& r : n.calibration->rows) {
    YAML::Node row(YAML::NodeType::Sequence);
    row.SetStyle(YAML::EmitterStyle::Flow);
    for (double v : {r.mean_dbm, r.prr, r.access_delay_s, r.unicast_prr}) row.push_back(NumberNode(v));
    rows.push_back(row);
  }
  out["rows"] = rows;
  return out;
}

}  // namespace sanet::scenario
