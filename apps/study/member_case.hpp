#pragma once
// A study member's case: the base case's document with the member's values set at their paths,
// built and checked like any case, with the study's collect: entries read against it.
#include <optional>
#include <string>
#include <vector>

#include "apps/case/case_reader.hpp"
#include "apps/problem/case.hpp"
#include "apps/study/study.hpp"

namespace flexmoor::app {

struct MemberCase {
  Case c;
  std::vector<SummarySpec> collect;  // one per study.collect entry
};

// The member's case, or nullopt after reporting why not, in the study's file: a path the base
// case does not have; a problem of the case at the study line of the value that causes it (else
// the member's line), "member N (PATH = VALUE, ...): the member's case is not valid: CASE:LINE:
// ..." to `diag`; a collect: entry's problem at the entry's line, "member N: ...", to
// `collect_diag` (the same, most likely, for every member).
std::optional<MemberCase> buildMember(const Study& study, const StudyMember& member,
                                      Diagnostics& diag, Diagnostics& collect_diag);
// The same, throwing CaseError with every message.
MemberCase buildMember(const Study& study, const StudyMember& member);

// The member's values as "waves.spectrum.Hs = 2 m, waves.seed = 1".
std::string describeValues(const StudyMember& member);

// The hash (FNV-1a, 64 bits, 16 hex digits) of what makes the member's run: the base case's
// file text, the member's paths and values, and the collect: entries. A changed study changes
// the hashes of the members it changes, and only theirs.
std::string memberHash(const std::string& base_text, const StudyMember& member,
                       const std::vector<CollectSpec>& collect);

}  // namespace flexmoor::app
