#pragma once
// Reads a YAML case file into a validated Case. Every problem of the file is collected and
// reported at once, as `FILE:LINE: what is wrong (got X, expected Y)`, in one CaseError.
// The case format, every key with its default: README.md, section "Case files".
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/case/input/diagnostics.hpp"
#include "apps/case/input/node_table.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {

// Reads and validates a case file; throws CaseError listing every problem.
Case readCase(const std::string& path);

// A case file's document as read (yaml_load.hpp), its node marks kept, for a reader that sets
// values in it before the case is built (a study's members). `path` names the file in messages
// and is where the case's relative file names start.
struct CaseDocument {
  std::string path;
  YAML::Node root;
  std::optional<NodeTable> node_table;  // the nodes: read by node_table.hpp's fast path
};

// Throws CaseError when the file cannot be read as YAML.
CaseDocument loadCase(const std::string& path);
// The same of a case's text, which `name` stands for in messages (relative file names start in
// the working directory).
CaseDocument loadCaseFromText(const std::string& text, const std::string& name);

// Series quantities read against the case being built but reported in another file, to its
// Diagnostics (with `prefix` before each message): a study's collect: entries
// (readSeriesQuantity of case_builder.hpp). Each entry: its map, its path in that file
// ("collect[1]"), its name, and the keys the caller reads itself.
struct ForeignSeries {
  struct Entry {
    YAML::Node map;
    std::string path, name;
    std::vector<std::string> other_keys;
  };
  Diagnostics* diag = nullptr;
  std::string prefix;
  std::vector<Entry> entries;
  std::vector<std::optional<SummarySpec>> specs;  // filled: one per entry, nullopt when wrong
};

// Builds and validates the case of a loaded document, as readCase does the file's; reads
// `series` (when not null) against it. Throws CaseError for the case's own problems only.
Case readCase(const CaseDocument& document, ForeignSeries* series = nullptr);

// An existing file as it is, or with `.yaml` added; else the case `<name>.yaml` anywhere under
// the cases folder (casesDir of apps/common/data_dir.hpp; `name` with or without `.yaml`).
// Throws std::runtime_error when there is none, with the nearest names ("no case
// 'oc4-semi-surg'; did you mean 'oc4-semi-surge'?"; for a path, the nearest .yaml files next to
// it; every available name when none is near), when there are several, or when the cases folder
// is not found.
std::string resolveCasePath(const std::string& name_or_path);

// (name, title) of every .yaml under the cases folder (apps/common/data_dir.hpp), sorted by
// name; the name is the file's stem, the title its `title:` key. Throws std::runtime_error when
// the folder is not found.
std::vector<std::pair<std::string, std::string>> listCases();

}  // namespace flexmoor::app
