// Debian's stb_image (libstb-dev) for the images of a preset's lookup textures: PNG, JPEG, BMP and
// TGA, read from memory (lr_images.cpp reads the file itself). The plugin's version script keeps
// these symbols private.
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
