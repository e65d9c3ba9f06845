// The OBJ importer's entry points and the pipeline in order (the stages: obj_importer.hpp).
#include "obj_import.hpp"

#include <atomic>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "obj_file.hpp"
#include "obj_importer.hpp"
#include "obj_normals.hpp"
#include "obj_parallel.hpp"
#include "obj_split.hpp"

namespace pfx_obj {

bool Importer::run(std::string_view text, ObjMesh* out, std::string* error) {
  out_ = out;
  *out = ObjMesh{};
  StageClock clock(&out->stages);
  report(0.0f);
  clock.time("parse", true, [&] { parse(text); });
  bool ok = true;
  clock.time("plan", false, [&] { ok = plan(error); });
  if (!ok) return false;
  clock.time("resolve", true, [&] { resolve_all(threads_); });
  if (!first_resolve_error(error)) return false;
  clock.time("gather", false, [&] { gather(); });
  report(0.7f);
  clock.time("layout", false, [&] { layout_triangles(); });
  number_and_triangulate(&clock);
  assemble(&clock);
  return true;
}

// The stages after the index array: vertex arrays and bounds, normals, warnings.
void Importer::assemble(StageClock* clock) {
  report(0.85f);
  clock->time("vertices, bounds", true, [&] { fill_vertices(); });
  clock->time("normals", true, [&] { generate_normals(keys_, out_->positions, out_->indices, options_.pool, threads_, &out_->normals); });
  clock->time("warnings", false, [&] { finish(); });
  report(1.0f);
}

size_t Importer::chunk_count(size_t bytes) const {
  if (options_.chunk_bytes > 0) return std::max<size_t>(1, (bytes + options_.chunk_bytes - 1) / options_.chunk_bytes);
  // About eight chunks per thread of 1 to 4 MB each, their count a multiple of the thread count
  // so that the threads, taking equal chunks in turn, finish together. Not larger: the chunks
  // between parse and numbering each hold a chunk's corners (about its size in bytes), and with
  // 32 MB chunks a two-thread import of 487 MB faulted in three slots of 27 MB of them, more than
  // the vertex arrays took over, the rest unmapped at the end (245 against 221 ms with 4 MB,
  // medians of 21; on one thread 416 against 409 ms; at 99 MB the same either way).
  const size_t chunk_bytes = std::clamp<size_t>(bytes / (size_t{threads_} * 8), 1 << 20, 4 << 20);
  size_t chunks = (bytes + chunk_bytes - 1) / chunk_bytes;
  if (chunks > 1) chunks = (chunks + threads_ - 1) / threads_ * threads_;
  return std::max<size_t>(1, chunks);
}

void Importer::parse(std::string_view text) {
  texts_ = split_at_line_ends(text, chunk_count(text.size()));
  chunks_.assign(texts_.size(), ChunkData{});
  std::atomic<size_t> bytes_done{0};
  const double total = std::max<size_t>(1, text.size());
  run_parallel(
      options_.pool, threads_, texts_.size(),
      [&](size_t c, unsigned) {
        parse_one(c, 0);
        bytes_done += texts_[c].size();
      },
      [&] { report(static_cast<float>(0.6 * bytes_done.load() / total)); });
}

// Chunk c's text into chunks_[c], its file pages then dropped where they are the importer's own.
void Importer::parse_one(size_t c, size_t reserve_bytes) {
  parse_chunk(texts_[c], c == 0, options_.plain_lines, &chunks_[c], reserve_bytes);
  if (release_text_) release_read_pages(texts_[c]);
}

namespace {

// import_obj_text, told whether the text is import_obj_file's own mapping of the file (see
// release_read_pages).
bool import_text(std::string_view text, const std::string& name, const std::string& directory,
                 const ImportOptions& options, bool text_is_file_mapping, ObjMesh* out, std::string* error) {
  // Whatever way the import ends, the pages it kept for reuse go back (obj_spare_mappings.hpp).
  struct ReleaseSpares {
    ~ReleaseSpares() { release_spare_mappings(); }
  } release_spares;
  try {
    // Chunk by chunk, unless the file needs the stages (then from the start).
    if (options.streamed) {
      const Importer::Outcome outcome =
          Importer(name, directory, options, text_is_file_mapping).run_streamed(text, out, error);
      if (outcome != Importer::Outcome::kUseStages) return outcome == Importer::Outcome::kDone;
      release_spare_mappings();
    }
    return Importer(name, directory, options, text_is_file_mapping).run(text, out, error);
  } catch (const std::bad_alloc&) {
    *error = name + ": out of memory";
  } catch (const std::exception& e) {
    *error = std::string(e.what()).rfind(name, 0) == 0 ? e.what() : name + ": " + e.what();
  }
  *out = ObjMesh{};
  return false;
}

}  // namespace

bool import_obj_text(std::string_view text, const std::string& name, const std::string& directory,
                     const ImportOptions& options, ObjMesh* out, std::string* error) {
  return import_text(text, name, directory, options, false, out, error);
}

bool import_obj_file(const std::string& path, const ImportOptions& options, ObjMesh* out, std::string* error) {
  FileBytes file;
  if (!file.open(path, error)) return false;
  const std::string directory = std::filesystem::path(path).parent_path().string();
  return import_text(file.bytes(), path, directory.empty() ? "." : directory, options, file.mapped(), out, error);
}

}  // namespace pfx_obj
