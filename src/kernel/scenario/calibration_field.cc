#include "scenario/calibration_field.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenario/yaml_reader.h"

namespace sanet::scenario {
namespace {

constexpr const char* kColumns[] = {"mean_dbm", "prr", "access_delay_s"};

// What every table must be, wherever it came from: `fail(row, column, message)` reports.
template <typename Fail>
void CheckTable(const net::LinkCalibration& c, Fail fail) {
  if (c.rows.size() < 2) fail(c.rows.size(), 0, "a calibration needs at least two rows");
  bool heard = false;
  for (std::size_t i = 0; i < c.rows.size(); ++i) {
    const auto& r = c.rows[i];
    if (!std::isfinite(r.mean_dbm)) fail(i, 0, "is not a number");
    if (!(r.prr >= 0 && r.prr <= 1)) fail(i, 1, "must be within [0, 1]");
    if (!(r.access_delay_s >= 0 && r.access_delay_s <= 60)) fail(i, 2, "must be within [0, 60] s");
    if (i > 0 && !(r.mean_dbm > c.rows[i - 1].mean_dbm)) fail(i, 0, "rows must be in ascending mean_dbm");
    heard = heard || r.prr > 0;
  }
  if (!heard) fail(c.rows.size() - 1, 1, "no row delivers anything (every prr is 0)");
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

double CellNumber(const std::string& cell, const std::string& file, int line, const char* column) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(cell, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != cell.size()) throw ScenarioError(file, line, column, "'" + cell + "' is not a number");
  return value;
}

std::string ReadWhole(const Field& f, const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) f.Fail("cannot read the calibration file " + path.string());
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

net::LinkCalibration InlineRows(const Field& rows) {
  net::LinkCalibration c;
  for (const Field& row : rows.Items()) {
    const std::vector<double> v = row.Numbers(3);
    c.rows.push_back({v[0], v[1], v[2]});
  }
  const std::vector<Field> items = rows.Items();
  CheckTable(c, [&](std::size_t i, int column, const std::string& message) {
    const Field& at = items.empty() ? rows : items[std::min(i, items.size() - 1)];
    at.Fail(std::string(kColumns[column]) + " " + message);
  });
  return c;
}

}  // namespace

net::LinkCalibration ParseCalibrationCsv(const std::string& text, const std::string& file) {
  std::stringstream in(text);
  std::vector<int> lines;  // the file's line of each row
  net::LinkCalibration c;
  bool header = false;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = SplitCsv(line);
    if (!header) {
      if (cells != std::vector<std::string>(std::begin(kColumns), std::end(kColumns)))
        throw ScenarioError(file, number, "header", "expected the columns mean_dbm,prr,access_delay_s");
      header = true;
      continue;
    }
    if (cells.size() != 3)
      throw ScenarioError(file, number, "row", "expected 3 values, found " + std::to_string(cells.size()));
    c.rows.push_back({CellNumber(cells[0], file, number, kColumns[0]), CellNumber(cells[1], file, number, kColumns[1]),
                      CellNumber(cells[2], file, number, kColumns[2])});
    lines.push_back(number);
  }
  if (!header) throw ScenarioError(file, number, "header", "no header line (mean_dbm,prr,access_delay_s)");
  CheckTable(c, [&](std::size_t i, int column, const std::string& message) {
    throw ScenarioError(file, lines.empty() ? number : lines[std::min(i, lines.size() - 1)], kColumns[column], message);
  });
  return c;
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
  if (n.radio_model != net::RadioModel::kAbstract) f.Fail("needs radio_model: abstract (the full model needs none)");
  if (f.IsScalar() && f.Text() == "measure") return;
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
    row.push_back(NumberNode(r.mean_dbm)), row.push_back(NumberNode(r.prr)),
        row.push_back(NumberNode(r.access_delay_s));
    rows.push_back(row);
  }
  out["rows"] = rows;
  return out;
}

}  // namespace sanet::scenario
