// The GL state comparison on a real context: every protected value that a pass could leave
// changed is noticed and named; reading the state changes nothing and raises no GL error.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>

#include <glad/gl.h>

#include "gl_state.hpp"
#include "headless_context.hpp"

using pfx::validate::gl_state_changes;
using pfx::validate::snapshot_gl_state;

namespace {

pfx::app::HeadlessContext& context() {
  static std::string error;
  static std::unique_ptr<pfx::app::HeadlessContext> context = pfx::app::HeadlessContext::create(&error);
  INFO(error);
  REQUIRE(context);
  return *context;
}

}  // namespace

TEST_CASE("reading the GL state twice gives no change and no GL error", "[validate][gl]") {
  context();
  while (glGetError() != GL_NO_ERROR) {
  }
  const auto first = snapshot_gl_state();
  const auto second = snapshot_gl_state();
  CHECK(glGetError() == GL_NO_ERROR);
  CHECK(gl_state_changes(first, second).empty());
  CHECK(first.size() == pfx::validate::protected_gl_state_names().size());
}

TEST_CASE("each kind of protected state change is named with its old and new value", "[validate][gl]") {
  context();
  const auto before = snapshot_gl_state();
  glEnable(GL_SCISSOR_TEST);
  glViewport(1, 2, 3, 4);
  glColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glBindVertexArray(vao);
  const auto after = snapshot_gl_state();
  const std::vector<std::string> changes = gl_state_changes(before, after);
  auto has = [&](const std::string& text) {
    INFO("looking for: " << text);
    for (const auto& change : changes) INFO(change);
    return std::find(changes.begin(), changes.end(), text) != changes.end();
  };
  CHECK(has("GL_SCISSOR_TEST enabled (was disabled)"));
  CHECK(has("GL_VERTEX_ARRAY_BINDING " + std::to_string(vao) + " (was 0)"));
  CHECK(has("GL_COLOR_WRITEMASK (1, 0, 1, 1) (was (1, 1, 1, 1))"));
  CHECK(has("GL_BLEND_SRC_RGB GL_SRC_ALPHA (was GL_ONE)"));
  CHECK(has("GL_BLEND_DST_ALPHA GL_ONE_MINUS_SRC_ALPHA (was GL_ZERO)"));
  bool viewport = false;
  for (const auto& change : changes) viewport |= change.rfind("GL_VIEWPORT (1, 2, 3, 4) (was ", 0) == 0;
  CHECK(viewport);
  CHECK(changes.size() == 8);  // the four blend factors count one each

  glDisable(GL_SCISSOR_TEST);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBlendFunc(GL_ONE, GL_ZERO);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
}
