#include "tests/support/seed_tables.hpp"

#include <fstream>
#include <sstream>
#include <vector>

namespace flexmoor::test {

std::map<int, double> tableRow(const std::string& table, const std::string& model) {
  std::ifstream in(std::string(FLEXMOOR_DATA_DIR) + "/reference/seed-tables.csv");
  std::map<int, double> row;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string field; std::getline(s, field, ',');) fields.push_back(field);
    if (fields.size() == 5 && fields[0] == table && fields[1] == model)
      row[std::stoi(fields[3])] = std::stod(fields[4]);
  }
  return row;
}

}  // namespace flexmoor::test
