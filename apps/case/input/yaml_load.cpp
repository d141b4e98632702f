#include "apps/case/input/yaml_load.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "apps/case/input/node_table.hpp"

namespace flexmoor::app {
namespace {

const std::string kTooDeep = "lists and maps nested deeper than " + std::to_string(kMaxNesting) +
                             " levels (expected the few levels of a case file)";

// The file's text without a UTF-8 byte-order mark, so that yaml-cpp's positions index it.
std::optional<std::string> readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  return text;
}

// Whether the quoted string whose opening quote is text[open] is closed before the text ends
// ('' is a quote inside '...', \" one inside "...").
bool quoteCloses(const std::string& text, size_t open) {
  const char quote = text[open];
  for (size_t i = open + 1; i < text.size(); ++i) {
    if (quote == '"' && text[i] == '\\') {
      ++i;
    } else if (text[i] == quote) {
      if (quote == '\'' && i + 1 < text.size() && text[i + 1] == '\'')
        ++i;
      else
        return true;
    }
  }
  return false;
}

// The quoted scalar that starts last, of those noted: the only one that can run unclosed to the
// end of the file, since it would have swallowed any later one.
class LastQuote {
 public:
  explicit LastQuote(const std::string& text) : text_(text) {}

  // A scalar's mark; plain scalars do not start with a quote.
  void note(const YAML::Mark& mark) {
    if (mark.is_null() || mark.pos < 0 || static_cast<size_t>(mark.pos) >= text_.size()) return;
    const char first = text_[mark.pos];
    if ((first == '"' || first == '\'') && (!last_ || mark.pos > last_->pos)) last_ = mark;
  }

  // True (after reporting it) when the last quoted scalar is never closed.
  bool reportUnclosed(Diagnostics& diag) const {
    if (!last_ || quoteCloses(text_, last_->pos)) return false;
    const std::string q(1, text_[last_->pos]);
    diag.error(last_->line + 1, "the string quoted with " + q +
                                    " here is never closed (got the rest of the file as its "
                                    "text, expected a closing " +
                                    q + ")");
    return true;
  }

 private:
  const std::string& text_;
  std::optional<YAML::Mark> last_;
};

// The parser's events up to a syntax error, replayed to find its cause: an unclosed quote in a
// flow list or map makes yaml-cpp fail at the end of the file ("end of map flow not found"), and
// its guard against deep nesting fails 500 levels down, not where the nesting passes the limit.
class Replay : public YAML::EventHandler {
 public:
  explicit Replay(const std::string& text) : quotes(text) {}

  LastQuote quotes;
  std::optional<YAML::Mark> too_deep;  // where a list or map first opens past kMaxNesting

  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string&) override {
    quotes.note(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    open(mark);
  }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    open(mark);
  }
  void OnSequenceEnd() override { --level_; }
  void OnMapEnd() override { --level_; }
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}

 private:
  void open(const YAML::Mark& mark) {
    if (++level_ > kMaxNesting && !too_deep) too_deep = mark;
  }
  int level_ = 0;
};

// Walks a document without recursion, counting every value it meets (an alias once per use)
// and noting its quoted scalars.
class DocumentCheck {
 public:
  DocumentCheck(Diagnostics& diag, const std::string& text)
      : diag_(diag), budget_(aliasBudget(text.size())), last_quote_(text) {}

  // Walks the document one top-level entry at a time, so that an expansion past the budget is
  // reported at the key whose value holds it. Reports the first problem found.
  void run(const YAML::Node& root) {
    if (!root.IsMap()) {
      if (walk(root, 1)) reportExpansion(root, "");
    } else {
      ++visits_;
      for (const auto& kv : root) {
        if (walk(kv.first, 2) || walk(kv.second, 2)) {
          reportExpansion(kv.first, kv.first.IsScalar() ? kv.first.Scalar() + ": " : "");
          return;
        }
        if (!diag_.empty()) return;
      }
    }
    if (diag_.empty()) last_quote_.reportUnclosed(diag_);
  }

 private:
  struct Item {
    YAML::Node node;  // copied in, never assigned (see MapEntry)
    int level;        // of nested lists and maps, the top map being level 1
  };

  // True when the budget ran out; a nesting too deep is reported here.
  bool walk(const YAML::Node& start, int level) {
    std::vector<Item> collections;  // met, not yet opened
    if (!visit(start, level, collections)) return true;
    while (!collections.empty()) {
      const Item item = collections.back();
      collections.pop_back();
      if (item.level > kMaxNesting) {
        diag_.error(item.node, kTooDeep);
        return false;
      }
      const bool map = item.node.IsMap();
      for (const auto& child : item.node) {
        const bool within = map ? visit(child.first, item.level + 1, collections) &&
                                      visit(child.second, item.level + 1, collections)
                                : visit(child, item.level + 1, collections);
        if (!within) return true;
      }
    }
    return false;
  }

  // Counts a value, notes a scalar, keeps a list or map to open; false past the budget.
  bool visit(const YAML::Node& n, int level, std::vector<Item>& collections) {
    if (++visits_ > budget_) return false;
    if (n.IsScalar())
      last_quote_.note(n.Mark());
    else if (n.IsSequence() || n.IsMap())
      collections.push_back({n, level});
    return true;
  }

  void reportExpansion(const YAML::Node& at, const std::string& prefix) {
    diag_.error(at, prefix + "YAML aliases expand to more than " + std::to_string(budget_) +
                        " values (an alias bomb?)");
  }

  Diagnostics& diag_;
  const size_t budget_;
  size_t visits_ = 0;
  LastQuote last_quote_;
};

// The events of the text up to its syntax error.
Replay replay(const std::string& text) {
  Replay events(text);
  std::istringstream in(text);
  try {
    YAML::Parser(in).HandleNextDocument(events);
  } catch (const YAML::Exception&) {
  }
  return events;
}

std::optional<YAML::Node> parse(Diagnostics& diag, const std::string& text) {
  try {
    return YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    const Replay events = replay(text);
    diag.error(events.too_deep ? events.too_deep->line + 1 : e.mark.line + 1, kTooDeep);
  } catch (const YAML::ParserException& e) {
    if (!replay(text).quotes.reportUnclosed(diag))
      diag.error(e.mark.line + 1, "not valid YAML: " + e.msg);
  }
  return std::nullopt;
}

}  // namespace

size_t aliasBudget(size_t bytes) { return 1000000 + 2 * bytes; }

YAML::Node loadCaseDocument(Diagnostics& diag, std::optional<NodeTable>& node_table) {
  const std::optional<std::string> text = readText(diag.file());
  if (!text) diag.error(0, "cannot open the file");
  diag.throwIfAny();
  return loadCaseText(diag, *text, node_table);
}

YAML::Node loadCaseText(Diagnostics& diag, const std::string& text_in,
                        std::optional<NodeTable>& node_table) {
  const std::optional<std::string> text = text_in;
  // The node table's fast path (node_table.hpp): parse the text without it when yaml-cpp agrees
  // that it was the top-level `nodes:`; otherwise the whole text, as if there were none.
  std::string without_table = *text;
  node_table = takeNodeTable(without_table);
  std::optional<YAML::Node> root;
  if (node_table) {
    Diagnostics scratch(diag.file());  // a failure here is reported by the full parse below
    root = parse(scratch, without_table);
    if (!root || !tableFits(*root, *node_table)) {
      root.reset();
      node_table.reset();
    }
  }
  if (!root) root = parse(diag, *text);
  if (root) DocumentCheck(diag, node_table ? without_table : *text).run(*root);
  diag.throwIfAny();
  return *root;
}

}  // namespace flexmoor::app
