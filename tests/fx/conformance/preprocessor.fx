// The preprocessor: macros with and without arguments, conditionals with defined(), #undef,
// #include relative to the file, #pragma once, line continuations, token pasting, __LINE__, and
// the macros ReShade predefines (the frame here is 64x2).
// size: 64x2
#include "include/check.fxh"
#include "include/defines.fxh"
#include "include/defines.fxh"

#define SQUARE(x) ((x) * (x))
#define ADD3(a, b, c) (a + b + c)
#define LONG_SUM 1 + \
                 2 + \
                 3
#define PASTE(a, b) a##b
#define TWICE SQUARE(2)
#define GONE 1
#undef GONE

#if defined(GONE)
#error "GONE was undefined"
#endif

#if !defined(FROM_INCLUDE)
  #define FROM_INCLUDE_SEEN 0
#elif FROM_INCLUDE == 42
  #define FROM_INCLUDE_SEEN 1
#else
  #define FROM_INCLUDE_SEEN 2
#endif

#ifdef __RESHADE__
  #define HAS_RESHADE 1
#endif
#ifndef HAS_RESHADE
  #define HAS_RESHADE 0
#endif

static const int LineHere = __LINE__;

bool Check(int i)
{
  int PASTE(my, value) = 7 + IZero;
  switch (i)
  {
    case 0: return SQUARE(3 + IZero) == 9 && ADD3(1, 2, 3 + IZero) == 6 && LONG_SUM + IZero == 6;
    case 1: return myvalue == 7 && TWICE + IZero == 4;
    case 2: return FROM_INCLUDE_SEEN == 1 + IZero && HAS_RESHADE == 1;
    case 3: return LineHere == 38;
    case 4: return BUFFER_WIDTH == 64 && BUFFER_HEIGHT == 2 + IZero;
    case 5: return Near(BUFFER_RCP_WIDTH + Zero, 1.0 / 64.0) && Near(BUFFER_RCP_HEIGHT + Zero, 0.5);
    case 6: return BUFFER_COLOR_BIT_DEPTH == 8 && __RESHADE__ >= 50000 && __RENDERER__ == 0x14500 + IZero;
    case 7: return Near(ReShade::PixelSize + Zero, float2(1.0 / 64.0, 0.5)) && Near(BUFFER_ASPECT_RATIO + Zero, 32.0);
#if BUFFER_WIDTH > 32 && (BUFFER_HEIGHT < 4 || defined(NEVER))
    case 8: return true;
#else
    case 8: return false;
#endif
    default: return true;
  }
}

float4 Main(float4 position : SV_Position, float2 texcoord : TEXCOORD) : SV_Target
{
  return Verdict(Check(CheckIndex(position)));
}

technique preprocessor { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
