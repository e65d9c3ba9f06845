"""pfx.effects() describes the effects as pfx-render --list --json does, and Chain.params() gives
every instance's values with those descriptions."""

import json

import pfx

from conftest import RENDER, run_program


def test_effects_are_described_as_pfx_render_lists_them():
    listing = json.loads(run_program(RENDER, "--list", "--json"))
    expected = [dict(effect, plugin=plugin["id"], plugin_path=plugin["path"])
                for plugin in listing["plugins"] for effect in plugin["effects"]]
    assert pfx.effects() == expected
    assert {"bloom", "glare", "dof", "tiledlights"} <= {e["id"] for e in expected}


def test_params_hold_every_instance_with_its_values_and_descriptions():
    effects = {e["id"]: e for e in pfx.effects()}
    with pfx.Chain(["bloom", "dof", "bloom"]) as chain:
        chain.set("bloom#2.threshold", 4.5)
        params = chain.params()
        assert list(params) == ["bloom", "dof", "bloom#2"]
        for instance, values in params.items():
            effect = effects[instance.split("#")[0]]
            assert list(values) == [p["id"] for p in effect["parameters"]]
            for description in effect["parameters"]:
                entry = values[description["id"]]
                assert entry["key"] == f"{instance}.{description['id']}"
                assert {k: v for k, v in entry.items() if k not in ("value", "key")} == \
                       {k: v for k, v in description.items() if k != "key"}
        assert params["bloom#2"]["threshold"]["value"] == 4.5 == chain.get("bloom#2.threshold")
        assert params["bloom"]["threshold"]["value"] == params["bloom"]["threshold"]["default"]


def test_display_defaults_start_where_the_descriptions_say():
    with pfx.Chain(["bloom"], defaults="display") as chain:
        threshold = chain.params()["bloom"]["threshold"]
        assert threshold["value"] == threshold["display_default"] != threshold["default"]


def test_the_report_is_pfx_renders_for_the_same_run(pictures, tmp_path):
    path, pixels = pictures["demo"]
    expected = json.loads(run_program(RENDER, "--input", path, "--chain", "bloom,glare", "--out",
                                      tmp_path / "out.exr", "--json"))
    with pfx.Chain(["bloom", "glare"]) as chain:
        assert chain.report is None
        chain.run(pixels)
        report = chain.report
        assert report["renderer"] == expected["renderer"] == chain.renderer
    for key in ("effects", "effects_skipped", "timing", "peak_target_bytes", "unpooled_target_bytes", "effect_reports"):
        assert report[key] == expected[key], key
    assert [(p["effect"], p["pass"]) for p in report["passes"]] == [(p["effect"], p["pass"]) for p in expected["passes"]]
    assert all(p["ms"] > 0 for p in report["passes"]) and report["total_ms"] > 0
