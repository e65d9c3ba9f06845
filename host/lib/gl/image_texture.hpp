// Moving images between host memory (row 0 = top, host/lib/image) and GL textures (row 0 = bottom).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image.hpp"

namespace pfx::app {

// An immutable-storage RGBA16F texture holding img.rgba (converted to half by the GL).
uint32_t upload_color_texture(const Image& img);
// An R32F texture holding img.depth (linear view depth); 0 when the image has no depth.
uint32_t upload_depth_texture(const Image& img);
// The same into textures made before, of the image's size: a host that runs one picture size after
// another keeps its textures instead of making new ones each time.
void fill_color_texture(uint32_t texture, const Image& img);
void fill_depth_texture(uint32_t texture, const Image& img);
// An empty texture of one level in `internal_format` (GL_RGBA16F, GL_RGBA8...), nearest filtering.
uint32_t create_texture(uint32_t internal_format, int width, int height);
// An empty RGBA16F texture, e.g. for a chain's output.
uint32_t create_color_texture(int width, int height);
// Reads an RGBA texture back as floats into an Image of the given size (no depth).
Image download_color_texture(uint32_t texture, int width, int height);
void delete_texture(uint32_t texture);
// Reverses the row order of interleaved data (top-first <-> bottom-first).
std::vector<float> flip_rows(const std::vector<float>& data, int width, int height, int channels);

}  // namespace pfx::app
