#define F(x, ...) CAT(x, __VA_ARGS__)
#if defined(F) && (1 << 4) == 16 && __RENDERER__ >= 0x10000
#include "common.fxh"
#line 40 "other.fx"
struct S { float3x2 m; int2 v; };
float Sum(S s) { return s.m._m00 + s.m._21 + s.v.x + 1.0.x; }
#elif 0
#error never
#else
#warning never
#endif
