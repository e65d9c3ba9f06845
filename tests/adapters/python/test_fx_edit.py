"""An FX file edited while its effect runs (docs/fx.md): the next frame after an edit that compiles
runs the new version, with the parameter values kept; an edit that does not compile leaves the last
version that did running. Through the Python module, which runs frame after frame in one process
as an application does. The FX plugin reads its folders once per process, so PFX_FX_PATH is set
before the first chain."""

import os
import tempfile
import time

import numpy as np

FOLDER = tempfile.mkdtemp(prefix="pfx-fx-edit-")
EFFECT = os.path.join(FOLDER, "Edited.fx")
os.environ["PFX_FX_PATH"] = FOLDER

SOURCE = """#include "ReShade.fxh"
uniform float Gain < ui_type = "slider"; ui_min = 0.0; ui_max = 1.0; > = 1.0;
float4 Main(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target
{
  float3 c = tex2D(ReShade::BackBuffer, uv).rgb;
  return float4(%s, 1.0);
}
technique Edited { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
"""


def write(expression):
    with open(EFFECT, "w") as f:
        f.write(SOURCE % expression)
    # The plugin looks at the file's time every half second; let the clock move past both.
    time.sleep(0.6)


write("(1.0 - c) * Gain")  # before the catalog reads the folder

import pfx  # noqa: E402


def test_edits_take_effect_and_broken_ones_keep_the_last_good_version():
    picture = np.zeros((8, 8, 3), dtype=np.uint8)
    picture[..., 0] = 40
    picture[..., 1] = 120
    picture[..., 2] = 200
    with pfx.Chain(["fx_edited"]) as chain:
        chain.set("fx_edited.gain", 1.0)
        inverted = chain.run(picture)
        assert np.array_equal(inverted, 255 - picture)

        write("c * Gain")  # now a copy: the same picture back
        assert np.array_equal(chain.run(picture), picture)

        chain.set("fx_edited.gain", 0.5)  # the value reaches the new version
        halved = chain.run(picture).astype(int)
        assert np.abs(halved - picture // 2).max() <= 1

        write("c * Gain +")  # a syntax error: the last good version keeps running
        assert np.abs(chain.run(picture).astype(int) - picture // 2).max() <= 1
