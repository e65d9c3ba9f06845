#include "gpu_lists.hpp"

#include <pfx/cpp/gl_program.hpp>

#include <algorithm>

#include "tiledlights_shaders.hpp"

namespace pfx_tiledlights {
namespace {

namespace sh = shaders;

}  // namespace

GpuLists::~GpuLists() {
  glDeleteProgram(tiled_);
  glDeleteProgram(clustered_);
  glDeleteProgram(prefix_sum_);
  glDeleteBuffers(1, &stats_);
  for (Slot& slot : slots_) {
    glDeleteBuffers(1, &slot.heads);
    glDeleteBuffers(1, &slot.indices);
  }
}

bool GpuLists::create(std::string* error) {
  struct Program {
    GLuint* target;
    const char* name;
    std::string source;
  } programs[3] = {{&tiled_, "tiled", sh::tiled_compute()},
                   {&clustered_, "clustered", sh::clustered_compute()},
                   {&prefix_sum_, "prefix sum", sh::prefix_sum_compute()}};
  for (Program& p : programs) {
    std::string message;
    *p.target = pfx::gl::build_compute_program(p.source.c_str(), &message);
    if (!*p.target) {
      *error = std::string("shader '") + p.name + "': " + message;
      return false;
    }
  }
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment_);
  glCreateBuffers(1, &stats_);
  glNamedBufferStorage(stats_, 16, nullptr, GL_DYNAMIC_STORAGE_BIT);
  return true;
}

bool GpuLists::reserve_indices(Slot* slot, uint64_t needed, uint64_t budget) {
  needed = std::max<uint64_t>(needed, 1);
  if (needed > budget) return false;
  if (slot->indices && slot->index_capacity >= needed) return true;
  // Half again, within the budget: a slowly rising count does not reallocate every frame.
  const uint64_t capacity = std::min(budget, std::max(needed, slot->index_capacity + slot->index_capacity / 2));
  glDeleteBuffers(1, &slot->indices);
  glCreateBuffers(1, &slot->indices);
  glNamedBufferStorage(slot->indices, static_cast<GLsizeiptr>(capacity * 4), nullptr, 0);
  slot->index_capacity = capacity;
  return true;
}

void GpuLists::dispatch(GLuint program, int phase, const ListShape& shape) {
  glProgramUniform1i(program, sh::U_PHASE, phase);
  glUseProgram(program);
  glDispatchCompute(static_cast<GLuint>(shape.tiles_x), static_cast<GLuint>(shape.tiles_y), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

bool GpuLists::build(int slot_index, const ListShape& shape, uint64_t bound, uint64_t budget, std::string* error) {
  Slot& slot = slots_[slot_index];
  const size_t alignment = static_cast<size_t>(std::max(alignment_, 4));
  const uint64_t lists = shape.lists();
  list_heads_bytes_ = lists * 8;
  bounds_offset_ = align_up(list_heads_bytes_, alignment);
  bounds_bytes_ = uint64_t(shape.tiles_x) * shape.tiles_y * 8;
  const size_t heads_needed = bounds_offset_ + bounds_bytes_;
  if (heads_needed > slot.heads_bytes) {
    glDeleteBuffers(1, &slot.heads);
    glCreateBuffers(1, &slot.heads);
    glNamedBufferStorage(slot.heads, static_cast<GLsizeiptr>(heads_needed), nullptr, 0);
    slot.heads_bytes = heads_needed;
  }
  // The common case: the bound fits, so the buffer is sized before the GPU counts.
  const bool sized = reserve_indices(&slot, bound, budget);

  const GLuint cull = program(shape.clustered);
  const GLuint zero = 0;
  glClearNamedBufferData(stats_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_HEADS, slot.heads, 0,
                    static_cast<GLsizeiptr>(list_heads_bytes_));
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_BOUNDS, slot.heads, static_cast<GLintptr>(bounds_offset_),
                    static_cast<GLsizeiptr>(bounds_bytes_));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, sh::SSBO_STATS, stats_);
  if (slot.indices) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, sh::SSBO_INDICES, slot.indices);
  dispatch(cull, sh::PHASE_COUNT, shape);
  glProgramUniform1ui(prefix_sum_, sh::U_LIST_COUNT, static_cast<GLuint>(lists));
  glUseProgram(prefix_sum_);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  if (!sized) {
    // The bound is past the budget: the exact total decides (a wait for the GPU, this frame only
    // while the scene stays like this).
    ++readbacks_;
    GLuint entries = 0;
    glGetNamedBufferSubData(stats_, 0, 4, &entries);
    // The prefix sum saturates at 2^32 - 1: that many is past any budget.
    if (entries == 0xffffffffu || !reserve_indices(&slot, entries, budget)) {
      glUseProgram(0);
      *error = "the light lists need " + (entries == 0xffffffffu ? std::string("4294967295 or more")
                                                                  : std::to_string(entries)) +
               " indices, more than the " + std::to_string(budget) +
               " that max_list_indices and the GL's shader storage block size allow";
      return false;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, sh::SSBO_INDICES, slot.indices);
  }
  glProgramUniform1ui(cull, sh::U_INDEX_CAPACITY,
                      static_cast<GLuint>(std::min<uint64_t>(slot.index_capacity, 0xffffffffu)));
  dispatch(cull, sh::PHASE_FILL, shape);
  glUseProgram(0);
  frame_indices_ = slot.index_capacity;
  return true;
}

void GpuLists::bind_for_shading(int slot_index) const {
  const Slot& slot = slots_[slot_index];
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_HEADS, slot.heads, 0,
                    static_cast<GLsizeiptr>(list_heads_bytes_));
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, sh::SSBO_INDICES, slot.indices, 0,
                    static_cast<GLsizeiptr>(frame_indices_ * 4));
}

GpuLists::Stats GpuLists::read_stats() const {
  GLuint counters[4] = {};
  glGetNamedBufferSubData(stats_, 0, sizeof counters, counters);
  Stats stats;
  stats.entries = counters[0];
  stats.longest = counters[1];
  stats.inconsistent = counters[2];
  return stats;
}

uint64_t GpuLists::bytes() const {
  uint64_t total = 16;
  for (const Slot& slot : slots_) total += slot.heads_bytes + slot.index_capacity * 4;
  return total;
}

}  // namespace pfx_tiledlights
