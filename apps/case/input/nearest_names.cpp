#include "apps/case/input/nearest_names.hpp"

#include <algorithm>
#include <climits>

namespace flexmoor::app {

int editDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];  // the distance of a[0, i - 1) and b[0, j - 1)
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string> nearestNames(const std::string& name,
                                      const std::vector<std::string>& candidates, size_t limit) {
  std::vector<std::string> nearest;
  int best = INT_MAX;
  for (const std::string& c : candidates) best = std::min(best, editDistance(name, c));
  const int allowed = std::max(2, static_cast<int>(name.size()) / 3);
  for (const std::string& c : candidates) {
    if (nearest.size() == limit) break;
    if (best <= allowed ? editDistance(name, c) == best
                        : !name.empty() && c.find(name) != std::string::npos)
      nearest.push_back(c);
  }
  return nearest;
}

std::string didYouMean(const std::vector<std::string>& names) {
  if (names.empty()) return "";
  std::string text = "; did you mean ";
  for (size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + ("'" + names[k] + "'");
  return text + "?";
}

}  // namespace flexmoor::app
