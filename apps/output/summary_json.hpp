#pragma once
// <case>.summary.json: the scalar results a case declares, with their units, as one small JSON object
//   {"case": NAME, "results": {QUANTITY: VALUE, ...}, "units": {QUANTITY: UNIT, ...}}
// Values are written with enough digits to read back the same double.
#include <string>
#include <utility>
#include <vector>

namespace flexmoor::app {

// Writes the file at `path`, atomically (atomic_output.hpp: a symbolic link there is replaced, not
// followed). Throws std::runtime_error, before anything is written, when a value is NaN or
// infinite or a name appears twice in `results` or in `units`, and when the file cannot be
// written.
void writeSummaryJson(const std::string& path, const std::string& case_name,
                      const std::vector<std::pair<std::string, double>>& results,
                      const std::vector<std::pair<std::string, std::string>>& units);

}  // namespace flexmoor::app
