#pragma once
// The dissertation's Chapter V tables as transcribed in data/reference/seed-tables.csv
// (`table,model,quantity,index,value`), read at test time.
#include <map>
#include <string>

namespace flexmoor::test {

// index -> value of every row of `table` and `model` (e.g. "table4", "6 quadratic").
std::map<int, double> tableRow(const std::string& table, const std::string& model);

}  // namespace flexmoor::test
