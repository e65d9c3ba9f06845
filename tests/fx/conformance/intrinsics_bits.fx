// Bit intrinsics and reinterpretation, against values worked out by hand.
// size: 48x2
#include "include/check.fxh"

bool Check(int i)
{
  uint u = uint(IZero);
  switch (i)
  {
    case 0: return countbits(0xF0F0u + u) == 8u;
    case 1: return reversebits(1u + u) == 0x80000000u;
    case 2: return firstbithigh(0x00F0u + u) == 7u && firstbitlow(0x00F0u + u) == 4u;
    case 3: return asuint(1.0 + Zero) == 0x3F800000u && asfloat(0x40000000u + u) == 2.0;
    case 4: return asint(-2.0 + Zero) == int(0xC0000000u) && asfloat(asint(0.25 + Zero)) == 0.25;
    case 5: return f32tof16(1.0 + Zero) == 0x3C00u && f16tof32(0xC000u + u) == -2.0;
    case 6: return ((0xF0u + u) & 0x3Cu) == 0x30u && ((0xF0u + u) | 0x0Fu) == 0xFFu && ((0xF0u + u) ^ 0xFFu) == 0x0Fu;
    case 7: return ((1 + IZero) << 4) == 16 && ((-16 + IZero) >> 2) == -4 && (0x80000000u + u) >> 31 == 1u;
    case 8: return (~(0 + IZero)) == -1 && (~(0u + u)) == 0xFFFFFFFFu;
    case 9: return all(countbits(uint2(3u, 7u) + u) == uint2(2u, 3u));
    case 10: return asuint(-Zero) == 0x80000000u;  // the sign of zero kept
    case 11: return f16tof32(f32tof16(0.5 + Zero)) == 0.5 && f32tof16(65504.0 + Zero) == 0x7BFFu;
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique intrinsics_bits { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
