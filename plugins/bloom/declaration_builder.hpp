// What bloom and glare declare with: the kit's declaration builder at the sizes they need, and the
// names and inputs their passes repeat.
#pragma once

#include <cstdint>
#include <string>

#include <pfx/cpp/declaration.hpp>
#include <pfx/effect.h>

namespace pfx_bloom {

// Enough for the deepest pyramid (every level a target and a down and an up pass) and for glare's
// streak passes.
using DeclarationBuilder = pfx::desc::DeclarationBuilder<48, 64>;

// Names like "level3" that live as long as the plugin: a table per prefix, built once.
class IndexedNames {
 public:
  explicit IndexedNames(const char* prefix) {
    for (int i = 0; i < kCount; ++i) names_[i] = prefix + std::to_string(i);
  }
  const char* operator[](int i) const { return names_[i].c_str(); }

 private:
  static constexpr int kCount = 64;
  std::string names_[kCount];
};

// pfx_pass_input in one line.
inline pfx_pass_input input(const char* name, pfx_filter filter, pfx_wrap wrap) { return {name, filter, wrap}; }

}  // namespace pfx_bloom
