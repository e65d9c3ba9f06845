// Texture sizes and mip counts from constant expressions of any shape, as public effects write
// them: a swizzle of a static const vector (a scalar initialiser is splat over it), a float
// vector's component, float arithmetic on the frame's size (truncated toward zero), and a log2
// written with shifts and comparisons; sizes and mip counts that come to 0 on a small frame
// (BUFFER_HEIGHT / 256, a bloom's last level) are 1, as ReShade makes them. The frame here is 64x2
// (320x240 under vkBasalt, where they come to 0 as well).
// size: 64x2
#include "include/check.fxh"

#define INT_LOG2(v) (((v >> 1) != 0) + ((v >> 2) != 0) + ((v >> 3) != 0) + ((v >> 4) != 0) + ((v >> 5) != 0))

static const int2 Small = 8;
static const float2 Cursor = float2(12.9, 6.0);
static const int Levels = INT_LOG2(16) + 1;

texture2D SwizzledTex { Width = Small.y; Height = Small.x / 2; };
sampler2D Swizzled { Texture = SwizzledTex; };
texture2D FloatsTex { Width = Cursor.x; Height = Cursor.y; };
sampler2D Floats { Texture = FloatsTex; };
texture2D FrameTex { Width = BUFFER_WIDTH / 3.0; Height = BUFFER_HEIGHT * 1.5; };
sampler2D Frame { Texture = FrameTex; };
texture2D MippedTex { Width = 16; Height = 16; MipLevels = Levels; };
sampler2D Mipped { Texture = MippedTex; };
texture2D VanishedTex { Width = BUFFER_WIDTH / 1024; Height = BUFFER_HEIGHT / 256; MipLevels = BUFFER_WIDTH / 4096; };
sampler2D Vanished { Texture = VanishedTex; };

bool Check(int i)
{
  switch (i)
  {
    case 0: return all(tex2Dsize(Swizzled, 0) == int2(8, 4));
    case 1: return all(tex2Dsize(Floats, 0) == int2(12, 6));
    case 2: return all(tex2Dsize(Frame, 0) == int2(21, 3));  // 64 / 3.0 = 21.33, 2 * 1.5 = 3
    case 3: return all(tex2Dsize(Mipped, 0) == int2(16, 16)) && Levels == 5;
    case 4: return all(tex2Dsize(Mipped, 4) == int2(1, 1));  // the fifth level is there
    case 5: return all(tex2Dsize(Vanished, 0) == int2(1, 1));
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique size_constants { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
