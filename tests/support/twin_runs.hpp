#pragma once
// For the tests that state a case twice (in code and in its case file, or through a scenario's
// function): the same model, and runs with every record kept, compared to the bit; and what a
// case stated in code is refused for.
#include <string>

#include "apps/output/memory_sink.hpp"
#include "apps/problem/case.hpp"
#include "apps/problem/case_spec.hpp"
#include "apps/run/simulation.hpp"

namespace flexmoor::test {

// A run and every record it makes.
struct RecordedRun {
  app::SimulationResult result;
  app::MemorySink records;
};

// Runs the case to its end, its records into out.records.
void runRecorded(const app::Case& c, RecordedRun& out);

// buildCase refuses the spec with a reason that contains `part`.
void expectRefused(const app::CaseSpec& spec, const std::string& part);

// The same nodes and reference, the same elements on the same nodes, the same equations,
// prescribed values and gravity; the same line, node and surface load counts.
void expectSameModel(const model::Model& a, const model::Model& b);

// Both succeeded, with as many records, each at the same time with the same displacement,
// velocity, acceleration and reactions.
void expectSameRecords(const RecordedRun& a, const RecordedRun& b);
// The same summary names in the same order, with the same values (but the CPU time's).
void expectSameSummary(const RecordedRun& a, const RecordedRun& b);

}  // namespace flexmoor::test
