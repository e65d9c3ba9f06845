// A colour grade with one parameter of each kind a ReShade preset writes: a float3 (three numbers
// separated by commas), a float, a combo (an int) and a bool. Every value moves the picture, so a
// value that a host drops or misreads shows in the bytes.
#include "ReShade.fxh"
uniform float3 Lift < ui_type = "slider"; ui_min = -0.5; ui_max = 0.5; > = float3(0.0, 0.0, 0.0);
uniform float Gain < ui_type = "slider"; ui_min = 0.0; ui_max = 2.0; > = 1.0;
uniform int Mode < ui_type = "combo"; ui_items = "Multiply\0Screen\0"; > = 0;
uniform bool Invert = false;
float4 Grade(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
  float3 c = tex2D(ReShade::BackBuffer, uv).rgb;
  c = Mode == 0 ? c * Gain : 1.0 - (1.0 - c) * (1.0 - Gain * 0.25);
  c = saturate(c + Lift);
  return float4(Invert ? 1.0 - c : c, 1.0);
}
technique Grade < ui_label = "Grade"; > { pass { VertexShader = PostProcessVS; PixelShader = Grade; } }
