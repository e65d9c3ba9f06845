// A CRT-style scanline effect as public collections write them: the line count follows a
// parameter whose default and slider range are the frame's own height, so the picture has one
// dark line per 4 rows of the frame it runs on, whatever its size.
#include "ReShade.fxh"

uniform int iHeight < ui_type = "slider"; ui_min = 1; ui_max = BUFFER_HEIGHT; ui_label = "Lines of the picture"; > = BUFFER_HEIGHT;
uniform float fPeriod < ui_type = "slider"; ui_min = 2.0; ui_max = 16.0; > = 4.0;

float4 Scanlines(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  float row = floor(texcoord.y * iHeight);
  bool dark = fmod(row, fPeriod) >= fPeriod * 0.5;
  return dark ? float4(0.0, 0.0, 0.0, 1.0) : float4(1.0, 1.0, 1.0, 1.0);
}

technique Scanlines
{
  pass { VertexShader = PostProcessVS; PixelShader = Scanlines; }
}
