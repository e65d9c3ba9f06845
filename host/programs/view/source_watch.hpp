// Notices an edit of a file an effect of the chain was made from (an FX file), so the viewer draws
// a frame when one is saved even while nothing else changes: the effect looks at its own files when
// it runs, and a viewer that draws only on change would otherwise never run it.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace pfx::app {

class SourceWatch {
 public:
  // Whether any of `files` (the chain's, looked up again at each call, so a chain changed since is
  // followed) changed since the last call: a new modification time, size or inode, the file
  // appearing or going. A file seen for the first time counts as unchanged.
  bool changed(const std::vector<std::string>& files);

 private:
  struct Stamp {
    long long time = -1, size = -1;
    unsigned long long inode = 0;
    bool operator!=(const Stamp& other) const { return time != other.time || size != other.size || inode != other.inode; }
  };
  std::map<std::string, Stamp> seen_;
};

}  // namespace pfx::app
