"""pfx.Chain(preset=...): a pfx preset gives the chain, each effect on or off and its values, and an
8-bit picture comes out as pfx-render --preset writes it, bit for bit; a ReShade preset (.ini)
drives FX effects in its order with its values and its PreprocessorDefinitions, and what it names
that is not loaded is one warning; a preset that does not read raises pfx.Error. The FX plugin
reads its folders once per process, so PFX_FX_PATH is set before pfx is imported."""

import json
import os

import numpy as np
import pytest

LISTING = os.path.join(os.environ["PFX_SOURCE_DIR"], "tests", "fx", "listing", "Shaders")
os.environ["PFX_FX_PATH"] = LISTING

import pfx  # noqa: E402

from conftest import PHOTOGRAPH, run_program, RENDER  # noqa: E402
from test_8bit import read_png  # noqa: E402


def test_a_pfx_preset_gives_pfx_render_s_chain_flags_and_values(tmp_path):
    preset = tmp_path / "look.json"
    preset.write_text(json.dumps({"pfx_preset": 1, "chain": [{"effect": "bloom"}, {"effect": "glare", "enabled": False}],
                                  "parameters": {"bloom": {"strength": 2.5}}}))
    expected_path = tmp_path / "expected.png"
    run_program(RENDER, "--input", PHOTOGRAPH, "--preset", preset, "--out", expected_path)
    picture = read_png(PHOTOGRAPH)[..., :3].copy()
    with pfx.Chain(preset=str(preset)) as chain:
        assert chain.effects == ["bloom", "glare"]
        assert chain.get("bloom.strength") == 2.5
        actual = chain.run(picture)
    assert np.array_equal(actual, read_png(expected_path)[..., :3]), "not pfx-render's bytes"
    assert not np.array_equal(actual, picture), "bloom changed nothing: the comparison would prove nothing"


def test_effects_given_replace_the_preset_s_chain_and_its_values_still_apply(tmp_path):
    preset = tmp_path / "look.json"
    preset.write_text(json.dumps({"pfx_preset": 1, "chain": [{"effect": "glare"}],
                                  "parameters": {"bloom": {"strength": 2.5}}}))
    with pfx.Chain(["bloom"], preset=str(preset)) as chain:
        assert chain.effects == ["bloom"]
        assert chain.get("bloom.strength") == 2.5
        # A preset's value is fixed, as set() fixes one: an 8-bit picture does not move it to the
        # display-referred default.
        chain.run(np.zeros((4, 4, 3), np.uint8))
        assert chain.get("bloom.strength") == 2.5


def test_a_reshade_preset_drives_fx_effects_with_its_values_and_definitions(tmp_path):
    preset = tmp_path / "look.ini"
    preset.write_text("PreprocessorDefinitions=PFX_TEST_LEVEL=0.75\n"
                      "Techniques=GoodTint@Good.fx,DefinedLevel@Level.fx,Missing@Missing.fx\n"
                      "TechniqueSorting=DefinedLevel@Level.fx,GoodTint@Good.fx,Missing@Missing.fx\n\n"
                      "[Good.fx]\nAmount=0.000000\n")
    with pytest.warns(RuntimeWarning, match="fx_missing"):
        chain = pfx.Chain(preset=str(preset))
    with chain:
        assert chain.effects == ["fx_definedlevel", "fx_goodtint"]
        assert chain.get("fx_goodtint.amount") == 0
        out = chain.run(np.full((4, 4, 3), 100, np.uint8))
    # DefinedLevel writes the preset's 0.75 everywhere (the file's own default is 0.25, code 64);
    # GoodTint at Amount 0 keeps it.
    assert np.abs(out.astype(int) - 191).max() <= 1, out[0, 0]


def test_a_preset_that_does_not_read_raises(tmp_path):
    broken = tmp_path / "broken.json"
    broken.write_text("{\"pfx_preset\": 1, \"chain\": ")
    with pytest.raises(pfx.Error, match="broken.json"):
        pfx.Chain(preset=str(broken))
    with pytest.raises(pfx.Error, match="missing.ini"):
        pfx.Chain(preset=str(tmp_path / "missing.ini"))
