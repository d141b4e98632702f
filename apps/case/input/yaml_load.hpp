#pragma once
// Loads the YAML document of a case file so that no text can crash or hang the reader, and says
// plainly what yaml-cpp lets through or words poorly:
//   - a quoted string that is never closed (yaml-cpp reads it to the end of the file);
//   - lists and maps nested deeper than kMaxNesting levels (yaml-cpp's parser recurses and gives
//     up at 500 as "bad file");
//   - aliases that expand to more values than aliasBudget (a "billion laughs" file: an alias is
//     the anchored node itself, so a reader walking the document visits it once per use).
// Each is reported with its line to the Diagnostics, which then throw; nothing else is read.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>

#include "apps/case/input/diagnostics.hpp"
#include "apps/case/input/node_table.hpp"

namespace flexmoor::app {

// Levels of nested lists and maps, the document's top map included; a case needs about six.
constexpr int kMaxNesting = 256;

// The most values (scalars, lists and maps, each use of an alias counted in full) that a file of
// `bytes` characters may expand to: a million, for reasonable reuse of anchors, plus two per
// character (a file without aliases holds at most about one value per character).
size_t aliasBudget(size_t bytes);

// The document of diag.file(); throws CaseError (after reporting to diag) when it cannot be read.
// A plain node table is read by the fast path of node_table.hpp into `node_table` and left out
// of the document; otherwise `node_table` is empty and `nodes:` is in the document.
YAML::Node loadCaseDocument(Diagnostics& diag, std::optional<NodeTable>& node_table);
// The same of a case's text (diag.file() names it in messages).
YAML::Node loadCaseText(Diagnostics& diag, const std::string& text,
                        std::optional<NodeTable>& node_table);

}  // namespace flexmoor::app
