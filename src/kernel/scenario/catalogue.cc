#include "scenario/catalogue.h"

#include <cstdio>

#include "scenario/declarations.h"
#include "sensors/sensor_registry.h"

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
    out += Line("      %-28s %s\n", f.key, what);
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
    out += Line("      %-28s %s\n", r.key, what);
  }
  return out + note;
}

std::vector<FieldInfo> Table(const std::string& name) {
  for (const SectionTable& t : SectionTables())
    if (t.name == name) return t.fields;
  return {};
}

std::string Joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// Each model: what it is, what it carries, its drive limits, its body keys.
std::string ModelSection() {
  std::string out = "models (body keys with their defaults):\n";
  for (robots::ModelKind kind : robots::AllModels()) {
    const robots::ModelSpec model = robots::ModelSpec::Defaults(kind);
    out += Line("  %-10s %s\n", robots::ModelName(kind), robots::ModelOf(kind).Summary());
    out += Line("      %-28s %s\n", "carries",
                Joined(robots::DefaultSensorKinds(model)) + " (any other kind may be added)");
    if (robots::HasDrive(model))
      out += Line("      %-28s %s\n", "drive limits",
                  ShortNumber(model.max_speed) + " m/s, " + ShortNumber(model.max_turn_rate) + " rad/s");
    out += FieldLines(Table(std::string("body.") + robots::ModelName(kind)));
  }
  return out;
}

// Each sensor kind: what it measures, what Node::Sensor gives, its ROS 2 message, its keys.
std::string SensorSection() {
  std::string out =
      "sensors (keys under a node's `sensors`; more of a kind under another name with `kind: KIND`, whose topics\n"
      "take its name in place of the kind's; Python's node.sensor(name) gives the same reading, scans as numpy):\n";
  for (const sensors::SensorKind* kind : sensors::AllKinds()) {
    const sensors::SensorInfo& info = kind->Info();
    out += Line("  %-12s %s\n", info.name, info.summary);
    out += Line("      %-28s %s\n", "reading", info.reading + " (" + info.units + ")");
    out += Line("      %-28s %s\n", "ROS 2",
                info.ros2_type.empty() ? "none" : info.ros2_type + " on /<robot>/" + info.topic);
    out += FieldLines(Table("sensors." + info.name));
  }
  return out;
}

std::string ControllerSection(const hosting::Registry& registry) {
  std::string out = "controllers (parameters as each reads them):\n";
  for (const ControllerInfo* c : registry.List()) out += Line("  %-18s %s\n", c->name, c->description) + ParamLines(*c);
  return out;
}

}  // namespace

std::string Catalogue(const hosting::Registry& registry, CatalogueSections sections) {
  return (sections.models ? ModelSection() : "") + (sections.sensors ? SensorSection() : "") +
         (sections.controllers ? ControllerSection(registry) : "");
}

std::string ReferenceMarkdown() {
  std::string out;
  for (const SectionTable& t : SectionTables())
    out += "<!-- fields: " + t.name + " -->\n" + MarkdownTable(t.fields) + "<!-- /fields -->\n\n";
  return out;
}

}  // namespace sanet::scenario
