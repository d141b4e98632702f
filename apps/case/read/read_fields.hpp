#pragma once
// Readers of case values shared by the ocean sections (read_hydro.cpp, read_sea.cpp): quantities
// of a map's fields that are nullopt when wrong (reported), and tables of [a, b] rows.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

// A required quantity: nullopt when it is absent (reported) or wrong.
std::optional<double> requiredQuantity(CaseBuilder& b, Fields& f, const std::string& key,
                                       const QuantityKind& kind, Limit limit);

// An optional quantity: its fallback when absent, nullopt when wrong.
std::optional<double> optionalQuantity(CaseBuilder& b, const Fields& f, const std::string& key,
                                       const QuantityKind& kind, Limit limit, double fallback);

// One column of a table: its name in messages ("z") and what it holds.
struct Column {
  const char* name;
  const QuantityKind& kind;
};

// [[a, b], ...]: at least one row, a strictly increasing from row to row; nullopt when wrong
// (the first problem reported).
std::optional<std::vector<std::pair<double, double>>> readIncreasingRows(CaseBuilder& b,
                                                                         const YAML::Node& n,
                                                                         const std::string& path,
                                                                         const Column& first,
                                                                         const Column& second);

}  // namespace flexmoor::app
