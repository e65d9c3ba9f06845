// Uniform values reach the shader with their types and layouts: scalars, vectors, a colour, a
// combo's index, a bool, and uniforms that are not parameters (an array, a matrix, no initial
// value, an array of matrices and what follows it, an integer matrix).
// size: 48x2
#include "include/check.fxh"

uniform float Strength < ui_type = "slider"; ui_min = 0.0; ui_max = 2.0; > = 0.75;
uniform float3 Tint < ui_type = "color"; > = float3(0.1, 0.2, 0.3);
uniform float4 Edge < ui_type = "color"; > = float4(0.5, 0.25, 0.125, 0.0625);
uniform int Mode < ui_type = "combo"; ui_items = "First\0Second\0Third\0"; > = 2;
uniform bool Enabled = true;
uniform int2 Cells = int2(-3, 4);
uniform uint Big = 4000000000u;
uniform float Weights[3] = { 1.0, 2.0, 4.0 };
uniform float2x2 Rows = float2x2(1, 2, 3, 4);
uniform float Unset;
uniform float3x3 Frames[2] = { float3x3(1, 2, 3, 4, 5, 6, 7, 8, 9), float3x3(10, 11, 12, 13, 14, 15, 16, 17, 18) };
uniform float Last = 0.5;
uniform int2x2 IRows = int2x2(5, 6, 7, 8);

bool Check(int i)
{
  switch (i)
  {
    case 0: return Strength == 0.75;
    case 1: return Near(Tint, float3(0.1, 0.2, 0.3));
    case 2: return all(Edge == float4(0.5, 0.25, 0.125, 0.0625));
    case 3: return Mode == 2 && Enabled;
    case 4: return all(Cells == int2(-3, 4)) && Big == 4000000000u;
    case 5: return Weights[0] == 1.0 && Weights[2] == 4.0;
    case 6: return Rows[1][0] == 3.0 && Rows[0][1] == 2.0;
    case 7: return Unset == 0.0;
    case 8: return Frames[0][0][2] == 3.0 && Frames[1][2][0] == 16.0 && Frames[1][1][1] == 14.0;
    case 9: return Last == 0.5;
    case 10: return IRows[1][0] == 7 && IRows[0][1] == 6;
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique uniforms { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
