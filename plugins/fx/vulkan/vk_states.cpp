#include "vk_states.hpp"

#include <algorithm>

namespace pfx::fx::vulkan {

VkFormat vk_format(TextureFormat format) {
  switch (format) {
    case TextureFormat::kR8: return VK_FORMAT_R8_UNORM;
    case TextureFormat::kR16: return VK_FORMAT_R16_UNORM;
    case TextureFormat::kR16F: return VK_FORMAT_R16_SFLOAT;
    case TextureFormat::kR32F: return VK_FORMAT_R32_SFLOAT;
    case TextureFormat::kR32I: return VK_FORMAT_R32_SINT;
    case TextureFormat::kR32U: return VK_FORMAT_R32_UINT;
    case TextureFormat::kRG8: return VK_FORMAT_R8G8_UNORM;
    case TextureFormat::kRG16: return VK_FORMAT_R16G16_UNORM;
    case TextureFormat::kRG16F: return VK_FORMAT_R16G16_SFLOAT;
    case TextureFormat::kRG32F: return VK_FORMAT_R32G32_SFLOAT;
    case TextureFormat::kRGBA16: return VK_FORMAT_R16G16B16A16_UNORM;
    case TextureFormat::kRGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case TextureFormat::kRGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case TextureFormat::kRGB10A2: return VK_FORMAT_A2B10G10R10_UNORM_PACK32;
    case TextureFormat::kRGBA8: break;
  }
  return VK_FORMAT_R8G8B8A8_UNORM;
}

VkFormat srgb_form(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM: return VK_FORMAT_R8G8B8A8_SRGB;
    case VK_FORMAT_B8G8R8A8_UNORM: return VK_FORMAT_B8G8R8A8_SRGB;
    case VK_FORMAT_A8B8G8R8_UNORM_PACK32: return VK_FORMAT_A8B8G8R8_SRGB_PACK32;
    default: return VK_FORMAT_UNDEFINED;
  }
}

namespace {

VkSamplerAddressMode address(AddressMode mode) {
  switch (mode) {
    case AddressMode::kMirror: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case AddressMode::kWrap: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case AddressMode::kBorder: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    case AddressMode::kClamp: break;
  }
  return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
}

VkBlendOp blend_op(BlendOp op) {
  switch (op) {
    case BlendOp::kSubtract: return VK_BLEND_OP_SUBTRACT;
    case BlendOp::kRevSubtract: return VK_BLEND_OP_REVERSE_SUBTRACT;
    case BlendOp::kMin: return VK_BLEND_OP_MIN;
    case BlendOp::kMax: return VK_BLEND_OP_MAX;
    case BlendOp::kAdd: break;
  }
  return VK_BLEND_OP_ADD;
}

VkBlendFactor blend_factor(BlendFactor factor) {
  switch (factor) {
    case BlendFactor::kZero: return VK_BLEND_FACTOR_ZERO;
    case BlendFactor::kOne: return VK_BLEND_FACTOR_ONE;
    case BlendFactor::kSrcColor: return VK_BLEND_FACTOR_SRC_COLOR;
    case BlendFactor::kSrcAlpha: return VK_BLEND_FACTOR_SRC_ALPHA;
    case BlendFactor::kInvSrcColor: return VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR;
    case BlendFactor::kInvSrcAlpha: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    case BlendFactor::kDestColor: return VK_BLEND_FACTOR_DST_COLOR;
    case BlendFactor::kDestAlpha: return VK_BLEND_FACTOR_DST_ALPHA;
    case BlendFactor::kInvDestColor: return VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR;
    case BlendFactor::kInvDestAlpha: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
  }
  return VK_BLEND_FACTOR_ONE;
}

VkCompareOp compare_op(CompareFunc func) {
  switch (func) {
    case CompareFunc::kNever: return VK_COMPARE_OP_NEVER;
    case CompareFunc::kLess: return VK_COMPARE_OP_LESS;
    case CompareFunc::kEqual: return VK_COMPARE_OP_EQUAL;
    case CompareFunc::kLessEqual: return VK_COMPARE_OP_LESS_OR_EQUAL;
    case CompareFunc::kGreater: return VK_COMPARE_OP_GREATER;
    case CompareFunc::kNotEqual: return VK_COMPARE_OP_NOT_EQUAL;
    case CompareFunc::kGreaterEqual: return VK_COMPARE_OP_GREATER_OR_EQUAL;
    case CompareFunc::kAlways: break;
  }
  return VK_COMPARE_OP_ALWAYS;
}

// ReShade's INCR and DECR wrap, INCRSAT and DECRSAT saturate (Vulkan names them the other way).
VkStencilOp stencil_op(StencilOp op) {
  switch (op) {
    case StencilOp::kKeep: break;
    case StencilOp::kZero: return VK_STENCIL_OP_ZERO;
    case StencilOp::kReplace: return VK_STENCIL_OP_REPLACE;
    case StencilOp::kIncrSat: return VK_STENCIL_OP_INCREMENT_AND_CLAMP;
    case StencilOp::kDecrSat: return VK_STENCIL_OP_DECREMENT_AND_CLAMP;
    case StencilOp::kInvert: return VK_STENCIL_OP_INVERT;
    case StencilOp::kIncr: return VK_STENCIL_OP_INCREMENT_AND_WRAP;
    case StencilOp::kDecr: return VK_STENCIL_OP_DECREMENT_AND_WRAP;
  }
  return VK_STENCIL_OP_KEEP;
}

}  // namespace

VkStencilOpState stencil_state(const StencilState& s) {
  VkStencilOpState out{};
  out.failOp = stencil_op(s.fail_op);
  out.passOp = stencil_op(s.pass_op);
  out.depthFailOp = stencil_op(s.depth_fail_op);
  out.compareOp = compare_op(s.func);
  out.compareMask = s.read_mask & 0xFFu;
  out.writeMask = s.write_mask & 0xFFu;
  out.reference = s.ref & 0xFFu;
  return out;
}

VkSamplerCreateInfo sampler_info(const SamplerInfo& s, bool integer_texture, float max_lod_bias) {
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  const bool min_linear = !integer_texture && s.min_filter == FilterMode::kLinear;
  info.magFilter = !integer_texture && s.mag_filter == FilterMode::kLinear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  info.minFilter = min_linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  // A texture of one level samples it whatever the mip filter says (Vulkan clamps the level).
  info.mipmapMode = !integer_texture && s.mip_filter == FilterMode::kLinear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = address(s.address[0]);
  info.addressModeV = address(s.address[1]);
  info.addressModeW = address(s.address[2]);
  info.mipLodBias = std::clamp(s.lod_bias, -max_lod_bias, max_lod_bias);
  info.minLod = s.min_lod;
  info.maxLod = std::max(s.min_lod, std::min(s.max_lod, VK_LOD_CLAMP_NONE));
  info.borderColor = integer_texture ? VK_BORDER_COLOR_INT_TRANSPARENT_BLACK : VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  return info;
}

VkPipelineColorBlendAttachmentState blend_state(const BlendTarget& b, bool integer_target) {
  VkPipelineColorBlendAttachmentState out{};
  out.blendEnable = b.enable && !integer_target ? VK_TRUE : VK_FALSE;  // Vulkan blends no integers, GL ignores it
  out.colorBlendOp = blend_op(b.color_op);
  out.alphaBlendOp = blend_op(b.alpha_op);
  out.srcColorBlendFactor = blend_factor(b.src);
  out.dstColorBlendFactor = blend_factor(b.dest);
  out.srcAlphaBlendFactor = blend_factor(b.src_alpha);
  out.dstAlphaBlendFactor = blend_factor(b.dest_alpha);
  out.colorWriteMask = b.write_mask & 0xFu;  // R, G, B, A: the same bits as FX's
  return out;
}

VkPrimitiveTopology vk_topology(Topology topology) {
  switch (topology) {
    case Topology::kPointList: return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    case Topology::kLineList: return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    case Topology::kLineStrip: return VK_PRIMITIVE_TOPOLOGY_LINE_STRIP;
    case Topology::kTriangleStrip: return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    case Topology::kTriangleList: break;
  }
  return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
}

}  // namespace pfx::fx::vulkan
