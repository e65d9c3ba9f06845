// pfx's ReShade.fxh: the common declarations FX effects include, for shader folders that do not
// bring their own (a folder's own ReShade.fxh is found first). Written for pfx from the FX
// language reference; MIT licence, like the rest of pfx.
#pragma once

#define BUFFER_PIXEL_SIZE float2(BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT)
#define BUFFER_SCREEN_SIZE float2(BUFFER_WIDTH, BUFFER_HEIGHT)
#define BUFFER_ASPECT_RATIO (BUFFER_WIDTH * BUFFER_RCP_HEIGHT)

// pfx hands FX effects the depth buffer as standard (not reversed, not logarithmic) window-space
// depth of a projection whose far plane is RESHADE_DEPTH_LINEARIZATION_FAR_PLANE times its near
// plane, so GetLinearizedDepth below needs no per-game settings.
#ifndef RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN
#define RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN 0
#endif
#ifndef RESHADE_DEPTH_INPUT_IS_REVERSED
#define RESHADE_DEPTH_INPUT_IS_REVERSED 0
#endif
#ifndef RESHADE_DEPTH_INPUT_IS_LOGARITHMIC
#define RESHADE_DEPTH_INPUT_IS_LOGARITHMIC 0
#endif
#ifndef RESHADE_DEPTH_MULTIPLIER
#define RESHADE_DEPTH_MULTIPLIER 1
#endif
#ifndef RESHADE_DEPTH_LINEARIZATION_FAR_PLANE
#define RESHADE_DEPTH_LINEARIZATION_FAR_PLANE 1000.0
#endif

namespace ReShade
{
  static const float AspectRatio = BUFFER_WIDTH * BUFFER_RCP_HEIGHT;
  static const float2 PixelSize = float2(BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT);
  static const float2 ScreenSize = float2(BUFFER_WIDTH, BUFFER_HEIGHT);
  float GetAspectRatio() { return AspectRatio; }
  float2 GetPixelSize() { return PixelSize; }
  float2 GetScreenSize() { return ScreenSize; }

  texture BackBufferTex : COLOR;
  texture DepthBufferTex : DEPTH;
  sampler BackBuffer { Texture = BackBufferTex; };
  sampler DepthBuffer { Texture = DepthBufferTex; };

  // Depth from 0 at the camera to 1 at the far plane, linear in distance.
  float GetLinearizedDepth(float2 texcoord)
  {
#if RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN
    texcoord.y = 1.0 - texcoord.y;
#endif
    float depth = tex2Dlod(DepthBuffer, float4(texcoord, 0, 0)).x * RESHADE_DEPTH_MULTIPLIER;
#if RESHADE_DEPTH_INPUT_IS_LOGARITHMIC
    depth = (exp(depth * log(1.01)) - 1.0) / 0.01;
#endif
#if RESHADE_DEPTH_INPUT_IS_REVERSED
    depth = 1.0 - depth;
#endif
    // Window depth d of near n = 1 and far f: linear = d / (f - d * (f - 1)).
    const float far_plane = RESHADE_DEPTH_LINEARIZATION_FAR_PLANE;
    return depth / (far_plane - depth * (far_plane - 1.0));
  }
}

// A triangle covering the screen, with texture coordinates from (0, 0) at the top left.
void PostProcessVS(in uint id : SV_VertexID, out float4 position : SV_Position, out float2 texcoord : TEXCOORD)
{
  texcoord = float2(id == 2 ? 2.0 : 0.0, id == 1 ? 2.0 : 0.0);
  position = float4(texcoord * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
}
