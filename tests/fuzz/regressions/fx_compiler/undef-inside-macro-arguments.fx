#define F(x) x
float4 PS(float4 p : SV_Position) : SV_Target { return F(
#undef F
1); }
technique T { pass { VertexShader = 0; PixelShader = PS; } }
