#include "layer_test_support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>

#include <vulkan/vulkan.h>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#endif

namespace pfx::test {

void add_sanitizer_runtime(std::vector<std::string>* argv) {
#if defined(__SANITIZE_ADDRESS__)
  // vkcube is a C program, and AddressSanitizer's interceptor of C++ throws finds the real
  // __cxa_throw only in libraries loaded when it starts: the layer's code that throws and catches
  // (a preset's JSON parse error) needs the C++ library preloaded too.
  argv->push_back("LD_PRELOAD=" + sanitizer_runtime() + " " + loaded_library("libstdc++.so"));
  const char* asan_options = std::getenv("ASAN_OPTIONS");
  argv->push_back(std::string("ASAN_OPTIONS=") + (asan_options ? asan_options : "") + ":detect_leaks=0");
#else
  (void)argv;
#endif
}

std::string lavapipe_device_name() {
#if defined(__SANITIZE_ADDRESS__)
  // The loader unloads lavapipe at vkDestroyInstance, and a block lavapipe keeps in its globals for
  // the process's life then points nowhere and is reported as a leak at exit (128 bytes, "<unknown
  // module>"): kept mapped, LeakSanitizer sees it held (bridge_c_test.c does the same).
  (void)dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
#endif
  VkInstanceCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  VkInstance instance = VK_NULL_HANDLE;
  REQUIRE(vkCreateInstance(&info, nullptr, &instance) == VK_SUCCESS);
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::string name;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(device, &properties);
    if (properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) name = properties.deviceName;
  }
  vkDestroyInstance(instance, nullptr);
  return name;
}

void write_explicit_manifest(const ScratchFolder& folder) {
  std::ofstream(folder.file("pfx_explicit.json"))
      << "{\"file_format_version\": \"1.0.0\", \"layer\": {\"name\": \"VK_LAYER_PFX_post_effects\", \"type\": "
         "\"GLOBAL\", \"library_path\": \"" PFX_LAYER_LIBRARY "\", \"api_version\": \"1.3.0\", "
         "\"implementation_version\": \"1\", \"description\": \"pfx\", \"functions\": {\"vkGetInstanceProcAddr\": "
         "\"pfx_layer_GetInstanceProcAddr\", \"vkGetDeviceProcAddr\": \"pfx_layer_GetDeviceProcAddr\"}}}\n";
}

}  // namespace pfx::test
