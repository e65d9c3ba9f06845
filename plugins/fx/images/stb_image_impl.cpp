// Debian's stb_image (libstb-dev) for the images FX textures name with `source`: PNG, JPEG, BMP
// and TGA, read from memory (texture_image.cpp reads the file itself). Linked into the plugin, whose
// version script keeps these symbols private, and into the Vulkan runtime's test program.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_MAX_DIMENSIONS 16384
#include <stb/stb_image.h>
