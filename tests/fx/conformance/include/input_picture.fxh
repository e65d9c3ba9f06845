// The input picture run_conformance.py makes, worked out independently of pfx: the 8-bit value of
// each channel at pixel (x, y), counted from the top-left corner as FX counts.
float3 InputPixel(int2 p)
{
  return float3((p.x * 37 + p.y * 11) % 256, (p.x * 5 + p.y * 67) % 256, (p.x * 3 + 128) % 256) / 255.0;
}
// Within half a code of an 8-bit value.
bool SameCode(float3 a, float3 b) { return all(abs(a - b) <= 0.5 / 255.0); }
