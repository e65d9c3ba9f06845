// The FX files in tests/fx/files (written for these tests, in the way public effects are written)
// compile through the whole front end from disk with no diagnostic at all, and what they declare
// arrives in the tree as written.
#include <catch2/catch.hpp>

#include "fx_test_support.hpp"

using namespace pfx::fx;

namespace {

std::unique_ptr<FrontEndResult> compile_file(const std::string& name, const PreprocessorOptions& options = {}) {
  FrontEndOptions front_end;
  front_end.preprocessor = options;
  return compile_front_end(std::string(PFX_FX_TEST_FILES) + "/" + name, front_end);
}

const TechniqueDecl& technique(const FrontEndResult& result) {
  for (const DeclPtr& d : result.unit.declarations)
    if (d->kind == DeclKind::kTechnique) return *d->technique;
  FAIL("no technique");
  throw 0;
}

const VariableDecl* global(const FrontEndResult& result, const std::string& name) {
  for (const DeclPtr& d : result.unit.declarations)
    for (const VariableDecl& v : d->variables)
      if (v.name == name) return &v;
  return nullptr;
}

std::string annotation(const VariableDecl& v, const std::string& name) {
  for (const Annotation& a : v.annotations)
    if (a.name == name) return a.value->kind == ExprKind::kString ? a.value->text : print_expression(*a.value);
  return "<none>";
}

}  // namespace

TEST_CASE("every test FX file compiles with no diagnostic", "[fx][files]") {
  for (const char* name : {"Grade.fx", "Blur.fx", "Compute.fx", "Bits.fx"}) {
    INFO(name);
    auto result = compile_file(name);
    CHECK(result->diagnostics.format_all() == "");
  }
}

TEST_CASE("Grade.fx: UI macros, combo items, a 3D LUT", "[fx][files]") {
  auto result = compile_file("Grade.fx");
  REQUIRE(result->ok());
  const TechniqueDecl& grade = technique(*result);
  CHECK(grade.name == "Grade");
  CHECK(grade.annotations.size() == 3);
  const VariableDecl* strength = global(*result, "Strength");
  REQUIRE(strength);
  CHECK(annotation(*strength, "ui_tooltip") == "Parameter Strength");
  CHECK(annotation(*strength, "ui_max") == "1.0");
  CHECK(print_expression(*strength->initializer) == "0.75");
  const VariableDecl* mode = global(*result, "Mode");
  REQUIRE(mode);
  CHECK(annotation(*mode, "ui_items") == std::string("Neutral\0Warm\0Cold\0", 18));
  const VariableDecl* use_lut = global(*result, "UseLut");
  REQUIRE(use_lut);
  CHECK(annotation(*use_lut, "ui_tooltip") == "Applies 16^3 LUT");
  const VariableDecl* lut = global(*result, "Lut");
  REQUIRE(lut);
  CHECK(type_name(lut->resolved) == "sampler3D");
}

TEST_CASE("Blur.fx: passes, render targets and blend states", "[fx][files]") {
  auto result = compile_file("Blur.fx");
  REQUIRE(result->ok());
  const TechniqueDecl& blur = technique(*result);
  REQUIRE(blur.passes.size() == 3);
  CHECK(blur.passes[0].name == "Down");
  CHECK(blur.passes[1].name == "Blur");
  CHECK(blur.passes[2].name == "Combine");
  CHECK(blur.passes[1].states.size() == 13);
  CHECK(blur.passes[1].states[3].name == "RenderTarget1");
  CHECK(blur.passes[1].states[3].value->variable == global(*result, "LumaTex"));
  CHECK(print_expression(*global(*result, "HalfTex")->states[0].value) == "(/ 1920 2)");
}

TEST_CASE("Compute.fx: thread groups, shared memory and the reshade pragma", "[fx][files]") {
  auto result = compile_file("Compute.fx");
  REQUIRE(result->ok());
  REQUIRE(result->preprocessed.pragmas.size() == 1);
  CHECK(spell(result->preprocessed.pragmas[0].tokens) == "reshade skipoptimization");
  const TechniqueDecl& histogram = technique(*result);
  REQUIRE(histogram.passes.size() == 3);
  const StateAssignment& count = histogram.passes[1].states[0];
  CHECK(count.name == "ComputeShader");
  REQUIRE(count.thread_group.size() == 3);
  CHECK(print_expression(*count.thread_group[0]) == "8");
  CHECK(print_expression(*count.thread_group[2]) == "1");
  CHECK(type_name(global(*result, "LocalBins")->resolved) == "uint[64]");
}

TEST_CASE("Bits.fx: renderer and version tests follow the options", "[fx][files]") {
  PreprocessorOptions d3d11;
  d3d11.renderer = 0xb000;
  CHECK(compile_file("Bits.fx", d3d11)->ok());
  PreprocessorOptions old;
  old.reshade_version = 30000;
  std::string errors = compile_file("Bits.fx", old)->diagnostics.format_all();
  CHECK(errors == std::string(PFX_FX_TEST_FILES) + "/Bits.fx:12:3: error: #error \"this effect needs ReShade 4 or newer\"\n");
}
