#pragma once
// Where flexmoor's data are: the named cases (cases/) and the figure scripts (plot/). Installed,
// they are in share/flexmoor of the prefix libflexmoor was installed into; in a build tree,
// build/share/flexmoor holds links to the source's cases/ and apps/plot/. The environment
// variable FLEXMOOR_DATA_DIR, when set, names another folder holding cases/ and plot/.
#include <filesystem>

namespace flexmoor::app {

// $FLEXMOOR_DATA_DIR when set and not empty, else the share/flexmoor folder found from the file
// libflexmoor was loaded from (the same relative path as between the installed lib/ and share/).
// Throws std::runtime_error naming the folder searched when it holds no cases/ folder.
std::filesystem::path dataDir();

// dataDir()/cases, its links resolved (so a named case is reported by the file it is: in the
// build tree, the source's).
std::filesystem::path casesDir();

// dataDir()/plot/flexmoor_plot.py: the script that draws every figure (beside the modules it
// imports). Throws std::runtime_error naming the path when it is not there.
std::filesystem::path plotScript();

}  // namespace flexmoor::app
