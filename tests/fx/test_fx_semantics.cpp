// Semantic analysis: HLSL's types and implicit conversions, swizzles, overloads, intrinsics, and
// the errors for unknown names, recursion, huge arrays and type mismatches. Types written by hand
// from HLSL's rules.
#include <catch2/catch.hpp>

#include "codegen/glsl_generator.hpp"
#include "fx_test_support.hpp"
#include "model/effect_model.hpp"

using pfx::fx::test::compile_text;
using pfx::fx::test::errors_of;

namespace {

const char* kContext = R"(
struct S { float a; int2 b; };
static const int K = 4;
texture2D T { Width = 4; Height = 4; };
texture2D TI { Format = R32I; };
texture3D T3 { Width = 4; Height = 4; Depth = 4; };
sampler2D S2 { Texture = T; };
sampler2D<int> SI { Texture = TI; };
sampler3D S3 { Texture = T3; };
storage2D<uint> ST { Texture = TI; };
float g(float x) { return x; }
float g(int x) { return 1; }
int h(float2 v) { return 1; }
void f() {
  float s; int i; uint u; bool b; half hh; float2 v2; float3 v3; float4 v4; int3 i3;
  float3x2 m32; float4x4 m44; float2x2 m22; S st; float arr[3];
)";

// The type of `expression` inside the context above, or the diagnostics if it does not check.
std::string type_of(const std::string& expression) {
  auto result = compile_text(std::string(kContext) + expression + ";\n}\n");
  if (!result->ok()) return result->diagnostics.format_all();
  const auto& declarations = result->unit.declarations;
  const pfx::fx::Stmt& body = *declarations.back()->function->body;
  return pfx::fx::type_name(body.statements.back()->expression->resolved);
}

std::string column_of(const std::string& source, const std::string& text) {
  return std::to_string(source.find(text) + 1);
}

}  // namespace

TEST_CASE("arithmetic follows HLSL's promotions and splats", "[fx][sema]") {
  const std::pair<const char*, const char*> cases[] = {
      {"s + i", "float"},   {"i + u", "uint"},      {"i + b", "int"},     {"b && s", "bool"},
      {"v3 * s", "float3"}, {"i3 + v3", "float3"},  {"v3 < s", "bool3"},  {"hh * s", "float"},
      {"-b", "int"},        {"!v3", "bool3"},       {"~u", "uint"},       {"i << 2", "int"},
      {"i++", "int"},       {"(i, v2)", "float2"},  {"b ? v3 : s", "float3"}, {"i ? 1 : 2", "int"},
      {"m22 * 2", "float2x2"}, {"u % 3u", "uint"},  {"K * 2", "int"},     {"v4 == v4", "bool4"},
  };
  for (const auto& [expression, type] : cases) {
    INFO(expression);
    CHECK(type_of(expression) == type);
  }
}

TEST_CASE("vector truncation is allowed with a warning", "[fx][sema]") {
  std::string source = "void f() { float4 a; float3 b = a; }";
  CHECK(errors_of(source) == "main.fx:1:33: warning: implicit truncation from 'float4' to 'float3'\n");
  CHECK(type_of("v4 + v3") == "float3");
}

TEST_CASE("swizzles on scalars, vectors and matrices, members and indexing", "[fx][sema]") {
  const std::pair<const char*, const char*> cases[] = {
      {"v4.xyz", "float3"}, {"s.xxx", "float3"},    {"s.x", "float"},        {"v2.yx", "float2"},
      {"v4.rgba", "float4"}, {"i3.zzzz", "int4"},   {"m32._m00", "float"},   {"m32._11_22", "float2"},
      {"m44._m33_m00_m11", "float3"}, {"m32[1]", "float2"}, {"v3[0]", "float"}, {"st.b", "int2"},
      {"st.b.y", "int"},    {"arr[1]", "float"},    {"arr", "float[3]"},     {"v4.xyz.xy.x", "float"},
  };
  for (const auto& [expression, type] : cases) {
    INFO(expression);
    CHECK(type_of(expression) == type);
  }
}

TEST_CASE("constructors, casts and overloads", "[fx][sema]") {
  CHECK(type_of("float4(v2, 1, 2)") == "float4");
  CHECK(type_of("float3x2(1, 2, 3, 4, 5, 6)") == "float3x2");
  CHECK(type_of("float4(s)") == "float4");
  CHECK(type_of("(int3)v3") == "int3");
  CHECK(type_of("(float4)s") == "float4");
  CHECK(type_of("(float2x2)v4") == "float2x2");
  CHECK(type_of("g(s)") == "float");
  CHECK(type_of("g(i)") == "float");
  CHECK(type_of("h(v2)") == "int");
}

TEST_CASE("intrinsics are typed by HLSL's rules", "[fx][sema]") {
  const std::pair<const char*, const char*> cases[] = {
      {"mul(v4, m44)", "float4"},   {"mul(m32, v2)", "float3"}, {"mul(v3, m32)", "float2"},
      {"mul(m44, m44)", "float4x4"}, {"dot(v3, v3)", "float"},  {"lerp(v3, v3, s)", "float3"},
      {"saturate(i)", "float"},     {"max(i, i)", "int"},       {"abs(v3)", "float3"},
      {"length(v4)", "float"},      {"cross(v3, v3)", "float3"}, {"isnan(v2)", "bool2"},
      {"asuint(s)", "uint"},        {"f32tof16(s)", "uint"},    {"f16tof32(u)", "float"},
      {"all(v3)", "bool"},          {"frac(v2)", "float2"},     {"step(s, v3)", "float3"},
      {"atan2(v2, v2)", "float2"},  {"fmod(s, 2)", "float"},    {"sign(v3)", "int3"},
      {"transpose(m32)", "float2x3"}, {"rsqrt(s)", "float"},    {"countbits(u)", "uint"},
      {"tex2D(S2, v2)", "float4"},  {"tex2Dlod(S2, v4)", "float4"}, {"tex2Dfetch(SI, i3.xy)", "int"},
      {"tex2Dsize(S2)", "int2"},    {"tex3D(S3, v3)", "float4"}, {"tex2DgatherR(S2, v2)", "float4"},
      {"tex2Dstore(ST, i3.xy, u)", "void"}, {"atomicAdd(ST, i3.xy, u)", "uint"}, {"tex2Doffset(S2, v2, int2(1, 0))", "float4"},
      {"tex3Dsize(S3, 0)", "int3"}, {"sincos(s, s, s)", "void"}, {"clip(s)", "void"}, {"barrier()", "void"},
  };
  for (const auto& [expression, type] : cases) {
    INFO(expression);
    CHECK(type_of(expression) == type);
  }
}

// The typed tree of `expression` inside the context above.
static std::string typed_tree(const std::string& expression) {
  auto result = compile_text(std::string(kContext) + expression + ";\n}\n");
  if (!result->ok()) return result->diagnostics.format_all();
  const pfx::fx::Stmt& body = *result->unit.declarations.back()->function->body;
  return pfx::fx::print_typed_expression(*body.statements.back()->expression);
}

TEST_CASE("the typed tree shows where each implicit conversion happens", "[fx][sema]") {
  CHECK(typed_tree("s + i") == "(+ s:float (implicit i:int):float):float");
  CHECK(typed_tree("v3 * s") == "(* v3:float3 (implicit s:float):float3):float3");
  CHECK(typed_tree("i = s") == "(= i:int (implicit s:float):int):int");
  CHECK(typed_tree("v4.xyz = v2.xyy") == "(= (. v4:float4 xyz):float3 (. v2:float2 xyy):float3):float3");
  CHECK(typed_tree("b && i") == "(&& b:bool (implicit i:int):bool):bool");
  CHECK(typed_tree("g(i)") == "(call g i:int):float");
  CHECK(typed_tree("h(v3)") == "(call h (implicit v3:float3):float2):int");
  CHECK(typed_tree("lerp(v3, v4, 1)") ==
        "(call lerp v3:float3 (implicit v4:float4):float3 (implicit 1:int):float3):float3");
  CHECK(typed_tree("arr[u]") == "([] arr:float[3] u:uint):float");
  CHECK(typed_tree("arr[s]") == "([] arr:float[3] (implicit s:float):int):float");
  CHECK(typed_tree("i ? v2 : 0") == "(? (implicit i:int):bool v2:float2 (implicit 0:int):float2):float2");
}

TEST_CASE("implicit conversions appear in the tree as implicit casts", "[fx][sema]") {
  auto result = compile_text("static const float a = 1; static const int2 b = 3;");
  REQUIRE(result->ok());
  const pfx::fx::Expr& init = *result->unit.declarations[0]->variables[0].initializer;
  CHECK(init.kind == pfx::fx::ExprKind::kCast);
  CHECK(init.implicit);
  CHECK(pfx::fx::type_name(init.resolved) == "float");
  CHECK(pfx::fx::type_name(init.operands[0]->resolved) == "int");
  CHECK(pfx::fx::type_name(result->unit.declarations[1]->variables[0].initializer->resolved) == "int2");
}

TEST_CASE("unknown names, functions and types", "[fx][sema][bad]") {
  CHECK(errors_of("void f() { x = 1; }") == "main.fx:1:12: error: unknown name 'x'\n");
  CHECK(errors_of("void f() { foo(1); }") == "main.fx:1:12: error: unknown function 'foo'\n");
  CHECK(errors_of("void f() { S s; }") == "main.fx:1:14: error: unknown type 'S'\n");
  CHECK(errors_of("technique T { pass { PixelShader = Missing; } }") ==
        "main.fx:1:36: error: unknown function 'Missing' in PixelShader\n");
  CHECK(errors_of("float x; sampler s { Texture = x; };") == "main.fx:1:32: error: 'Texture' must name a texture, not 'x'\n");
  CHECK(errors_of("namespace A { float v; } void f() { float w = v; }") == "main.fx:1:47: error: unknown name 'v'\n");
  CHECK(errors_of("namespace A { float v; } void f() { float w = A::v; }").empty());
  CHECK(errors_of("namespace A { float v; namespace B { float w() { return v; } } }").empty());
}

TEST_CASE("recursion is refused with the cycle named", "[fx][sema][bad]") {
  CHECK(errors_of("float f(float x) { return f(x); }") ==
        "main.fx:1:27: error: recursive call to 'f' (f -> f): FX functions cannot recurse\n");
  CHECK(errors_of("float b(float x);\nfloat a(float x) { return b(x); }\nfloat b(float x) { return a(x); }") ==
        "main.fx:3:27: error: recursive call to 'a' (a -> b -> a): FX functions cannot recurse\n");
}

TEST_CASE("array sizes: constants, limits, huge arrays", "[fx][sema][bad]") {
  CHECK(errors_of("static const int N = 2 * 3; float a[N]; float b[N + 1][2];").empty());
  CHECK(errors_of("float a[100000000];") == "main.fx:1:9: error: array 'a' has more than 1048576 elements\n");
  CHECK(errors_of("float a[1024][1024][1024];") == "main.fx:1:21: error: array 'a' has more than 1048576 elements\n");
  CHECK(errors_of("uniform int n; float a[n];") == "main.fx:1:24: error: array size is not an integer constant\n");
  CHECK(errors_of("float a[-1];") == "main.fx:1:9: error: array size must be positive, not -1\n");
  CHECK(errors_of("static const float w[] = { 1, 2, 3 }; static const float x[2] = { 1, 2, 3 };") ==
        "main.fx:1:65: error: initialiser list has 3 values; 'float[2]' needs 2\n");
}

TEST_CASE("type errors", "[fx][sema][bad]") {
  CHECK(errors_of("void f() { float3 v = float2(1, 2); }") ==
        "main.fx:1:23: error: cannot convert 'float2' to 'float3' in the initialisation of 'v'\n");
  CHECK(errors_of("float4 c = float4(1, 2, 3);") == "main.fx:1:12: error: 'float4' constructor needs 4 components, not 3\n");
  CHECK(errors_of("static const float k = 1; void f() { k = 2; }") ==
        "main.fx:1:38: error: cannot assign to 'k': it is not a modifiable value\n");
  CHECK(errors_of("uniform float u; void f() { u = 1; }") ==
        "main.fx:1:29: error: cannot assign to 'u': it is not a modifiable value\n");
  CHECK(errors_of("void f() { float2 v; v.z = 1; }") == "main.fx:1:23: error: swizzle 'z' reaches past a 2-component value\n");
  CHECK(errors_of("void f() { float4 v; v.xg = 1; }") == "main.fx:1:23: error: swizzle 'xg' mixes xyzw and rgba\n");
  CHECK(errors_of("void f() { float4 v; v.xx = 1; }") == "main.fx:1:23: error: cannot assign to this expression: it is not a modifiable value\n");
  CHECK(errors_of("struct S { float a; }; void f() { S s; s.b = 1; }") == "main.fx:1:41: error: struct 'S' has no member 'b'\n");
  CHECK(errors_of("void f() { float a; int b = a & 1; }") == "main.fx:1:31: error: operator '&' needs integers, not 'float'\n");
  CHECK(errors_of("void f() { float a = sin(1, 2); }") == "main.fx:1:22: error: 'sin' takes 1 argument(s), not 2\n");
  CHECK(errors_of("float3x2 m; void f() { float3 r = mul(m, float3(1, 2, 3)); }") ==
        "main.fx:1:35: error: 'mul' of 'float3x2' and 'float3': sizes do not match\n");
  CHECK(errors_of("void f() { texture2D t; }") == "main.fx:1:22: error: 't': textures, samplers and storages must be global\n");
  CHECK(errors_of("void f() { float4 a = tex2D(1, 2); }") ==
        "main.fx:1:23: error: 'tex2D' needs a sampler or storage as its first argument\n");
  std::string ambiguous = "float g(int a) { return 0; } float g(uint a) { return 0; } void f() { g(1.0); }";
  CHECK(errors_of(ambiguous) == "main.fx:1:" + column_of(ambiguous, "g(1.0)") + ": error: ambiguous call to 'g' with (float)\n");
  std::string none = "float g(float2 a) { return 0; } struct Q { float x; }; void f() { Q q; g(q); }";
  CHECK(errors_of(none) == "main.fx:1:" + column_of(none, "g(q)") + ": error: no overload of 'g' takes (Q)\n");
}

TEST_CASE("statement checks", "[fx][sema][bad]") {
  CHECK(errors_of("void f() { break; }") == "main.fx:1:12: error: 'break' outside a loop or switch\n");
  CHECK(errors_of("void f() { continue; }") == "main.fx:1:12: error: 'continue' outside a loop\n");
  CHECK(errors_of("void f() { return 1; }") == "main.fx:1:12: error: a void function cannot return a value\n");
  CHECK(errors_of("float f() { return; }") == "main.fx:1:13: error: 'return' needs a value of type 'float'\n");
  CHECK(errors_of("void f(int i) { switch (i) { case 1: break; case 1: break; } }") ==
        "main.fx:1:50: error: duplicate case 1\n");
  CHECK(errors_of("void f(int i) { for (int k = 0; k < 4; ++k) { if (k == 2) continue; } int k; }").empty());
  CHECK(errors_of("void f() { float a; float a; }") == "main.fx:1:27: error: redefinition of 'a'\n");
}

TEST_CASE("texture, sampler, storage and pass states are checked by name and value", "[fx][sema][bad]") {
  CHECK(errors_of("texture2D t { Widht = 4; };") == "main.fx:1:15: error: unknown texture state 'Widht'\n");
  CHECK(errors_of("texture2D t { Format = RGBA9; };") ==
        "main.fx:1:24: error: 'RGBA9' is not a value of Format (R8, R16, R16F, R32F, R32I, R32U, RG8, RG16, RG16F, "
        "RG32F, RGBA8, RGBA16, RGBA16F, RGBA32F, RGB10A2)\n");
  CHECK(errors_of("texture2D t { Width = 100000; };") == "main.fx:1:23: error: 'Width' must be an integer constant from 1 to 16384\n");
  CHECK(errors_of("texture2D t { Width = BUFFER_WIDTH / 2; Height = 0.5 * BUFFER_HEIGHT; MipLevels = 3; };").empty());
  CHECK(errors_of("texture2D t; sampler2D s { AddressU = clamp; };") == "main.fx:1:24: error: sampler 's' has no Texture\n");
  CHECK(errors_of("texture2D t; sampler2D s { Texture = t; AddressU = Clamp; MinFilter = linear; MipLODBias = -1; };").empty());
  CHECK(errors_of("texture2D t; storage2D s { Texture = t; MipLevel = 0; Format = R8; };") ==
        "main.fx:1:55: error: unknown storage state 'Format'\n");
  std::string per_target = "technique T { pass { BlendOp3 = ADD; SrcBlend7 = ONE; BlendEnable8 = true; } }";
  CHECK(errors_of(per_target) == "main.fx:1:" + std::to_string(per_target.find("BlendEnable8") + 1) +
                                     ": error: unknown pass state 'BlendEnable8'\n");
  std::string topology = "technique T { pass { PrimitiveTopology = TRIANGLEFAN; } }";
  CHECK(errors_of(topology) == "main.fx:1:" + std::to_string(topology.find("TRIANGLEFAN") + 1) +
                                   ": error: 'TRIANGLEFAN' is not a value of PrimitiveTopology (POINTLIST, LINELIST, "
                                   "LINESTRIP, TRIANGLELIST, TRIANGLESTRIP)\n");
  // TRUE and FALSE, in any case, as ReShade takes them; a variable of that name is the variable.
  CHECK(errors_of("texture2D t; sampler2D s { Texture = t; SRGBTexture = FALSE; }; "
                  "technique T { pass { BlendEnable = True; ClearRenderTargets = false; } }")
            .empty());
  CHECK(errors_of("texture2D t; sampler2D s { Texture = t; SRGBTexture = MAYBE; };") ==
        "main.fx:1:55: error: unknown name 'MAYBE'\n");
  // Sizes folded through swizzles of constant vectors (a scalar initialiser splat), float
  // arithmetic truncated, comparisons and bit operations.
  CHECK(errors_of("static const int2 Small = 256; static const float2 Cursor = float2(32.9, 48.0);\n"
                  "texture2D a { Width = Small.y; Height = Cursor.x; MipLevels = ((Small.x >> 4) != 0) + "
                  "((Small.x & 0xF0F0) != 0); };\n"
                  "texture2D b { Width = BUFFER_WIDTH / 3.0; Height = Small.y / Small.x; };")
            .empty());
  std::string threads = "void CS() {} technique T { pass { ComputeShader = CS<2000, 1>; } }";
  CHECK(errors_of(threads) == "main.fx:1:" + std::to_string(threads.find("2000") + 1) +
                                  ": error: thread group size must be a constant from 1 to 1024\n");
}

namespace {

// What building the effect's model and generating each pass's GLSL report for `source`.
std::string generation_errors(const std::string& source) {
  auto result = compile_text(source);
  if (!result->ok()) return result->diagnostics.format_all();
  pfx::fx::EffectModel model = pfx::fx::build_effect_model(result->unit, result->diagnostics);
  for (const auto& technique : model.techniques)
    for (const auto& pass : technique.passes) pfx::fx::generate_pass(result->unit, model, pass, result->diagnostics);
  return result->diagnostics.format_all();
}

const char* kPass = "\nfloat4 VS(uint id : SV_VertexID) : SV_Position { return 0; }\n"
                    "technique T { pass { VertexShader = VS; PixelShader = PS; } }\n";

}  // namespace

TEST_CASE("a function's static may start only from globals and literals, as it starts before any call", "[fx][sema]") {
  CHECK(generation_errors("float Next(float x) { static float n = x; n += 1; return n; }\n"
                          "float4 PS() : SV_Target { return Next(1); }" + std::string(kPass)) ==
        "main.fx:1:36: error: the initialiser of the static 'n' uses 'x', a local of the function; a static starts before "
        "any call, so it may use only globals and literals\n");
  CHECK(generation_errors("static const float K = 2;\nfloat Next() { static float n = K * 2; n += 1; return n; }\n"
                          "float4 PS() : SV_Target { return Next(); }" + std::string(kPass)) == "");
}

TEST_CASE("intrinsics of an integer matrix other than all and any are refused by name", "[fx][sema]") {
  CHECK(generation_errors("float4 PS() : SV_Target { int2x2 m = int2x2(1, 2, 3, 4); return any(m) ? transpose(m)._m01 : 0; }" +
                          std::string(kPass)) == "main.fx:1:74: error: transpose() of an integer or bool matrix is not supported\n");
}

TEST_CASE("the table of intrinsics spells every id and each name once", "[fx][sema]") {
  using pfx::fx::Intrinsic;
  for (int id = 1; id < static_cast<int>(Intrinsic::kCount); ++id)
    CHECK_FALSE(pfx::fx::intrinsic_name(static_cast<Intrinsic>(id)).empty());
  for (const pfx::fx::IntrinsicInfo& row : pfx::fx::intrinsic_table()) {
    CHECK(pfx::fx::find_intrinsic(row.name) == &row);  // a name spelled twice would find the first row only
    CHECK(row.min_arguments <= row.max_arguments);
  }
  CHECK(pfx::fx::find_intrinsic("tex3Dlodoffset")->id == Intrinsic::kTexSampleLodOffset);
  CHECK(pfx::fx::find_intrinsic("AllMemoryBarrier")->id == Intrinsic::kMemoryBarrier);
  CHECK(pfx::fx::intrinsic_name(Intrinsic::kTexSample) == "tex2D");
  CHECK(pfx::fx::find_intrinsic("tex4D") == nullptr);
}
