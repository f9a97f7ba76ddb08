// What sanet knows, described from the declarations (scenario/declarations.h) and from the
// controllers themselves: the text of `sanet list`, and the reference tables of the scenario
// format in markdown (`sanet list --markdown`, compared with docs/scenario.md by a test).
#pragma once

#include <string>

#include "hosting/controller_registry.h"

namespace sanet::scenario {

// Which sections `sanet list` prints (all by default; --models, --sensors, --controllers pick).
struct CatalogueSections {
  bool models = true, sensors = true, controllers = true;
};
std::string Catalogue(const hosting::Registry& registry, CatalogueSections sections = {});
// Each table between `<!-- fields: NAME -->` and `<!-- /fields -->` lines, as in docs/scenario.md.
std::string ReferenceMarkdown();

}  // namespace sanet::scenario
