// Compute passes: thread groups and their IDs, group-shared memory with a barrier, storages
// written with tex2Dstore (FX's rows from the top), atomics, and the back buffer read from a
// compute shader.
// size: 32x2
#include "include/check.fxh"
#include "include/input_picture.fxh"

texture Shared { Width = 8; Height = 8; Format = R32F; };
storage2D SharedOut { Texture = Shared; };
sampler SharedIn { Texture = Shared; MinFilter = POINT; MagFilter = POINT; };
texture Copy { Width = 8; Height = 2; Format = RGBA32F; };
storage2D CopyOut { Texture = Copy; };
sampler CopyIn { Texture = Copy; MinFilter = POINT; MagFilter = POINT; };
texture Count { Format = R32U; };
storage2D<uint> CountOut { Texture = Count; };
sampler2D<uint> CountIn { Texture = Count; };

groupshared float Slots[16];

// Thread i of a 4x4 group writes 2 i to the shared array, waits, then stores its neighbour's
// slot plus 100 times the group's x.
void Neighbours(uint3 id : SV_DispatchThreadID, uint3 group : SV_GroupID, uint index : SV_GroupIndex)
{
  Slots[index] = 2.0 * index;
  barrier();
  tex2Dstore(SharedOut, int2(id.xy), Slots[(index + 1) % 16] + 100.0 * group.x);
}

void CopyBackBuffer(uint3 id : SV_DispatchThreadID)
{
  tex2Dstore(CopyOut, int2(id.xy), float4(tex2Dfetch(ReShade::BackBuffer, int2(id.xy)).rgb, 1.0));
  atomicAdd(CountOut, int2(0, 0), 1u);
}

bool Check(int i)
{
  switch (i)
  {
    case 0: return tex2Dfetch(SharedIn, int2(0, 0) + IZero).x == 2.0;     // group (0, 0), thread 0
    case 1: return tex2Dfetch(SharedIn, int2(5, 2) + IZero).x == 120.0;   // group (1, 0), thread 9
    case 2: return tex2Dfetch(SharedIn, int2(7, 7) + IZero).x == 100.0;   // group (1, 1), thread 15
    case 3: return SameCode(tex2Dfetch(CopyIn, int2(3, 1) + IZero).rgb, InputPixel(int2(3, 1)));
    case 4: return SameCode(tex2Dfetch(CopyIn, int2(6, 0) + IZero).rgb, InputPixel(int2(6, 0)));
    case 5: return tex2Dfetch(CountIn, int2(0, 0) + IZero) == 16u;        // 8 x 2 threads added one each
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique compute
{
  pass { ComputeShader = Neighbours<4, 4>; DispatchSizeX = 2; DispatchSizeY = 2; }
  pass { ComputeShader = CopyBackBuffer<8, 2>; }
  pass { VertexShader = PostProcessVS; PixelShader = Main; }
}
