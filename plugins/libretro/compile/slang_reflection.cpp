#include "slang_reflection.hpp"

#include <algorithm>
#include <memory>

#include <spirv_cross/spirv_cross_c.h>

namespace pfx::libretro {
namespace {

// One stage's module, parsed; SPIRV-Cross's messages go to `error`.
class StageReflection {
 public:
  ~StageReflection() {
    if (context_) spvc_context_destroy(context_);
  }
  bool parse(const std::vector<std::uint32_t>& words, std::string* error) {
    error_ = error;
    spvc_parsed_ir ir = nullptr;
    return spvc_context_create(&context_) == SPVC_SUCCESS &&
           (spvc_context_set_error_callback(context_, &StageReflection::on_error, this), true) &&
           spvc_context_parse_spirv(context_, words.data(), words.size(), &ir) == SPVC_SUCCESS &&
           spvc_context_create_compiler(context_, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                        &compiler_) == SPVC_SUCCESS &&
           spvc_compiler_create_shader_resources(compiler_, &resources_) == SPVC_SUCCESS;
  }
  std::vector<spvc_reflected_resource> list(spvc_resource_type type) const {
    const spvc_reflected_resource* items = nullptr;
    std::size_t count = 0;
    spvc_resources_get_resource_list_for_type(resources_, type, &items, &count);
    return std::vector<spvc_reflected_resource>(items, items + count);
  }
  spvc_compiler compiler() const { return compiler_; }

 private:
  static void on_error(void* self, const char* message) {
    *static_cast<StageReflection*>(self)->error_ = std::string("SPIRV-Cross: ") + message;
  }
  spvc_context context_ = nullptr;
  spvc_compiler compiler_ = nullptr;
  spvc_resources resources_ = nullptr;
  std::string* error_ = nullptr;
};

// The type a member's SPIR-V type is, if it is one the format uses.
std::optional<SemanticType> member_type(spvc_compiler compiler, spvc_type_id id) {
  const spvc_type type = spvc_compiler_get_type_handle(compiler, id);
  if (spvc_type_get_num_array_dimensions(type) != 0) return std::nullopt;
  const unsigned size = spvc_type_get_vector_size(type), columns = spvc_type_get_columns(type);
  switch (spvc_type_get_basetype(type)) {
    case SPVC_BASETYPE_FP32:
      if (size == 1 && columns == 1) return SemanticType::kFloat;
      if (size == 4 && columns == 1) return SemanticType::kVec4;
      if (size == 4 && columns == 4) return SemanticType::kMat4;
      return std::nullopt;
    case SPVC_BASETYPE_INT32:
      return size == 1 && columns == 1 ? std::optional<SemanticType>(SemanticType::kInt) : std::nullopt;
    case SPVC_BASETYPE_UINT32:
      return size == 1 && columns == 1 ? std::optional<SemanticType>(SemanticType::kUint) : std::nullopt;
    default:
      return std::nullopt;
  }
}

// One stage's block of `kind` into `block` (merged with the other stage's).
bool read_block(const StageReflection& stage, spvc_resource_type kind, const char* what, const SemanticContext& context,
                ReflectedBlock* block, std::string* error) {
  const std::vector<spvc_reflected_resource> blocks = stage.list(kind);
  if (blocks.empty()) return true;
  if (blocks.size() > 1) return *error = std::string("more than one ") + what, false;
  const spvc_compiler compiler = stage.compiler();
  const spvc_reflected_resource& resource = blocks[0];
  const bool uniform = kind == SPVC_RESOURCE_TYPE_UNIFORM_BUFFER;
  if (uniform && spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationDescriptorSet) != 0)
    return *error = std::string("the ") + what + " is not in descriptor set 0", false;
  const std::uint32_t binding = uniform ? spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationBinding) : 0;
  const spvc_type type = spvc_compiler_get_type_handle(compiler, resource.base_type_id);
  std::size_t size = 0;
  spvc_compiler_get_declared_struct_size(compiler, type, &size);
  if (block->present && block->binding != binding)
    return *error = std::string("the ") + what + " is at binding " + std::to_string(block->binding) +
                    " in one stage and " + std::to_string(binding) + " in the other",
           false;
  block->present = true, block->binding = binding;
  block->size = std::max(block->size, static_cast<std::uint32_t>(size));
  const spvc_buffer_range* ranges = nullptr;
  std::size_t range_count = 0;
  spvc_compiler_get_active_buffer_ranges(compiler, resource.id, &ranges, &range_count);
  for (std::size_t r = 0; r < range_count; ++r) {
    const unsigned index = ranges[r].index;
    ReflectedMember member;
    member.name = spvc_compiler_get_member_name(compiler, resource.base_type_id, index);
    unsigned offset = 0;
    spvc_compiler_type_struct_member_offset(compiler, type, index, &offset);
    member.offset = offset;
    const auto semantic = find_semantic(member.name, false, context, error);
    if (!semantic) return *error = std::string(what) + " member " + *error, false;
    const SemanticType wanted = semantic_type(semantic->kind);
    if (member_type(compiler, spvc_type_get_member_type(type, index)) != wanted)
      return *error = std::string(what) + " member '" + member.name + "' must be a " + semantic_type_name(wanted),
             false;
    member.semantic = *semantic;
    const auto same = std::find_if(block->members.begin(), block->members.end(),
                                   [&](const ReflectedMember& m) { return m.name == member.name; });
    if (same == block->members.end())
      block->members.push_back(member);
    else if (same->offset != member.offset)
      return *error = std::string(what) + " member '" + member.name + "' is at another offset in each stage", false;
  }
  std::sort(block->members.begin(), block->members.end(),
            [](const ReflectedMember& a, const ReflectedMember& b) { return a.offset < b.offset; });
  return true;
}

bool read_samplers(const StageReflection& stage, const SemanticContext& context, PassInterface* out,
                   std::string* error) {
  const spvc_compiler compiler = stage.compiler();
  for (const spvc_reflected_resource& resource : stage.list(SPVC_RESOURCE_TYPE_SAMPLED_IMAGE)) {
    const std::string name = resource.name;
    if (spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationDescriptorSet) != 0)
      return *error = "sampler '" + name + "' is not in descriptor set 0", false;
    const auto semantic = find_semantic(name, true, context, error);
    if (!semantic) return *error = "sampler " + *error, false;
    out->samplers.push_back(
        {name, *semantic, spvc_compiler_get_decoration(compiler, resource.id, SpvDecorationBinding)});
  }
  return true;
}

}  // namespace

bool reflect_slang_pass(const std::vector<std::uint32_t>& vertex, const std::vector<std::uint32_t>& fragment,
                        const SemanticContext& context, PassInterface* out, std::string* error) {
  *out = PassInterface{};
  StageReflection stages[2];
  if (!stages[0].parse(vertex, error) || !stages[1].parse(fragment, error)) return false;
  if (!stages[0].list(SPVC_RESOURCE_TYPE_SAMPLED_IMAGE).empty())
    return *error = "the vertex stage samples a texture: slang passes sample only in the fragment stage", false;
  for (const StageReflection& stage : stages)
    if (!read_block(stage, SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, "uniform block", context, &out->uniforms, error) ||
        !read_block(stage, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, "push constant block", context, &out->push, error))
      return false;
  return read_samplers(stages[1], context, out, error);
}

}  // namespace pfx::libretro
