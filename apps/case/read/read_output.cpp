// output: of a case file: what the records of the run's netCDF file hold
// (apps/problem/output_fields.hpp).
//   output:
//     fields: [position, tension]     # default: every field
#include <algorithm>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

void readOutput(CaseBuilder& b, const YAML::Node& n) {
  if (n.IsNull()) return;
  Fields f(b.diag, n, "output", {"fields"});
  const YAML::Node* list = f.require("fields");
  if (!list) return;
  OutputFields fields = OutputFields::none();
  const std::vector<YAML::Node> items = listItems(b.diag, *list, f.path("fields"));
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string path = itemPath(f.path("fields"), i);
    const auto name = b.in.text(items[i], path);
    if (!name) continue;
    const auto& names = OutputFields::kNames;
    const auto known = std::find_if(names.begin(), names.end(),
                                    [&](const auto& entry) { return entry.first == *name; });
    if (known == names.end()) {
      b.diag.error(items[i], path + ": not a field of the results (got '" + *name +
                                 "', expected one of " + OutputFields::list() + ")");
      continue;
    }
    if (fields.has(known->second))
      b.diag.error(items[i], path + ": '" + *name + "' is listed twice");
    fields.add(known->second);
  }
  b.c.output = fields;
}

}  // namespace flexmoor::app
