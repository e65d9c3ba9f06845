#pragma once
// What a slang pass's SPIR-V reads, found by SPIRV-Cross's reflection (Debian's static
// libraries): its uniform block and push constants, each member the pass uses with its offset and
// what its name stands for (slang_semantics.hpp), and its samplers with their bindings. The format's rules are checked here, as RetroArch checks them: descriptor set 0, at
// most one block of each kind, the same block at the same binding in both stages with its members
// at the same offsets, samplers only in the fragment stage, every name one the format knows, of
// the type the format gives it.
#include <cstdint>
#include <string>
#include <vector>

#include "slang_semantics.hpp"

namespace pfx::libretro {

struct ReflectedMember {
  std::string name;
  Semantic semantic;
  std::uint32_t offset = 0;
};

struct ReflectedBlock {
  bool present = false;
  std::uint32_t binding = 0;             // the uniform block's (push constants have none)
  std::uint32_t size = 0;                // bytes, as declared
  std::vector<ReflectedMember> members;  // those the pass reads, by offset
};

struct ReflectedSampler {
  std::string name;
  Semantic semantic;
  std::uint32_t binding = 0;
};

struct PassInterface {
  ReflectedBlock uniforms, push;
  std::vector<ReflectedSampler> samplers;
};

// False with why in *error (naming the uniform or sampler).
bool reflect_slang_pass(const std::vector<std::uint32_t>& vertex, const std::vector<std::uint32_t>& fragment,
                        const SemanticContext& context, PassInterface* out, std::string* error);

}  // namespace pfx::libretro
