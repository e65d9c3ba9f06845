#include "keep_loaded.hpp"

#include <dlfcn.h>
#include <link.h>

#include <algorithm>

namespace pfx::app {

std::vector<std::string> loaded_shared_objects() {
  std::vector<std::string> names;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        // The main program and the vDSO have no file name to dlopen.
        if (info->dlpi_name && info->dlpi_name[0])
          static_cast<std::vector<std::string>*>(out)->push_back(info->dlpi_name);
        return 0;
      },
      &names);
  return names;
}

int keep_loaded_since(const std::vector<std::string>& before) {
  int kept = 0;
  for (const std::string& name : loaded_shared_objects()) {
    if (std::find(before.begin(), before.end(), name) != before.end()) continue;
    // RTLD_NOLOAD finds the loaded object without loading anything; RTLD_NODELETE on it makes
    // every later dlclose leave it mapped. Closing our own handle then only drops our reference.
    if (void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE)) {
      dlclose(handle);
      ++kept;
    }
  }
  return kept;
}

}  // namespace pfx::app
