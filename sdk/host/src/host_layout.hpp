// Reading structs a plugin wrote against another minor version of the ABI (core.h's growth rule):
// a plugin built with older headers hands over smaller structs, one built with newer headers
// bigger ones and arrays whose elements are further apart than this host's sizeof. Everything the
// host keeps of a plugin's descriptors is first copied into this host's own layout here, so the
// rest of libpfxhost (and every program on top of it) indexes plain arrays.
#pragma once

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <pfx/pfx.h>

namespace pfx::host {

// A copy of a sized struct in this host's layout: the bytes the writer's struct_size covers, at
// most sizeof(T); fields the writer's version did not have read as zero, which by the growth rule
// means what the version before them did. The caller has checked struct_size >= the minimum.
template <class T>
T read_sized(const T* source) {
  T value{};
  std::memcpy(&value, source, std::min<size_t>(source->struct_size, sizeof(T)));
  return value;
}

// Element `index` of an array of sized structs, stepped by the elements' own struct_size.
template <class T>
const T* sized_element(const T* array, uint32_t index) {
  return pfx_at(T, array, index);
}

// An array of `count` sized structs copied into this host's layout. Empty *problem on success;
// otherwise it names the element: smaller than `min_size`, or of another size than element 0.
template <class T>
std::vector<T> read_sized_array(const T* array, uint32_t count, size_t min_size, const char* what,
                                std::string* problem) {
  std::vector<T> copies;
  problem->clear();
  if (count == 0) return copies;
  const uint32_t stride = array[0].struct_size;
  if (stride < min_size) {
    *problem = std::string(what) + " #0: struct_size " + std::to_string(stride) + " is below the first published size " +
               std::to_string(min_size);
    return {};
  }
  copies.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    const T* element = sized_element(array, i);
    if (element->struct_size != stride) {
      *problem = std::string(what) + " #" + std::to_string(i) + ": struct_size " + std::to_string(element->struct_size) +
                 " differs from element #0's " + std::to_string(stride) + " (one array, one size)";
      return {};
    }
    copies.push_back(read_sized(element));
  }
  return copies;
}

// An effect descriptor in this host's layout with its parameter table; `desc.params` points into
// `params`. Strings and functions still point into the plugin, valid while it stays loaded.
struct HostLayoutEffect {
  pfx_effect_desc desc{};
  std::vector<pfx_param_desc> params;
};

// The plugin's effect descriptor in this host's layout, or null with *problem saying why.
std::unique_ptr<HostLayoutEffect> effect_in_host_layout(const pfx_effect_desc* plugin_desc, std::string* problem);

}  // namespace pfx::host
