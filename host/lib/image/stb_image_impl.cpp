// Debian's stb_image (libstb-dev), compiled here rather than linked from libstb.a so that it is
// built with our sanitizers and fuzz instrumentation, and with only the formats no better library
// reads: TGA and BMP. JPEG goes through libjpeg-turbo (jpeg_decode.hpp), PNG through libpng.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_TGA
#define STBI_ONLY_BMP
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
// Far above any texture, and far below what overflows stb's own size arithmetic.
#define STBI_MAX_DIMENSIONS 16384
#include <stb/stb_image.h>
