// HLSL's arithmetic intrinsics at chosen inputs, each against its value worked out by hand,
// including those whose GLSL namesake means something else (fmod, frac, round, sign, atan2).
// size: 160x2
#include "include/check.fxh"

bool Check(int i)
{
  float s, c, e, ip;
  switch (i)
  {
    case 0: return Near(fmod(-5.5 + Zero, 2.0), -1.5);          // the sign of x, not of y
    case 1: return Near(frac(-1.25 + Zero), 0.75);               // x - floor(x)
    case 2: return Near(lerp(2.0, 4.0, 0.25 + Zero), 2.5);
    case 3: return saturate(1.5 + Zero) == 1.0 && saturate(-0.5 + Zero) == 0.0;
    case 4: return Near(rsqrt(4.0 + Zero), 0.5);
    case 5: return Near(rcp(4.0 + Zero), 0.25);
    case 6: return Near(atan2(1.0 + Zero, -1.0), 2.35619449);  // atan2(y, x): the second quadrant
    case 7: sincos(0.5 + Zero, s, c); return Near(s, 0.47942554) && Near(c, 0.87758256);
    case 8: return step(0.5, 0.4 + Zero) == 0.0 && step(0.5, 0.6 + Zero) == 1.0 && step(0.5, 0.5 + Zero) == 1.0;
    case 9: return Near(smoothstep(0.0, 2.0, 0.5 + Zero), 0.15625);
    case 10: return sign(-3.0 + Zero) == -1 && sign(Zero) == 0 && sign(2.5 + Zero) == 1;  // an int
    case 11: return round(2.5 + Zero) == 2.0 && round(3.5 + Zero) == 4.0 && round(-2.5 + Zero) == -2.0;  // half to even
    case 12: return trunc(-1.7 + Zero) == -1.0 && floor(-1.5 + Zero) == -2.0 && ceil(-1.5 + Zero) == -1.0;
    case 13: return mad(2.0 + Zero, 3.0, 4.0) == 10.0;
    case 14: return ldexp(1.5 + Zero, 3.0) == 12.0;
    case 15: { float m = frexp(12.0 + Zero, e); return m == 0.75 && e == 4.0; }
    case 16: { float f = modf(-2.75 + Zero, ip); return f == -0.75 && ip == -2.0; }
    case 17: return Near(log10(1000.0 + Zero), 3.0) && exp2(3.0 + Zero) == 8.0 && Near(pow(2.0 + Zero, 10.0), 1024.0);
    case 18: return Near(log(exp(1.0 + Zero)), 1.0) && Near(log2(8.0 + Zero), 3.0) && sqrt(9.0 + Zero) == 3.0;
    case 19: return dot(float3(1, 2, 3), float3(4, 5, 6) + Zero) == 32.0;
    case 20: return all(cross(float3(1, 0, 0), float3(0, 1, 0) + Zero) == float3(0, 0, 1));
    case 21: return Near(length(float2(3, 4) + Zero), 5.0) && Near(distance(float2(1, 1), float2(4, 5) + Zero), 5.0);
    case 22: return Near(normalize(float2(0, 3) + Zero), float2(0, 1));
    case 23: return Near(reflect(float2(1, -1) + Zero, float2(0, 1)), float2(1, 1));
    case 24: return abs(-3 + IZero) == 3 && min(-2 + IZero, 5) == -2 && max(7u + uint(IZero), 3u) == 7u && clamp(12 + IZero, 0, 10) == 10;
    case 25: return Near(degrees(3.14159265 + Zero), 180.0) && Near(radians(180.0 + Zero), 3.14159265);
    case 26: { float x = Zero / Zero; float y = 1.0 / Zero; return isnan(x) && isinf(y) && !isfinite(y) && isfinite(1.0 + Zero); }
    case 27: return Close(sin(1.0 + Zero), 0.84147098) && Close(cos(1.0 + Zero), 0.54030231) && Close(tan(0.5 + Zero), 0.54630249);
    case 28: return Close(asin(0.5 + Zero), 0.52359878) && Close(acos(0.5 + Zero), 1.04719755) && Close(atan(1.0 + Zero), 0.78539816);
    case 29: return Close(sinh(1.0 + Zero), 1.17520119) && Close(cosh(1.0 + Zero), 1.54308063) && Close(tanh(1.0 + Zero), 0.76159416);
    case 30: return all(max(float2(1, 5) + Zero, float2(3, 2)) == float2(3, 5)) && all(abs(float2(-1, 2) + Zero) == float2(1, 2));
    case 31: return any(float3(0, 0, 1) + Zero) && !any(float2(0, 0) + Zero) && all(float2(1, -1) + Zero) && !all(float2(1, 0) + Zero);
    case 32: return Near(lerp(float2(0, 10), float2(10, 20) + Zero, float2(0.5, 0.1)), float2(5, 11));
    case 33: return Near(fmod(float2(5.5, -7.0) + Zero, float2(2.0, 3.0)), float2(1.5, -1.0));
    case 34: return Near(refract(float2(0, -1) + Zero, float2(0, 1), 1.0), float2(0, -1));
    case 35: return exp(Zero) == 1.0 && Near(exp(1.0 + Zero), 2.71828183);
    case 36: return Near(fwidth(Zero), 0.0) && ddx(Zero) == 0.0;
    case 37: return frac(2.0 + Zero) == 0.0 && frac(0.25 + Zero) == 0.25;
    case 38: return clamp(-0.5 + Zero, 0.0, 1.0) == 0.0 && min(-0.0 + Zero, 0.5) <= 0.0;
    case 39: return Near(saturate(float3(-1, 0.5, 2) + Zero), float3(0, 0.5, 1));
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique intrinsics_math { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
