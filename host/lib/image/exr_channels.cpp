#include "exr_channels.hpp"

#include <cctype>
#include <set>

namespace pfx::app::detail {
namespace {

std::string layer_of(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos ? std::string() : name.substr(0, dot);
}

std::string base_of(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  return dot == std::string::npos ? name : name.substr(dot + 1);
}

std::string join_name(const std::string& layer, const std::string& base) {
  return layer.empty() ? base : layer + "." + base;
}

bool equals_ignoring_case(const std::string& a, const char* b) {
  std::size_t i = 0;
  for (; i < a.size() && b[i]; ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return i == a.size() && !b[i];
}

const ExrChannelInfo* find(const ExrPartInfo& part, const std::string& name) {
  for (const auto& c : part.channels) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

bool has(const ExrPartInfo& part, const std::string& layer, const char* base) {
  return find(part, join_name(layer, base)) != nullptr;
}

// X, Y, Z of a position, normal or motion layer are axes: its Y is no luminance, its Z no depth.
bool is_vector_layer(const ExrPartInfo& part, const std::string& layer) { return has(part, layer, "X"); }

bool is_luminance_layer(const ExrPartInfo& part, const std::string& layer) {
  return has(part, layer, "Y") && !is_vector_layer(part, layer);
}

bool holds_color(const ExrPartInfo& part, const std::string& layer) {
  return has(part, layer, "R") || has(part, layer, "G") || has(part, layer, "B") || is_luminance_layer(part, layer);
}

std::vector<std::string> channels_in_layer(const ExrPartInfo& part, const std::string& layer) {
  std::vector<std::string> names;
  for (const auto& c : part.channels) {
    if (layer_of(c.name) == layer) names.push_back(c.name);
  }
  return names;
}

std::string list(const std::vector<std::string>& names) {
  constexpr std::size_t kMaxListed = 24;
  if (names.empty()) return "none";
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < kMaxListed; ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > kMaxListed) text += ", ... (" + std::to_string(names.size()) + " in all)";
  return text;
}

std::string channel_list(const ExrPartInfo& part) {
  std::vector<std::string> names;
  for (const auto& c : part.channels) names.push_back(c.name);
  return list(names);
}

std::string part_label(const std::vector<ExrPartInfo>& parts, int index) {
  const std::string& name = parts[static_cast<std::size_t>(index)].name;
  return name.empty() ? "part " + std::to_string(index) : "part '" + name + "'";
}

// "part 'beauty' (R, G, B), part 'depth' (Z)": what a multi-part file offers.
std::string part_list(const std::vector<ExrPartInfo>& parts) {
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    text += (i ? "; " : "") + part_label(parts, static_cast<int>(i)) +
            (parts[i].deep ? " (deep)" : " (" + channel_list(parts[i]) + ")");
  }
  return text;
}

int first_flat_part(const std::vector<ExrPartInfo>& parts) {
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!parts[i].deep) return static_cast<int>(i);
  }
  return -1;
}

void add_source(ExrChannelPlan* plan, const ExrChannelInfo& channel, int slot) {
  plan->sources.push_back({channel.name, slot, channel.x_sampling, channel.y_sampling});
}

// Depth candidates in one part, step by step: Z; a "depth" channel or the Z of a "depth" layer;
// the Z of any layer that is not a vector's.
const ExrChannelInfo* depth_in_part(const ExrPartInfo& part, int step) {
  for (const auto& c : part.channels) {
    const std::string layer = layer_of(c.name), base = base_of(c.name);
    switch (step) {
      case 0:
        if (c.name == "Z") return &c;
        break;
      case 1:
        if (equals_ignoring_case(base, "depth") || (base == "Z" && equals_ignoring_case(base_of(layer), "depth")))
          return &c;
        break;
      default:
        if (base == "Z" && !layer.empty() && !is_vector_layer(part, layer)) return &c;
        break;
    }
  }
  return nullptr;
}

constexpr int kDepthSteps = 3;

// The colour of `layer` ("" for the plain channels) of one part, with its alpha and depth.
bool plan_layer(const std::vector<ExrPartInfo>& parts, int index, const std::string& layer, ExrChannelPlan* plan,
                std::string* reason) {
  const ExrPartInfo& part = parts[static_cast<std::size_t>(index)];
  plan->part = index;
  plan->sources.clear();
  auto channel = [&](const char* base) { return find(part, join_name(layer, base)); };
  const ExrChannelInfo *r = channel("R"), *g = channel("G"), *b = channel("B");
  std::string what;
  if (r && g && b) {
    plan->color = ExrColorMode::Rgb;
    add_source(plan, *r, kSlotR);
    add_source(plan, *g, kSlotG);
    add_source(plan, *b, kSlotB);
    what = "R, G, B";
  } else if (is_luminance_layer(part, layer)) {
    const ExrChannelInfo *ry = channel("RY"), *by = channel("BY");
    add_source(plan, *channel("Y"), kSlotR);
    if (ry || by) {
      plan->color = ExrColorMode::LuminanceChroma;
      if (ry) add_source(plan, *ry, kSlotG);
      if (by) add_source(plan, *by, kSlotB);
      what = std::string("Y, ") + (ry ? "RY" : "no RY") + ", " + (by ? "BY" : "no BY") + " converted to RGB";
    } else {
      plan->color = ExrColorMode::Grey;
      what = "Y as grey";
    }
  } else if (r || g || b) {
    plan->color = ExrColorMode::Rgb;
    std::string present, missing;
    const ExrChannelInfo* rgb[3] = {r, g, b};
    const char* names[3] = {"R", "G", "B"};
    for (int i = 0; i < 3; ++i) {
      if (rgb[i]) add_source(plan, *rgb[i], kSlotR + i);
      std::string& text = rgb[i] ? present : missing;
      text += (text.empty() ? "" : ", ") + std::string(names[i]);
    }
    what = present + " (no " + missing + ": 0)";
  } else {
    const std::vector<std::string> names = channels_in_layer(part, layer);
    if (names.size() != 1) {
      *reason = (layer.empty() ? std::string("no colour channels") : "layer '" + layer + "' has no colour channels") +
                " (R, G, B or Y) and not a single channel to show as grey; " + part_label(parts, index) +
                " has channels " + channel_list(part);
      return false;
    }
    plan->color = ExrColorMode::Grey;
    add_source(plan, *find(part, names[0]), kSlotR);
    what = "'" + names[0] + "' as grey";
  }
  if (const ExrChannelInfo* a = channel("A")) {
    add_source(plan, *a, kSlotA);
    what += ", A";
  } else {
    what += " (no A: alpha 1)";
  }

  const ExrChannelInfo* z = nullptr;
  if (!layer.empty() && !is_vector_layer(part, layer)) z = channel("Z");
  for (int step = 0; !z && step < kDepthSteps; ++step) z = depth_in_part(part, step);
  plan->depth = z != nullptr;
  if (z) {
    add_source(plan, *z, kSlotZ);
    what += "; depth " + z->name;
  }

  plan->description = (parts.size() > 1 ? part_label(parts, index) + ", " : std::string()) +
                      (layer.empty() ? std::string() : "layer '" + layer + "': ") + what;
  return true;
}

// No layer named: the plain channels, else the one layer that holds colour, else a lone channel.
bool plan_default(const std::vector<ExrPartInfo>& parts, int index, ExrChannelPlan* plan, std::string* reason) {
  const ExrPartInfo& part = parts[static_cast<std::size_t>(index)];
  if (holds_color(part, "")) return plan_layer(parts, index, "", plan, reason);
  std::set<std::string> layers, color_layers;
  for (const auto& c : part.channels) {
    const std::string layer = layer_of(c.name);
    if (layer.empty()) continue;
    layers.insert(layer);
    if (holds_color(part, layer)) color_layers.insert(layer);
  }
  if (color_layers.size() == 1) return plan_layer(parts, index, *color_layers.begin(), plan, reason);
  if (part.channels.size() == 1) return plan_layer(parts, index, layer_of(part.channels[0].name), plan, reason);
  const std::string where = parts.size() > 1 ? part_label(parts, index) + " (the first part)" : std::string("it");
  if (color_layers.size() > 1) {
    *reason = "several layers hold colour and none is plain R, G, B or Y: " +
              list(std::vector<std::string>(color_layers.begin(), color_layers.end())) +
              "; choose one with --layer NAME";
  } else {
    *reason = "no colour channels (R, G, B or Y, plain or in a layer) and not a single channel to show as grey: " +
              where + " has channels " + channel_list(part);
    if (!layers.empty() || parts.size() > 1) *reason += "; choose a layer or part with --layer NAME";
  }
  if (parts.size() > 1) *reason += " (parts: " + part_list(parts) + ")";
  return false;
}

}  // namespace

bool plan_color_channels(const std::vector<ExrPartInfo>& parts, const std::string& layer, ExrChannelPlan* plan,
                         std::string* reason) {
  const int first = first_flat_part(parts);
  if (first < 0) {
    *reason = "deep OpenEXR images are not supported";
    return false;
  }
  if (layer.empty()) return plan_default(parts, first, plan, reason);
  // A part of that name first (multi-part files name their parts after their layers), then a layer.
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].name != layer) continue;
    if (parts[i].deep) {
      *reason = "part '" + layer + "' is a deep image, which is not supported";
      return false;
    }
    const int index = static_cast<int>(i);
    if (!channels_in_layer(parts[i], layer).empty()) return plan_layer(parts, index, layer, plan, reason);
    return plan_default(parts, index, plan, reason);
  }
  std::set<std::string> layers;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    for (const auto& c : parts[i].channels) {
      if (parts[i].deep) continue;
      if (layer_of(c.name) == layer) return plan_layer(parts, static_cast<int>(i), layer, plan, reason);
      if (!layer_of(c.name).empty()) layers.insert(layer_of(c.name));
    }
  }
  *reason = "no part or layer named '" + layer + "' (layers: " +
            list(std::vector<std::string>(layers.begin(), layers.end())) + ")";
  if (parts.size() > 1) *reason += " (parts: " + part_list(parts) + ")";
  return false;
}

bool plan_depth_channel(const std::vector<ExrPartInfo>& parts, ExrChannelPlan* plan, std::string* reason) {
  const int first = first_flat_part(parts);
  if (first < 0) {
    *reason = "deep OpenEXR images are not supported";
    return false;
  }
  const ExrChannelInfo* chosen = nullptr;
  int index = first;
  for (int step = 0; !chosen && step < kDepthSteps; ++step) {
    for (std::size_t i = 0; !chosen && i < parts.size(); ++i) {
      if (parts[i].deep) continue;
      chosen = depth_in_part(parts[i], step);
      index = static_cast<int>(i);
    }
  }
  const ExrPartInfo& part = parts[static_cast<std::size_t>(first)];
  if (!chosen) {
    index = first;
    chosen = find(part, "R");
    if (!chosen) chosen = find(part, "Y");
    if (!chosen && part.channels.size() == 1) chosen = &part.channels[0];
  }
  if (!chosen) {
    *reason = "no depth channel: looked for Z, a 'depth' channel, the Z of a layer, R, Y or a lone channel; it has " +
              (parts.size() > 1 ? "parts: " + part_list(parts) : "channels " + channel_list(part));
    return false;
  }
  plan->part = index;
  plan->sources.clear();
  add_source(plan, *chosen, kSlotZ);
  plan->color = ExrColorMode::None;
  plan->depth = true;
  plan->description = "depth " + chosen->name + (parts.size() > 1 ? " of " + part_label(parts, index) : "");
  return true;
}

}  // namespace pfx::app::detail
