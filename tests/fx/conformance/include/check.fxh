// What the self-checking conformance files share: check i is judged in the pixel columns
// [4i, 4i + 4) of the output, green when it holds and red when it does not (run_conformance.py).
#include "ReShade.fxh"

// Zero that the GLSL compiler cannot fold: results are computed when the shader runs.
uniform float Zero = 0.0;
uniform int IZero = 0;

int CheckIndex(float4 position) { return int(position.x) / 4; }

float4 Verdict(bool ok) { return ok ? float4(0.0, 1.0, 0.0, 1.0) : float4(1.0, 0.0, 0.0, 1.0); }

// Transcendental functions are approximations on GPUs (GLSL leaves their precision open).
bool Close(float a, float b) { return abs(a - b) <= 1e-3 * max(1.0, abs(b)); }
bool Near(float a, float b) { return abs(a - b) <= 1e-5 * max(1.0, abs(b)); }
bool Near(float2 a, float2 b) { return Near(a.x, b.x) && Near(a.y, b.y); }
bool Near(float3 a, float3 b) { return Near(a.xy, b.xy) && Near(a.z, b.z); }
bool Near(float4 a, float4 b) { return Near(a.xy, b.xy) && Near(a.zw, b.zw); }
