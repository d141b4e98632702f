#pragma once
// Problems found in a case file, collected so that a reader reports every one of them at once as
// `FILE:LINE: what is wrong (got X, expected Y)`, then throws a single CaseError
// (apps/problem/case_error.hpp).
#include <string>
#include <utility>
#include <vector>

#include "apps/problem/case_error.hpp"

namespace YAML {
class Node;
}

namespace flexmoor::app {

class Diagnostics {
 public:
  explicit Diagnostics(std::string file) : file_(std::move(file)) {}

  // A problem at a 1-based line (0: the file as a whole).
  void error(int line, const std::string& what);
  // A problem at a YAML node (its line is Mark().line + 1).
  void error(const YAML::Node& at, const std::string& what);

  // Something a run will do, but perhaps not as the user meant: reported, not refused.
  void warning(int line, const std::string& what);
  // "FILE:LINE: warning: what", in the order found.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // What a run does that the case does not spell out (a default it chose): "FILE:LINE: note:
  // what", each text once, in the order found.
  void note(int line, const std::string& what);
  const std::vector<std::string>& notes() const { return notes_; }

  // Until redirect(nullptr), problems and warnings go to `to` instead, each prefixed with
  // `prefix` (a study's collect: entries, read against a member's case, are the study file's).
  void redirect(Diagnostics* to, std::string prefix = "") {
    redirect_ = to;
    prefix_ = std::move(prefix);
  }

  const std::string& file() const { return file_; }
  bool empty() const { return problems_.empty(); }
  // Every message, ordered by line (problems on one line in the order they were found).
  std::vector<std::string> messages() const;

  // Throws CaseError with every message collected, if there is any.
  void throwIfAny() const;

 private:
  struct Problem {
    int line;
    std::string message;
  };
  std::string file_;
  std::vector<Problem> problems_;
  std::vector<std::string> warnings_;
  std::vector<std::string> notes_;
  Diagnostics* redirect_ = nullptr;
  std::string prefix_;
};

// 1-based line of a node, or 0 when the node carries no position.
int lineOf(const YAML::Node& node);

}  // namespace flexmoor::app
