// Fills a pfx_declaration from storage that outlives the call, as the ABI asks (valid until the
// next declare or destroy): one builder per effect instance, cleared at every declare.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>

#include <pfx/cpp/descriptors.hpp>
#include <pfx/effect.h>

namespace pfx_bloom {

class DeclarationBuilder {
 public:
  static constexpr uint32_t kMaxTargets = 48, kMaxPasses = 64, kMaxInputs = 16;

  void clear() { target_count_ = pass_count_ = 0; }

  // An RGBA16F target of a fixed size. name must outlive the declaration (a static string).
  void target(const char* name, int width, int height) {
    pfx_target_desc& t = targets_[target_count_++];
    t = pfx_target_desc{};
    t.struct_size = sizeof t;
    t.name = name;
    t.format = PFX_FORMAT_RGBA16F;
    t.size_mode = PFX_SIZE_FIXED;
    t.width = static_cast<uint32_t>(width);
    t.height = static_cast<uint32_t>(height);
  }

  void pass(const char* name, const char* output, std::initializer_list<pfx_pass_input> inputs, pfx_blend blend,
            pfx_load load, uint32_t tag) {
    pfx_pass_input* stored = inputs_[pass_count_];
    uint32_t n = 0;
    for (const pfx_pass_input& input : inputs) stored[n++] = input;
    passes_[pass_count_++] = pfx::desc::fullscreen_pass(name, output, stored, n, blend, load, tag);
  }

  // The last pass declared reads one more input (for passes whose input count varies).
  void add_input(const pfx_pass_input& input) {
    pfx_pass_desc& last = passes_[pass_count_ - 1];
    inputs_[pass_count_ - 1][last.input_count++] = input;
  }

  void finish(pfx_declaration* out) const {
    out->targets = targets_;
    out->target_count = target_count_;
    out->passes = passes_;
    out->pass_count = pass_count_;
  }

  uint32_t pass_count() const { return pass_count_; }

 private:
  pfx_target_desc targets_[kMaxTargets] = {};
  pfx_pass_desc passes_[kMaxPasses] = {};
  pfx_pass_input inputs_[kMaxPasses][kMaxInputs] = {};
  uint32_t target_count_ = 0, pass_count_ = 0;
};

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
