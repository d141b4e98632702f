#pragma once
// The names nearest a mistyped one, for "did you mean ...?" (a case name on the command line).
#include <string>
#include <vector>

namespace flexmoor::app {

// Levenshtein distance: the fewest insertions, deletions and substitutions of characters that
// turn `a` into `b`.
int editDistance(const std::string& a, const std::string& b);

// The candidates nearest `name`: those at the smallest edit distance when it is at most a third
// of the name's length (and at least 2 are allowed), else those that contain `name` (a part of a
// name, like "ex8"), else none. In the candidates' order, at most `limit`.
std::vector<std::string> nearestNames(const std::string& name,
                                      const std::vector<std::string>& candidates, size_t limit = 4);

// "; did you mean 'a'?" or "; did you mean 'a' or 'b'?" of `names`; "" for none.
std::string didYouMean(const std::vector<std::string>& names);

}  // namespace flexmoor::app
