texture2D T { Width = 64; Height = 1; Format = R32U; };
storage2D<uint> S { Texture = T; };
groupshared uint Bins[64];
void CS(uint3 id : SV_DispatchThreadID, uint index : SV_GroupIndex)
{
	Bins[index] = 0; barrier(); atomicAdd(Bins[index], 1u); barrier();
	tex2Dstore(S, int2(index, 0), Bins[index]);
}
technique C { pass { ComputeShader = CS<64, 1, 1>; DispatchSizeX = 1; DispatchSizeY = 1; } }
