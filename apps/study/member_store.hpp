#pragma once
// What a study keeps of its members in DIR/members/NNNN/ (1-based, 4 digits): the member's run
// outputs (<case>.nc, <case>.summary.json), series.nc, run.log (its progress) and errors.log (its
// diagnoses), and the outcome: `complete` holding the hash of the member's case text (written
// last, after series.nc), or `failed` holding the exit code on its first line and the error.
#include <string>

#include "apps/study/study.hpp"

namespace flexmoor::app {

// How a member ended, as study.nc's status holds it.
enum MemberStatus { kComplete = 0, kStatusBadInput = 2, kStatusNotConverged = 3, kFailed = 4 };

struct MemberOutcome {
  int status = kFailed;
  std::string error;  // empty when complete
};

std::string memberDirectory(const std::string& dir, int index);
std::string seriesPath(const std::string& dir, int index);

// Whether the member is complete with the case text it has now (its hash).
bool isComplete(const std::string& dir, const StudyMember& member);
void markComplete(const std::string& dir, const StudyMember& member);
// `failed`: the status (2, 3 or 4) and the error text.
void markFailed(const std::string& dir, const StudyMember& member, int status,
                const std::string& error);
// Before a member runs (again): its outcome removed.
void clearOutcome(const std::string& dir, const StudyMember& member);
// complete, failed (with its text), or failed as "did not run" when there is no outcome.
MemberOutcome readOutcome(const std::string& dir, const StudyMember& member);

// The last `bytes` characters of a file (an error log's end), whitespace trimmed.
std::string fileTail(const std::string& path, size_t bytes);

}  // namespace flexmoor::app
