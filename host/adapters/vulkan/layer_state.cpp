#include "layer_state.hpp"

namespace pfx::vulkan_layer {

LayerState& state() {
  // Never destroyed: the application may present from a thread still running at exit.
  static LayerState* layer_state = new LayerState;
  return *layer_state;
}

Instance* find_instance(void* key) {
  auto found = state().instances.find(key);
  return found == state().instances.end() ? nullptr : found->second.get();
}

Device* find_device(void* key) {
  auto found = state().devices.find(key);
  return found == state().devices.end() ? nullptr : found->second.get();
}

}  // namespace pfx::vulkan_layer
