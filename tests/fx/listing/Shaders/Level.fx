// A grey level a preset's PreprocessorDefinitions set: PFX_TEST_LEVEL has a default the file
// gives only when it is not defined, and the depth setting pfx defines itself shows in the
// output if a preset could change it.
#include "ReShade.fxh"
#ifndef PFX_TEST_LEVEL
#define PFX_TEST_LEVEL 0.25
#endif
float4 Level(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
  float level = PFX_TEST_LEVEL + 0.125 * RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN;
  return float4(level, level, level, 1.0);
}
technique DefinedLevel { pass { VertexShader = PostProcessVS; PixelShader = Level; } }
