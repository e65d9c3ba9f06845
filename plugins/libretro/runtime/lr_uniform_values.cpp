#include "lr_uniform_values.hpp"

#include <cstring>

namespace pfx_libretro {

using namespace pfx::libretro;

namespace {

// BrightnessNits with the HDR pipeline off: RetroArch's default paper white.
constexpr float kSdrPaperWhiteNits = 200.0f;

template <typename T>
void put(std::vector<unsigned char>& bytes, std::uint32_t offset, const T* values, std::size_t count) {
  if (offset + sizeof(T) * count <= bytes.size()) std::memcpy(bytes.data() + offset, values, sizeof(T) * count);
}

void put_size(std::vector<unsigned char>& bytes, std::uint32_t offset, PixelSize size) {
  const float v[4] = {static_cast<float>(size.width), static_cast<float>(size.height),
                      1.0f / static_cast<float>(size.width), 1.0f / static_cast<float>(size.height)};
  put(bytes, offset, v, 4);
}

PixelSize indexed(const std::vector<PixelSize>* sizes, int index) {
  return sizes && index >= 0 && static_cast<std::size_t>(index) < sizes->size()
             ? (*sizes)[static_cast<std::size_t>(index)]
             : PixelSize{};
}

}  // namespace

PixelSize semantic_size(const Semantic& semantic, const PassValues& values) {
  switch (semantic.kind) {
    case SemanticKind::kOutputSize:
      return values.output;
    case SemanticKind::kFinalViewportSize:
      return values.viewport;
    case SemanticKind::kOriginalSize:
    case SemanticKind::kOriginalHistorySize:
      return values.original;
    case SemanticKind::kSourceSize:
      return values.source;
    case SemanticKind::kPassOutputSize:
    case SemanticKind::kPassFeedbackSize:
      return indexed(values.pass_sizes, semantic.index);
    case SemanticKind::kUserSize:
      return indexed(values.lookup_sizes, semantic.index);
    default:
      return PixelSize{};
  }
}

void write_block_values(const ReflectedBlock& block, const PassValues& values, std::vector<unsigned char>& bytes) {
  for (const ReflectedMember& member : block.members) {
    const std::uint32_t at = member.offset;
    const int index = member.semantic.index;
    switch (member.semantic.kind) {
      case SemanticKind::kMvp:
        put(bytes, at, values.mvp, 16);
        break;
      case SemanticKind::kOutputSize:
      case SemanticKind::kFinalViewportSize:
        put_size(bytes, at, semantic_size(member.semantic, values));
        break;
      case SemanticKind::kFrameCount:
        put(bytes, at, &values.frame_count, 1);
        break;
      case SemanticKind::kFrameDirection:
        put(bytes, at, &values.frame_direction, 1);
        break;
      case SemanticKind::kFrameTimeDelta:
        put(bytes, at, &values.frame_time_delta_us, 1);
        break;
      case SemanticKind::kOriginalFps:
        put(bytes, at, &values.original_fps, 1);
        break;
      case SemanticKind::kOriginalAspect:
      case SemanticKind::kOriginalAspectRotated: {  // no rotation: both the same
        const float aspect = static_cast<float>(values.original.width) / static_cast<float>(values.original.height);
        put(bytes, at, &aspect, 1);
        break;
      }
      case SemanticKind::kRotation: {
        const std::uint32_t none = 0;
        put(bytes, at, &none, 1);
        break;
      }
      case SemanticKind::kTotalSubFrames:
      case SemanticKind::kCurrentSubFrame: {  // one frame shown once: one sub-frame, the first
        const std::uint32_t one = 1;
        put(bytes, at, &one, 1);
        break;
      }
      // pfx hands effects display-referred SDR frames and wants them back so: RetroArch's HDR
      // pipeline off, which every shader reading these names takes as pass-through.
      case SemanticKind::kHdrMode:
      case SemanticKind::kSubpixelLayout:
      case SemanticKind::kExpandGamut: {
        const std::uint32_t off = 0;
        put(bytes, at, &off, 1);
        break;
      }
      case SemanticKind::kScanlines:
      case SemanticKind::kInverseTonemap:
      case SemanticKind::kHdr10: {
        const float off = 0.0f;
        put(bytes, at, &off, 1);
        break;
      }
      case SemanticKind::kBrightnessNits: {
        put(bytes, at, &kSdrPaperWhiteNits, 1);
        break;
      }
      case SemanticKind::kParameter: {
        const float v = values.parameters && index >= 0 && static_cast<std::size_t>(index) < values.parameters->size()
                            ? static_cast<float>((*values.parameters)[static_cast<std::size_t>(index)])
                            : 0.0f;
        put(bytes, at, &v, 1);
        break;
      }
      case SemanticKind::kOriginalSize:
      case SemanticKind::kOriginalHistorySize:
      case SemanticKind::kSourceSize:
      case SemanticKind::kPassOutputSize:
      case SemanticKind::kPassFeedbackSize:
      case SemanticKind::kUserSize:
        put_size(bytes, at, semantic_size(member.semantic, values));
        break;
      default:
        break;  // textures are not block members
    }
  }
}

}  // namespace pfx_libretro
