// pfx::host::ImportResult gives each result back to the importer that made it exactly once, on
// every way out: going out of scope, reset(), being moved from or assigned over. Checked against an
// importer that counts what it hands out and what comes back. And gl_error_text writes a GL error
// as messages quote it.
#include <catch2/catch.hpp>

#include <cstring>
#include <set>

#include <pfx/host/gl_error.hpp>
#include <pfx/host/import_result.hpp>

namespace {

// Hands out a result per import (failed when the path says "fail", none when it says "oom") and
// records which results are still out.
std::set<pfx_import_result*> g_out;
int g_released_twice = 0;

pfx_status counting_import(const pfx_import_request* request, pfx_import_result** out) {
  *out = nullptr;
  if (std::strcmp(request->path, "oom") == 0) return PFX_OUT_OF_MEMORY;
  auto* result = new pfx_import_result{};
  result->struct_size = sizeof *result;
  const bool fail = std::strcmp(request->path, "fail") == 0;
  result->status = fail ? PFX_ERROR : PFX_OK;
  result->error = fail ? "fail: no such file" : nullptr;
  result->vertex_count = 3;
  g_out.insert(result);
  *out = result;
  return result->status;
}

void counting_release(pfx_import_result* result) {
  if (!result) return;
  if (g_out.erase(result) == 0) ++g_released_twice;
  else delete result;
}

pfx_importer_desc counting_importer() {
  pfx_importer_desc desc{};
  desc.struct_size = sizeof desc;
  desc.id = "counting";
  desc.import = counting_import;
  desc.release = counting_release;
  return desc;
}

pfx_import_request request_for(const char* path) {
  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.path = path;
  return request;
}

}  // namespace

TEST_CASE("an import result is released once, whichever way it goes", "[import]") {
  const pfx_importer_desc importer = counting_importer();
  g_out.clear();
  g_released_twice = 0;
  {
    const pfx::host::ImportResult ok(importer, request_for("a.obj"));
    REQUIRE(ok);
    CHECK(ok.ok());
    CHECK(ok.error() == nullptr);
    CHECK(ok->vertex_count == 3);
    CHECK(g_out.size() == 1);

    const pfx::host::ImportResult failed(importer, request_for("fail"));
    REQUIRE(failed);
    CHECK_FALSE(failed.ok());
    CHECK(failed.status() == PFX_ERROR);
    CHECK(std::strcmp(failed.error(), "fail: no such file") == 0);
    CHECK(g_out.size() == 2);
  }
  CHECK(g_out.empty());  // both released when they went out of scope

  pfx::host::ImportResult first(importer, request_for("a.obj"));
  first.reset();
  CHECK(g_out.empty());
  CHECK_FALSE(first);
  first.reset();  // nothing left to release

  {
    pfx::host::ImportResult moved_from(importer, request_for("a.obj"));
    pfx::host::ImportResult moved_to(std::move(moved_from));
    CHECK(g_out.size() == 1);
    CHECK(moved_to);
    CHECK_FALSE(moved_from);
    moved_to = pfx::host::ImportResult(importer, request_for("b.obj"));  // the old one goes back
    CHECK(g_out.size() == 1);
  }
  CHECK(g_out.empty());
  CHECK(g_released_twice == 0);
}

TEST_CASE("an importer that could not allocate a result is out of memory, with nothing to release", "[import]") {
  const pfx_importer_desc importer = counting_importer();
  g_out.clear();
  g_released_twice = 0;
  const pfx::host::ImportResult none(importer, request_for("oom"));
  CHECK_FALSE(none);
  CHECK(none.status() == PFX_OUT_OF_MEMORY);
  CHECK(none.error() == nullptr);
  CHECK(g_released_twice == 0);
}

TEST_CASE("GL errors are written as four hexadecimal digits", "[gl]") {
  CHECK(pfx::host::gl_error_text(0x0502) == "0x0502");  // GL_INVALID_OPERATION
  CHECK(pfx::host::gl_error_text(0x0505) == "0x0505");  // GL_OUT_OF_MEMORY
  CHECK(pfx::host::gl_error_text(0x0506) == "0x0506");  // GL_INVALID_FRAMEBUFFER_OPERATION
}
