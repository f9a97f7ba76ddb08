#include "scenario/catalogue.h"

#include <cstdio>

#include "scenario/declarations.h"

namespace sanet::scenario {
namespace {

std::string Line(const char* format, const std::string& a, const std::string& b) {
  char text[1024];
  std::snprintf(text, sizeof text, format, a.c_str(), b.c_str());
  return text;
}

std::string Unquoted(std::string text) {
  std::string out;
  for (char c : text)
    if (c != '`') out += c;
  return out;
}

std::string FieldLines(const std::vector<FieldInfo>& fields) {
  std::string out;
  for (const FieldInfo& f : fields) {
    std::string what = f.type + (f.unit.empty() ? "" : " (" + f.unit + ")") + ", default " + Unquoted(f.default_text);
    if (!f.range.empty()) what += ", " + Unquoted(f.range);
    out += Line("      %-20s %s\n", f.key, what);
  }
  return out;
}

// A controller's parameters, as it reads them when created with none.
std::string ParamLines(const ControllerInfo& info) {
  Params none;
  std::string note;
  try {
    info.create(none);
  } catch (const std::exception& e) {
    note = Line("      (with no parameters: %s%s)\n", e.what(), "");
  }
  std::string out;
  for (const ParamRead& r : none.Reads()) {
    std::string what = r.kind == "required" ? r.kind : r.kind + ", default " + r.fallback;
    if (r.min > -HUGE_VAL && r.max < HUGE_VAL)
      what += ", in [" + ShortNumber(r.min) + ", " + ShortNumber(r.max) + "]";
    else if (r.min > -HUGE_VAL)
      what += ", at least " + ShortNumber(r.min);
    else if (r.max < HUGE_VAL)
      what += ", at most " + ShortNumber(r.max);
    out += Line("      %-20s %s\n", r.key, what);
  }
  return out + note;
}

const std::vector<std::pair<std::string, std::string>> kSensors = {{"ir", "sensors.ir"},
                                                                   {"laser", "sensors.laser"},
                                                                   {"odometry", "sensors.odometry"},
                                                                   {"ground_truth", "sensors.ground_truth"},
                                                                   {"bearing", "sensors.bearing"}};

}  // namespace

std::string Catalogue(const agents::Registry& registry) {
  const std::vector<SectionTable> tables = SectionTables();
  const auto table = [&](const std::string& name) {
    for (const SectionTable& t : tables)
      if (t.name == name) return t.fields;
    return std::vector<FieldInfo>{};
  };
  std::string out = "models (body keys with their defaults):\n";
  for (robots::ModelKind kind : robots::kAllModels) {
    out += Line("  %-10s %s\n", robots::ModelName(kind), robots::ModelSummary(kind));
    out += FieldLines(table(std::string("body.") + robots::ModelName(kind)));
  }
  out += "sensors (keys under a node's `sensors`):\n";
  for (const auto& [name, section] : kSensors) out += Line("  %s\n%s", name, FieldLines(table(section)));
  out += "controllers (parameters as each reads them):\n";
  for (const ControllerInfo* c : registry.List()) out += Line("  %-18s %s\n", c->name, c->description) + ParamLines(*c);
  return out;
}

std::string ReferenceMarkdown() {
  std::string out;
  for (const SectionTable& t : SectionTables())
    out += "<!-- fields: " + t.name + " -->\n" + MarkdownTable(t.fields) + "<!-- /fields -->\n\n";
  return out;
}

}  // namespace sanet::scenario
