#include "scenario/overrides.h"

#include <sstream>

#include "core/closest_names.h"

namespace sanet::scenario {
namespace {

[[noreturn]] void Refuse(const Override& o, const std::string& field, const std::string& message) {
  throw ScenarioError("--set " + o.text, 0, field, message);
}

// Errors name a list's item as the file's readers print it, `nodes[0].pose`; a path may name it
// so too: `[K]` is `.K`.
std::string DotsForBrackets(const std::string& path) {
  std::string dotted;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '[')
      dotted += '.';
    else if (path[i] != ']' || (i + 1 < path.size() && path[i + 1] != '.' && path[i + 1] != '['))
      dotted += path[i];  // a ']' inside a key stays, and the key then names nothing
  }
  return dotted;
}

std::vector<std::string> Split(const std::string& bracketed) {
  const std::string path = DotsForBrackets(bracketed);
  std::vector<std::string> parts;
  std::stringstream s(path);
  for (std::string part; std::getline(s, part, '.');) parts.push_back(part);
  if (!path.empty() && path.back() == '.') parts.push_back("");
  return parts;
}

bool IsIndex(const std::string& s) {
  return !s.empty() && s.size() < 9 && s.find_first_not_of("0123456789") == std::string::npos;
}

// The name an item of a list goes by: its `name`, or its grid's or scatter's.
std::string ItemName(const YAML::Node& item) {
  if (!item.IsMap()) return "";
  if (item["name"] && item["name"].IsScalar()) return item["name"].Scalar();
  for (const char* group : {"grid", "scatter"}) {
    const YAML::Node named = item[group];
    if (named && named.IsMap() && named["name"] && named["name"].IsScalar()) return named["name"].Scalar();
  }
  return "";
}

// The item of `list` that `key` names (by name, grid name or index), or -1.
long FindItem(const YAML::Node& list, const std::string& key) {
  for (std::size_t i = 0; i < list.size(); ++i)
    if (ItemName(list[i]) == key) return static_cast<long>(i);
  if (IsIndex(key) && std::stoul(key) < list.size()) return static_cast<long>(std::stoul(key));
  return -1;
}

std::string Names(const YAML::Node& list) {
  std::string names;
  for (std::size_t i = 0; i < list.size() && i < 12; ++i) {
    const std::string name = ItemName(list[i]);
    names += (names.empty() ? "" : ", ") + (name.empty() ? std::to_string(i) : name);
  }
  return list.size() > 12 ? names + ", ..." : names;
}

// Why `key` names no item of `list`: the names closest to it first (the list shows only the
// first twelve, and the one meant may come later), then the list.
std::string NoItemNamed(const YAML::Node& list, const std::string& key) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) names.push_back(ItemName(list[i]));
  const std::vector<std::string> close = ClosestNames(key, names);
  return "has no item named '" + key + "'" + (close.empty() ? "" : ": did you mean " + OrList(close) + "?") +
         " (items: " + Names(list) + ")";
}

YAML::Node ParseValue(const Override& o) {
  try {
    return YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    Refuse(o, o.path, "the value is not valid YAML: " + e.msg);
  }
}

void Apply(YAML::Node node, Override& o) {
  const std::vector<std::string> keys = Split(o.path);
  std::string field, created;  // created: the first mapping made on the way, which errors then concern
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string& key = keys[i];
    if (key.empty()) Refuse(o, field, "the path has an empty key (two dots, or a dot at an end)");
    const bool last = i + 1 == keys.size();
    if (node.IsSequence()) {
      const long index = FindItem(node, key);
      if (index < 0 && IsIndex(key))
        Refuse(o, field,
               node.size() == 0 ? "has no items"
                                : "has " + std::to_string(node.size()) + " items, 0 to " +
                                      std::to_string(node.size() - 1) + ": no item " + key);
      if (index < 0) Refuse(o, field, NoItemNamed(node, key));
      field += "[" + std::to_string(index) + "]";
      if (last) {
        node[static_cast<std::size_t>(index)] = ParseValue(o);
      } else {
        node.reset(node[static_cast<std::size_t>(index)]);
      }
      continue;
    }
    if (node.IsScalar()) Refuse(o, field, "is a value, not a mapping: no key '" + key + "' in it");
    field += (field.empty() ? "" : ".") + key;
    if (last) {
      node[key] = ParseValue(o);
    } else {
      if (!node[key] || node[key].IsNull()) {
        if (IsIndex(keys[i + 1]))
          Refuse(o, field,
                 "is not in the scenario: --set changes the items of a list that is there (or give the "
                 "whole list: --set " +
                     field + "=[...])");
        node[key] = YAML::Node(YAML::NodeType::Map);
        if (created.empty()) created = field;
      }
      node.reset(node[key]);
    }
  }
  o.field = created.empty() ? field : created;
}

bool Under(const std::string& field, const std::string& prefix) {
  if (field.compare(0, prefix.size(), prefix) != 0) return false;
  return field.size() == prefix.size() || field[prefix.size()] == '.' || field[prefix.size()] == '[';
}

}  // namespace

Override ParseOverride(const std::string& text) {
  Override o;
  o.text = text;
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw ScenarioError("--set " + text, 0, "", "expected PATH=VALUE, e.g. --set network.tx_power=25");
  o.path = text.substr(0, equals);
  o.value = text.substr(equals + 1);
  return o;
}

void ApplyOverrides(YAML::Node root, std::vector<Override>& overrides) {
  for (Override& o : overrides) Apply(root, o);
}

ScenarioError Attributed(const ScenarioError& error, const std::vector<Override>& overrides) {
  // The last one wins where two set the same field, as it did when they were applied.
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o)
    if (!o->field.empty() && Under(error.field(), o->field))
      return ScenarioError("--set " + o->text, 0, error.field(), error.message());
  return error;
}

}  // namespace sanet::scenario
