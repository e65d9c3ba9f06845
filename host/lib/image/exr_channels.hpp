// Internal to read_exr: which of a file's channels become the image, decided from the channel
// names alone (exr_io.hpp states the rules for users). Kept apart from the pixel reading so the
// rules can be read, and tested, as one piece.
#pragma once

#include <string>
#include <vector>

namespace pfx::app::detail {

struct ExrChannelInfo {
  std::string name;  // full name, layer included ("diffuse.R")
  int x_sampling = 1;
  int y_sampling = 1;
};

struct ExrPartInfo {
  std::string name;  // empty when the part has none (single-part files)
  bool deep = false;
  std::vector<ExrChannelInfo> channels;  // sorted by name, as OpenEXR stores them
};

// The scratch slots a pixel is decoded into before it becomes RGBA (+ depth).
enum ExrSlot { kSlotR = 0, kSlotG, kSlotB, kSlotA, kSlotZ, kSlotCount };

// How the colour slots become RGB.
enum class ExrColorMode {
  Rgb,              // R, G, B as they are (a missing one stays at its fill, 0)
  Grey,             // slot R holds one value shown as grey
  LuminanceChroma,  // slots R, G, B hold Y, RY, BY
  None,             // depth only
};

struct ExrChannelPlan {
  struct Source {
    std::string channel;
    int slot = 0;
    int x_sampling = 1;
    int y_sampling = 1;
  };
  int part = 0;
  std::vector<Source> sources;
  ExrColorMode color = ExrColorMode::Rgb;
  bool depth = false;  // slot Z is read
  // What was taken, in words, for logs and reports ("layer 'diffuse': R, G, B (no A: alpha 1)").
  std::string description;
};

// Colour for --input: `layer` empty or the name of a part or layer (exr_io.hpp).
bool plan_color_channels(const std::vector<ExrPartInfo>& parts, const std::string& layer, ExrChannelPlan* plan,
                         std::string* reason);

// One channel as linear depth, for --depth.
bool plan_depth_channel(const std::vector<ExrPartInfo>& parts, ExrChannelPlan* plan, std::string* reason);

}  // namespace pfx::app::detail
