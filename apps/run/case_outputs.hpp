#pragma once
// The files a run of a case leaves in its output directory, and those it works with:
//   DIR/<case>.nc              the results, put in place when the run ends
//   DIR/<case>.nc.partial      the results while they are streamed; what a killed run leaves
//   DIR/<case>-<n>.vtk         the state after step n
//   DIR/<case>.summary.json    the case's summary quantities
//   DIR/<case>.png             the case's figure, when it has one
//   DIR/.<case>.lock           held while a run of the case writes into DIR
// Every name starts with the case's, so cases share a directory without touching each other's.
#include <set>
#include <string>

namespace flexmoor::app {

// results/<case>, the output directory when none is given.
std::string defaultOutputDirectory(const std::string& case_name);

class CaseOutputs {
 public:
  CaseOutputs(std::string directory, std::string case_name);

  const std::string& directory() const { return directory_; }
  std::string netcdf() const;
  std::string partialNetcdf() const;
  std::string vtk(int step) const;  // step 1-based
  std::string summary() const;
  std::string figure() const;
  std::string lock() const;

  // Removes what an earlier run of the case left and this run did not write: DIR/<case>-<n>.vtk
  // for every n not in `vtk_steps`, and the temporary files of an atomic write that was killed
  // (".<case>-<n>.vtk.tmp-..." and ".<case>.summary.json.tmp-..."). Nothing of other cases.
  void removeStale(const std::set<int>& vtk_steps) const;

 private:
  std::string directory_, case_name_;
};

}  // namespace flexmoor::app
