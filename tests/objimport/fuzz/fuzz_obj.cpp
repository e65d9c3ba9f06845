// libFuzzer target for the OBJ and MTL parsers. Every input must import or fail with a message
// naming the file, without a crash or an out-of-bounds read (the target is built with
// AddressSanitizer), and the import cut into chunks, on one thread or three, must give exactly what
// one chunk gives.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <pfx/host/thread_pool.hpp>

#include "obj_import.hpp"
#include "obj_mtl.hpp"

namespace {

bool same(const pfx_obj::ObjMesh& a, const pfx_obj::ObjMesh& b) {
  auto same_floats = [](const pfx_obj::BigVector<float>& x, const pfx_obj::BigVector<float>& y) {
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
      if (!(x[i] == y[i]) && !(x[i] != x[i] && y[i] != y[i])) return false;
    return true;
  };
  return same_floats(a.positions, b.positions) && same_floats(a.normals, b.normals) &&
         same_floats(a.texcoords, b.texcoords) && same_floats(a.colors, b.colors) && a.indices == b.indices &&
         a.submeshes.size() == b.submeshes.size() && a.warnings == b.warnings && a.warning_total == b.warning_total &&
         a.faces == b.faces && a.lines_skipped == b.lines_skipped && a.points_skipped == b.points_skipped;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  pfx_obj::ImportOptions sequential;
  sequential.threads = 1;
  sequential.chunk_bytes = size_t{1} << 30;
  pfx_obj::ObjMesh one;
  std::string error_one;
  const bool ok_one = pfx_obj::import_obj_text(text, "fuzz.obj", "", sequential, &one, &error_one);
  if (!ok_one && error_one.rfind("fuzz.obj", 0) != 0) __builtin_trap();  // a message without the file

  // Small chunks cut the text at many line ends, on one thread and on three (which take them in
  // any order): every way exactly the one-chunk import.
  for (unsigned threads : {1u, 3u}) {
    pfx_obj::ImportOptions cut = sequential;
    static pfx::host::ThreadPool three(3);  // the pool a host offers, as libpfxhost makes it
    cut.pool = threads > 1 ? three.service() : nullptr;
    cut.threads = threads;
    cut.chunk_bytes = 1 + size % (threads == 1 ? 37 : 61);
    pfx_obj::ObjMesh cut_mesh;
    std::string error_cut;
    const bool ok_cut = pfx_obj::import_obj_text(text, "fuzz.obj", "", cut, &cut_mesh, &error_cut);
    if (ok_one != ok_cut || error_one != error_cut || (ok_one && !same(one, cut_mesh))) __builtin_trap();
  }

  if (ok_one) {
    for (uint32_t index : one.indices)
      if (index >= one.vertex_count()) __builtin_trap();
    if (one.normals.size() != one.positions.size()) __builtin_trap();
  }

  std::vector<pfx_obj::Material> materials;
  std::vector<std::string> warnings;
  pfx_obj::parse_mtl(text, "fuzz.mtl", "/base", &materials, &warnings);
  return 0;
}
