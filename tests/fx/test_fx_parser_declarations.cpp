// Global declarations: uniforms with annotations, constants, textures, samplers and storages with
// state blocks, structs, namespaces, functions, techniques and passes.
#include <catch2/catch.hpp>

#include "fx_test_support.hpp"

using pfx::fx::test::parse_to_text;

TEST_CASE("uniforms and constants", "[fx][parser]") {
  CHECK(parse_to_text("uniform float Strength < ui_type = \"slider\"; ui_min = 0.0; ui_max = 1.0; "
                      "ui_label = \"Strength\"; > = 0.5;") ==
        "(var uniform float Strength (@ ui_type \"slider\") (@ ui_min 0.0) (@ ui_max 1.0) (@ ui_label \"Strength\") 0.5)\n");
  CHECK(parse_to_text("uniform float3 Tint < ui_type = \"color\"; > = float3(1, 0.5, 0);") ==
        "(var uniform float3 Tint (@ ui_type \"color\") (float3 1 0.5 0))\n");
  CHECK(parse_to_text("uniform float timer < source = \"timer\"; >;") == "(var uniform float timer (@ source \"timer\"))\n");
  CHECK(parse_to_text("uniform int Mode < ui_min = -1; string UIName = \"m\"; >= 2;") ==
        "(var uniform int Mode (@ ui_min (- 1)) (@ UIName \"m\") 2)\n");
  CHECK(parse_to_text("static const float W[3] = { 0.1, 0.2, 0.3, };") == "(var static const float W[3] ({} 0.1 0.2 0.3))\n");
  CHECK(parse_to_text("static const int N[] = {1, 2};") == "(var static const int N[] ({} 1 2))\n");
  CHECK(parse_to_text("static const float2 O[2] = { {1, 2}, {3, 4} };") ==
        "(var static const float2 O[2] ({} ({} 1 2) ({} 3 4)))\n");
  CHECK(parse_to_text("groupshared int Shared[64];") == "(var groupshared int Shared[64])\n");
  CHECK(parse_to_text("float a, b = 2;") == "(var float a) (var float b 2)\n");
  CHECK(parse_to_text("float3x2 m; half4 h; double d; uint2 u; bool3 b; int4x4 i; dword w; vector v; matrix<int, 2, 3> k;") ==
        "(var float3x2 m)\n(var half4 h)\n(var double d)\n(var uint2 u)\n(var bool3 b)\n(var int4x4 i)\n(var uint w)\n"
        "(var float4 v)\n(var int2x3 k)\n");
}

TEST_CASE("textures, samplers and storages with state blocks", "[fx][parser]") {
  CHECK(parse_to_text("texture BackBuffer : COLOR; texture2D Depth : DEPTH;") ==
        "(var texture2D BackBuffer :COLOR)\n(var texture2D Depth :DEPTH)\n");
  CHECK(parse_to_text("texture2D Tex < source = \"lut.png\"; pooled = true; > { Width = 32 * 2; Height = 32; Format = RGBA8; };") ==
        "(var texture2D Tex (@ source \"lut.png\") (@ pooled true) (states (state Width (* 32 2)) (state Height 32) "
        "(state Format RGBA8)))\n");
  CHECK(parse_to_text("texture3D L { Width = 8; Height = 8; Depth = 8; MipLevels = 1; }") ==
        "(var texture3D L (states (state Width 8) (state Height 8) (state Depth 8) (state MipLevels 1)))\n");
  CHECK(parse_to_text("sampler2D<int> S { Texture = T; AddressU = CLAMP; MinFilter = POINT; SRGBTexture = false; };") ==
        "(var sampler2D<int> S (states (state Texture T) (state AddressU CLAMP) (state MinFilter POINT) "
        "(state SRGBTexture false)))\n");
  CHECK(parse_to_text("storage3D<uint> St { Texture = T; MipLevel = 0; }; sampler1D One { Texture = O; };") ==
        "(var storage3D<uint> St (states (state Texture T) (state MipLevel 0)))\n"
        "(var sampler1D One (states (state Texture O)))\n");
  CHECK(parse_to_text("sampler s { Texture = t; MipLODBias = -1.5f; };") ==
        "(var sampler2D s (states (state Texture t) (state MipLODBias (- 1.5f))))\n");
}

TEST_CASE("structs, namespaces and functions", "[fx][parser]") {
  CHECK(parse_to_text("struct VSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; float a, b; };") ==
        "(struct VSOut (var float4 pos :SV_Position) (var float2 uv :TEXCOORD0) (var float a) (var float b))\n");
  CHECK(parse_to_text("namespace A { namespace B { float f() { return 1; } } }") ==
        "(namespace A (namespace B (function float f () (block (return 1)))))\n");
  CHECK(parse_to_text("void f(in float a, out float b, inout float3 c : COLOR, float d = 2) { }") ==
        "(function void f ((var in float a) (var out float b) (var in out float3 c :COLOR) (var float d 2)) (block))\n");
  CHECK(parse_to_text("[numthreads(8, 8, 1)] void CS(uint3 id : SV_DispatchThreadID) {}") ==
        "([numthreads] 8 8 1) (function void CS ((var uint3 id :SV_DispatchThreadID)) (block))\n");
  CHECK(parse_to_text("float g(float x); float4 PS(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target { return 0; }") ==
        "(function float g ((var float x)) prototype)\n"
        "(function float4 PS ((var float4 p :SV_Position) (var float2 uv :TEXCOORD)) :SV_Target (block (return 0)))\n");
  CHECK(parse_to_text("float h(void) { return 0; } float k(sampler2D s, float a[4]) { return a[0]; }") ==
        "(function float h () (block (return 0)))\n"
        "(function float k ((var sampler2D s) (var float a[4])) (block (return ([] a 0))))\n");
  CHECK(parse_to_text("struct S { float v; }; S make() { S s; s.v = 1; return s; }") ==
        "(struct S (var float v))\n(function S make () (block (decl (var S s)) (expr (= (. s v) 1)) (return s)))\n");
}

TEST_CASE("techniques and passes with every kind of state", "[fx][parser]") {
  CHECK(parse_to_text(
            "technique T < ui_label = \"Tee\"; enabled = true; timeout = 1000; >\n"
            "{\n"
            "  pass P0 { VertexShader = VS; PixelShader = NS::PS; RenderTarget0 = Tex; BlendEnable = true;\n"
            "            SrcBlend = SRCALPHA; DestBlend = INVSRCALPHA; ClearRenderTargets = false;\n"
            "            RenderTargetWriteMask = 0xF; StencilEnable = true; StencilFunc = ALWAYS; }\n"
            "  pass { ComputeShader = CS<8, 8, 1>; DispatchSizeX = 4; }\n"
            "}") ==
        "(technique T (@ ui_label \"Tee\") (@ enabled true) (@ timeout 1000) (pass P0 (state VertexShader VS) "
        "(state PixelShader NS::PS) (state RenderTarget0 Tex) (state BlendEnable true) (state SrcBlend SRCALPHA) "
        "(state DestBlend INVSRCALPHA) (state ClearRenderTargets false) (state RenderTargetWriteMask 0xF) "
        "(state StencilEnable true) (state StencilFunc ALWAYS)) (pass (state ComputeShader CS (threads 8 8 1)) "
        "(state DispatchSizeX 4)))\n");
  CHECK(parse_to_text("technique Empty {}") == "(technique Empty)\n");
  CHECK(parse_to_text("technique C { pass { ComputeShader = Main<64>; } }") ==
        "(technique C (pass (state ComputeShader Main (threads 64))))\n");
}
