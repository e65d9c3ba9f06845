// What ReShade takes and Depth3D's SuperDepth3D relies on: `#if exists "file"` (1 when a quoted
// #include of the file would find it: beside this file, then the include folders; `exists MACRO`
// names the macro's file), #if arithmetic on literals wider than 32 bits (a 64-bit application
// hash), and a vector assigned to a wider one, whose missing components repeat its last one
// (ReShade checks assignments the other way round and widens as its casts do: c.rgb into a
// float4 is c.rgbb). Expected values are the lists below, read by eye.
// size: 32x2
#include "include/check.fxh"

#define HEADER_MACRO "include/defines.fxh"
#define MISSING_MACRO "include/no_such_header.fxh"

#if exists "include/check.fxh" && exists HEADER_MACRO && !exists MISSING_MACRO && !exists "nowhere.fxh"
  #define EXISTS_RIGHT 1
#else
  #define EXISTS_RIGHT 0
#endif
#if exists("ReShade.fxh")  // pfx's own header, from the include folders
  #define FINDS_INCLUDE_FOLDERS 1
#else
  #define FINDS_INCLUDE_FOLDERS 0
#endif
#if 0xC19572DDF > 0xFFFFFFFF && (0xC19572DDF & 0xF) == 0xF
  #define WIDE_LITERALS 1
#else
  #define WIDE_LITERALS 0
#endif

bool Check(int i)
{
  float4 colour = float4(9.0, 9.0, 9.0, 9.0);
  colour = float3(0.25, 0.5, 0.75 + Zero);
  float4 pair = float4(9.0, 9.0, 9.0, 9.0);
  pair = float2(1.0 + Zero, 2.0);
  int3 whole = int3(9, 9, 9);
  whole += int2(1 + IZero, 2);  // (9 + 1, 9 + 2, 9 + 2)
  switch (i)
  {
    case 0: return EXISTS_RIGHT == 1 + IZero;
    case 1: return FINDS_INCLUDE_FOLDERS == 1 + IZero;
    case 2: return WIDE_LITERALS == 1 + IZero;
    case 3: return Near(colour, float4(0.25, 0.5, 0.75, 0.75));
    case 4: return Near(pair, float4(1.0, 2.0, 2.0, 2.0));
    case 5: return all(whole == int3(10, 11, 11));
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique exists_and_widening
{
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
