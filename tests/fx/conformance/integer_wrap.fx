// Integer constants wrap at 32 bits as HLSL's integers do, in the values the runtime works out on
// the CPU (uniform initialisers, which become parameter values and, once they hold still,
// constants in the program): 0u - 1u is 0xFFFFFFFF, 0x7FFFFFFF + 1 is INT_MIN, ~0u is
// 0xFFFFFFFF, a product or a shift past 32 bits loses its high bits. Each expected value is a
// literal HLSL itself gives for the expression.
// size: 40x2
#include "include/check.fxh"

uniform uint MinusOne = 0u - 1u;
uniform int PastMax = 0x7FFFFFFF + 1;
uniform uint AllOnes = ~0u;
uniform uint Product = 0x10000u * 0x10000u + 5u;
uniform int Shifted = 1 << 31;
uniform uint ShiftedOut = (1u << 31) * 2u;
uniform int NegatedMin = -(0x7FFFFFFF + 1);
uniform uint FromInt = uint(-2);
uniform int FromUint = int(0xFFFFFFFEu);
uniform int2 Pair = int2(0x7FFFFFFF, 1) + int2(1, 0x7FFFFFFF);

bool Check(int i)
{
  switch (i)
  {
    case 0: return MinusOne == 4294967295u;
    case 1: return PastMax == -2147483647 - 1;
    case 2: return AllOnes == 4294967295u;
    case 3: return Product == 5u;
    case 4: return Shifted == -2147483647 - 1;
    case 5: return ShiftedOut == 0u;
    case 6: return NegatedMin == -2147483647 - 1;
    case 7: return FromInt == 4294967294u && FromUint == -2;
    case 8: return all(Pair == int2(-2147483647 - 1, -2147483647 - 1));
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique integer_wrap { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
