#include "apps/case/read/read_fields.hpp"

#include "apps/common/format_number.hpp"

namespace flexmoor::app {

std::optional<double> requiredQuantity(CaseBuilder& b, Fields& f, const std::string& key,
                                       const QuantityKind& kind, Limit limit) {
  const YAML::Node* n = f.require(key);
  return n ? b.in.quantity(*n, f.path(key), kind, limit) : std::nullopt;
}

std::optional<double> optionalQuantity(CaseBuilder& b, const Fields& f, const std::string& key,
                                       const QuantityKind& kind, Limit limit, double fallback) {
  const YAML::Node* n = f.find(key);
  return n ? b.in.quantity(*n, f.path(key), kind, limit) : std::optional<double>(fallback);
}

std::optional<std::vector<std::pair<double, double>>> readIncreasingRows(CaseBuilder& b,
                                                                         const YAML::Node& n,
                                                                         const std::string& path,
                                                                         const Column& first,
                                                                         const Column& second) {
  const std::string pair = std::string("[") + first.name + ", " + second.name + "]";
  const std::vector<YAML::Node> rows = listItems(b.diag, n, path);
  if (rows.empty()) {
    b.diag.error(n,
                 path + ": no samples (got " + describeNode(n) + ", expected [" + pair + ", ...])");
    return std::nullopt;
  }
  std::vector<std::pair<double, double>> samples;
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string row = itemPath(path, i);
    if (!rows[i].IsSequence() || rows[i].size() != 2) {
      b.diag.error(rows[i], row + ": expected " + pair + ", " + first.kind.name + " and " +
                                second.kind.name + " (got " + describeNode(rows[i]) + ")");
      return std::nullopt;
    }
    const auto a = b.in.quantity(rows[i][0], childPath(row, first.name), first.kind);
    const auto v = b.in.quantity(rows[i][1], childPath(row, second.name), second.kind);
    if (!a || !v) return std::nullopt;
    if (!samples.empty() && !(*a > samples.back().first)) {
      b.diag.error(rows[i][0], childPath(row, first.name) + ": not increasing (got " +
                                   formatNumber(*a) + " after " +
                                   formatNumber(samples.back().first) + ", expected " + first.name +
                                   " increasing strictly from row to row)");
      return std::nullopt;
    }
    samples.emplace_back(*a, *v);
  }
  return samples;
}

}  // namespace flexmoor::app
