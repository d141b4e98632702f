#pragma once
// Reading a study.nc back through the netCDF C API, for the study tests.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace flexmoor::test {

// A double variable whole, its _FillValue as NaN.
std::vector<double> doubleVariable(const std::filesystem::path& file, const std::string& name);
std::vector<int> intVariable(const std::filesystem::path& file, const std::string& name);
// Row `row` of a char (member, strlen) variable, without its trailing NULs.
std::string textRow(const std::filesystem::path& file, const std::string& name, size_t row);
// Every double variable by name, as stored (fill values as they are).
std::map<std::string, std::vector<double>> doubleVariables(const std::filesystem::path& file);
// Equal bit for bit.
bool sameBits(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace flexmoor::test
