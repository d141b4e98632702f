#pragma once
// Outputs that are never seen half written and never written through a planted link: a file is
// written under a temporary name in its own directory and put in place with rename(2), which
// replaces whatever is at the path (a file, or a symbolic link itself rather than its target)
// in one step. A reader that holds the old file open keeps reading the old file.
#include <string>

namespace flexmoor::app {

// Writes `text` to `path` in that way. Throws std::runtime_error "PATH: cannot write ...: <errno
// text>" when the file cannot be written or put in place; the temporary file is then removed
// and whatever was at `path` is left as it was.
void writeFileAtomically(const std::string& path, const std::string& text);

// Puts the finished file `written` (in the same directory) in place at `path`: flushes it to
// the disk, renames it over `path` and flushes the directory. Throws std::runtime_error naming
// both paths when the rename fails.
void moveIntoPlace(const std::string& written, const std::string& path);

// Removes whatever is at `path` (a file or a symbolic link, never the link's target); nothing
// when there is nothing. Throws std::runtime_error when it is there and cannot be removed.
void removeEntry(const std::string& path);

}  // namespace flexmoor::app
