// Notices that files were saved: the FX files the chain's effects were made from (the viewer draws
// a frame then, since an effect looks at its own files only when it runs, and a viewer that draws
// only on change would otherwise never run it) and the preset it started from (applied again).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace pfx::app {

class FileWatch {
 public:
  // Whether any of `files` (given at each call, so a list that changed since is followed) changed
  // since the last call: a new modification time, size or inode, the file
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
