// histories: named time functions (sine, ramp, table) that drive loads and supports.
#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

void readHistories(CaseBuilder& b, const YAML::Node& n) {
  if (n && n.size() > 0) b.diag.error(n, "histories: not read yet (expected no histories)");
}

std::shared_ptr<const model::TimeFunction> historyRef(CaseBuilder& b, const YAML::Node& n,
                                                      const std::string& path) {
  b.diag.error(n, path + ": histories are not read yet");
  return nullptr;
}

}  // namespace flexmoor::app
