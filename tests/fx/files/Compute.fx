// Compute passes: integer storages, group shared memory, barriers and atomics, a histogram.
#include "Common.fxh"
#pragma reshade skipoptimization

#define GROUP_SIZE 8
#define BINS 64

texture2D HistogramTex { Width = BINS; Height = 1; Format = R32U; };
texture2D CountTex { Width = 1; Height = 1; Format = R32I; };
storage2D<uint> HistogramStore { Texture = HistogramTex; };
storage2D<int> CountStore { Texture = CountTex; MipLevel = 0; };
sampler2D<uint> Histogram { Texture = HistogramTex; };

groupshared uint LocalBins[BINS];
groupshared int LocalCount;

[numthreads(GROUP_SIZE, GROUP_SIZE, 1)]
void ClearCS(uint3 id : SV_DispatchThreadID)
{
	if (id.y == 0 && id.x < BINS)
		tex2Dstore(HistogramStore, int2(id.x, 0), 0u);
}

void CountCS(uint3 id : SV_DispatchThreadID, uint3 tid : SV_GroupThreadID, uint index : SV_GroupIndex)
{
	if (index < BINS) LocalBins[index] = 0;
	if (index == 0) LocalCount = 0;
	barrier();
	float3 color = tex2Dfetch(Common::BackBuffer, int2(id.xy)).rgb;
	uint bin = (uint)(saturate(dot(color, 1.0 / 3.0)) * (BINS - 1));
	atomicAdd(LocalBins[bin], 1u);
	atomicAdd(LocalCount, 1);
	groupMemoryBarrier();
	barrier();
	if (index < BINS)
		atomicAdd(HistogramStore, int2(index, 0), LocalBins[index]);
	if (index == 0)
	{
		int previous = atomicExchange(CountStore, int2(0, 0), LocalCount);
		atomicMax(CountStore, int2(0, 0), previous);
	}
	memoryBarrier();
}

float4 ShowPS(float4 position : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
	uint count = tex2Dfetch(Histogram, int2(uv.x * BINS, 0));
	float height = count / (float)(BUFFER_WIDTH * BUFFER_HEIGHT) * BINS;
	return uv.y > 1.0 - height ? 1.0 : tex2D(Common::BackBuffer, uv);
}

technique Histogram
{
	pass Clear { ComputeShader = ClearCS<GROUP_SIZE, GROUP_SIZE>; DispatchSizeX = BINS / GROUP_SIZE; DispatchSizeY = 1; }
	pass Count
	{
		ComputeShader = CountCS<GROUP_SIZE, GROUP_SIZE, 1>;
		DispatchSizeX = BUFFER_WIDTH / GROUP_SIZE;
		DispatchSizeY = BUFFER_HEIGHT / GROUP_SIZE;
		DispatchSizeZ = 1;
	}
	pass Show { VertexShader = PostProcessVS; PixelShader = ShowPS; }
}
