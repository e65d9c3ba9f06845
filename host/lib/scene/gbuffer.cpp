#include "gbuffer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glad/gl.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <pfx/cpp/gl_program.hpp>

#include "frame_description.hpp"
#include "scene_camera.hpp"

namespace pfx::app {
namespace {

constexpr int kMapSlots = 4;  // albedo, emissive, alpha, normal: texture units 0..3

const char* kVertexShader = R"(#version 450 core
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 0) uniform mat4 view_projection;
layout(location = 1) uniform mat4 view;
out vec3 world_position;
out vec3 world_normal;
out vec2 uv;
out float view_depth;
void main() {
  world_position = in_position;
  world_normal = in_normal;
  uv = in_uv;
  // Affine in view space, so the interpolated value is exact: no depth-buffer precision loss.
  view_depth = -(view * vec4(in_position, 1.0)).z;
  gl_Position = view_projection * vec4(in_position, 1.0);
}
)";

// Texture slots: bit i of `maps` says whether unit i holds the material's map.
const char* kFragmentShader = R"(#version 450 core
in vec3 world_position;
in vec3 world_normal;
in vec2 uv;
in float view_depth;
layout(location = 2) uniform vec3 albedo_color;
layout(location = 3) uniform vec3 emissive_color;
layout(location = 4) uniform vec3 sky;
layout(location = 5) uniform int maps;
layout(location = 6) uniform vec3 ground;
layout(location = 7) uniform vec3 key_direction;
layout(location = 8) uniform vec3 key_radiance;
layout(location = 9) uniform float alpha_cutoff;
layout(binding = 0) uniform sampler2D albedo_map;
layout(binding = 1) uniform sampler2D emissive_map;
layout(binding = 2) uniform sampler2D alpha_map;
layout(binding = 3) uniform sampler2D normal_map;
layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_depth;
layout(location = 2) out vec4 out_normal;
layout(location = 3) out vec4 out_albedo;
layout(location = 4) out vec4 out_emissive;

// The surface's tangent frame from the screen-space change of position and UV, so meshes need no
// tangent attribute: T and B are the directions in which U and V grow, scaled alike.
// The derivatives are taken before any fragment of the quad is discarded.
vec3 mapped_normal(vec3 n, vec3 m, vec3 dp_dx, vec3 dp_dy, vec2 duv_dx, vec2 duv_dy) {
  vec3 across_y = cross(dp_dy, n), across_x = cross(n, dp_dx);
  vec3 t = across_y * duv_dx.x + across_x * duv_dy.x;
  vec3 b = across_y * duv_dx.y + across_x * duv_dy.y;
  float size = max(dot(t, t), dot(b, b));
  if (!(size > 0.0)) return n;  // no UV change over the pixel: nothing to map
  vec3 mapped = mat3(t * inversesqrt(size), b * inversesqrt(size), n) * m;
  float length2 = dot(mapped, mapped);
  return length2 > 0.0 ? mapped * inversesqrt(length2) : n;
}

void main() {
  vec3 dp_dx = dFdx(world_position), dp_dy = dFdy(world_position);
  vec2 duv_dx = dFdx(uv), duv_dy = dFdy(uv);
  bool cut = (maps & 4) != 0 && texture(alpha_map, uv).a < alpha_cutoff;
  vec3 albedo = albedo_color;
  if ((maps & 1) != 0) albedo *= texture(albedo_map, uv).rgb;
  vec3 emissive = emissive_color;
  if ((maps & 2) != 0) emissive *= texture(emissive_map, uv).rgb;
  // Two-sided: a back face seen from inside still gets a normal facing the camera.
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;
  if ((maps & 8) != 0)
    n = mapped_normal(n, texture(normal_map, uv).xyz * 2.0 - 1.0, dp_dx, dp_dy, duv_dx, duv_dy);
  vec3 light = mix(ground, sky, 0.5 + 0.5 * n.y) + key_radiance * max(dot(n, key_direction), 0.0);
  out_color = vec4(emissive + light * albedo, 1.0);
  out_depth = view_depth;
  out_normal = vec4(n, 0.0);
  out_albedo = vec4(albedo, 1.0);
  out_emissive = vec4(emissive, 1.0);
  if (cut) discard;
}
)";

GLuint make_target(GLenum format, int width, int height) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

void set_matrix(GLuint program, int location, const glm::dmat4& m) {
  const glm::mat4 f(m);
  glProgramUniformMatrix4fv(program, location, 1, GL_FALSE, glm::value_ptr(f));
}

}  // namespace

struct SceneRenderer::GpuMesh {
  GLuint vertex_array = 0, vertices = 0, indices = 0;
  GLsizei index_count = 0;
  int material = 0;
  ~GpuMesh() {
    glDeleteVertexArrays(1, &vertex_array);
    glDeleteBuffers(1, &vertices);
    glDeleteBuffers(1, &indices);
  }
};

std::unique_ptr<SceneRenderer> SceneRenderer::create(const Scene& scene, std::string* error) {
  if (!validate_scene(scene, error)) return nullptr;
  std::unique_ptr<SceneRenderer> renderer(new SceneRenderer);
  renderer->program_ = pfx::gl::build_program(
      std::array<GLenum, 2>{GL_VERTEX_SHADER, GL_FRAGMENT_SHADER}.data(),
      std::array<const char*, 2>{kVertexShader, kFragmentShader}.data(), 2, error);
  if (!renderer->program_) {
    if (error) *error = "scene shader: " + *error;
    return nullptr;
  }
  renderer->ambient_ = scene.ambient;
  renderer->ground_ = scene.ground_ambient;
  renderer->key_light_ = scene.key_light;
  renderer->background_ = scene.background;
  renderer->materials_ = scene.materials;
  for (const Texture& texture : scene.textures) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &name);
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(texture.width, texture.height))));
    glTextureStorage2D(name, levels, GL_RGBA16F, texture.width, texture.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(name, 0, 0, 0, texture.width, texture.height, GL_RGBA, GL_FLOAT, texture.rgba.data());
    glGenerateTextureMipmap(name);
    glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(name, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(name, GL_TEXTURE_WRAP_T, GL_REPEAT);
    renderer->textures_.push_back(name);
  }
  for (const Mesh& mesh : scene.meshes) {
    auto gpu = std::make_unique<GpuMesh>();
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 8);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const float vertex[8] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z, mesh.normals[v].x,
                               mesh.normals[v].y,   mesh.normals[v].z,   mesh.uvs[v].x,       mesh.uvs[v].y};
      interleaved.insert(interleaved.end(), vertex, vertex + 8);
    }
    glCreateBuffers(1, &gpu->vertices);
    glNamedBufferStorage(gpu->vertices, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                         interleaved.data(), 0);
    glCreateBuffers(1, &gpu->indices);
    glNamedBufferStorage(gpu->indices, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                         mesh.indices.data(), 0);
    glCreateVertexArrays(1, &gpu->vertex_array);
    glVertexArrayVertexBuffer(gpu->vertex_array, 0, gpu->vertices, 0, 8 * sizeof(float));
    glVertexArrayElementBuffer(gpu->vertex_array, gpu->indices);
    const GLuint sizes[3] = {3, 3, 2}, offsets[3] = {0, 3, 6};
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexArrayAttrib(gpu->vertex_array, a);
      glVertexArrayAttribFormat(gpu->vertex_array, a, static_cast<GLint>(sizes[a]), GL_FLOAT, GL_FALSE,
                                offsets[a] * sizeof(float));
      glVertexArrayAttribBinding(gpu->vertex_array, a, 0);
    }
    gpu->index_count = static_cast<GLsizei>(mesh.indices.size());
    gpu->material = mesh.material;
    renderer->meshes_.push_back(std::move(gpu));
  }
  return renderer;
}

SceneRenderer::~SceneRenderer() {
  meshes_.clear();
  for (GLuint texture : textures_) glDeleteTextures(1, &texture);
  release_targets();
  glDeleteProgram(program_);
}

void SceneRenderer::release_targets() {
  const GLuint textures[5] = {color_, depth_, normal_, albedo_, emissive_};
  glDeleteTextures(5, textures);
  glDeleteRenderbuffers(1, &depth_buffer_);
  glDeleteFramebuffers(1, &framebuffer_);
  color_ = depth_ = normal_ = albedo_ = emissive_ = depth_buffer_ = framebuffer_ = 0;
  width_ = height_ = 0;
}

void SceneRenderer::allocate(int width, int height) {
  release_targets();
  color_ = make_target(GL_RGBA16F, width, height);
  depth_ = make_target(GL_R32F, width, height);
  normal_ = make_target(GL_RGBA16F, width, height);
  albedo_ = make_target(GL_RGBA16F, width, height);
  emissive_ = make_target(GL_RGBA16F, width, height);
  glCreateRenderbuffers(1, &depth_buffer_);
  glNamedRenderbufferStorage(depth_buffer_, GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &framebuffer_);
  const GLuint targets[5] = {color_, depth_, normal_, albedo_, emissive_};
  GLenum buffers[5];
  for (int i = 0; i < 5; ++i) {
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0 + i, targets[i], 0);
    buffers[i] = GL_COLOR_ATTACHMENT0 + i;
  }
  glNamedFramebufferDrawBuffers(framebuffer_, 5, buffers);
  glNamedFramebufferRenderbuffer(framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer_);
  width_ = width;
  height_ = height;
}

void SceneRenderer::render(const Camera& camera, int width, int height) {
  if (width != width_ || height != height_) allocate(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const GLfloat background[4] = {background_.r, background_.g, background_.b, 1.0f};
  const GLfloat far_depth[4] = {INFINITY, 0, 0, 0};
  const GLfloat zero[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, background);
  glClearBufferfv(GL_COLOR, 1, far_depth);
  for (int i = 2; i < 5; ++i) glClearBufferfv(GL_COLOR, i, zero);
  const GLfloat one = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &one);

  const glm::dmat4 view = view_matrix(camera);
  set_matrix(program_, 0, projection_matrix(camera, double(width) / double(height)) * view);
  set_matrix(program_, 1, view);
  glProgramUniform3f(program_, 4, ambient_.r, ambient_.g, ambient_.b);
  glProgramUniform3f(program_, 6, ground_.r, ground_.g, ground_.b);
  const float key_length = glm::length(key_light_.direction);
  const glm::vec3 key = key_length > 0 ? key_light_.direction / key_length : glm::vec3(0.0f);
  glProgramUniform3f(program_, 7, key.x, key.y, key.z);
  glProgramUniform3f(program_, 8, key_light_.radiance.r, key_light_.radiance.g, key_light_.radiance.b);
  glUseProgram(program_);
  for (const auto& mesh : meshes_) {
    const Material& material = materials_[static_cast<size_t>(mesh->material)];
    glProgramUniform3f(program_, 2, material.albedo.r, material.albedo.g, material.albedo.b);
    glProgramUniform3f(program_, 3, material.emissive.r, material.emissive.g, material.emissive.b);
    glProgramUniform1f(program_, 9, material.alpha_cutoff);
    const int slots[kMapSlots] = {material.albedo_texture, material.emissive_texture, material.alpha_texture,
                                  material.normal_texture};
    int maps = 0;
    for (int unit = 0; unit < kMapSlots; ++unit)
      if (slots[unit] >= 0) {
        maps |= 1 << unit;
        glBindTextureUnit(static_cast<GLuint>(unit), textures_[static_cast<size_t>(slots[unit])]);
      }
    glProgramUniform1i(program_, 5, maps);
    glBindVertexArray(mesh->vertex_array);
    glDrawElements(GL_TRIANGLES, mesh->index_count, GL_UNSIGNED_INT, nullptr);
  }
  for (int unit = 0; unit < kMapSlots; ++unit) glBindTextureUnit(static_cast<GLuint>(unit), 0);
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

pfx::host::FrameTextures SceneRenderer::textures() const {
  pfx::host::FrameTextures t;
  t.color = color_;
  t.depth = depth_;
  t.normal = normal_;
  t.albedo = albedo_;
  t.emissive = emissive_;
  return t;
}

pfx_frame make_scene_frame(const Scene& scene, const Camera& camera, int width, int height) {
  pfx_frame frame = describe_frame(width, height, kEveryInput, PFX_DEPTH_LINEAR, to_pfx_camera(camera, width, height));
  frame.lights = scene.lights.empty() ? nullptr : scene.lights.data();
  frame.light_count = static_cast<uint32_t>(scene.lights.size());
  return frame;
}

}  // namespace pfx::app
