"""pfx.import_model agrees with pfx-import --json on counts and bounds for the models the tests
use (and a real one Debian ships), and its arrays are shaped as docs/python.md says."""

import json
import os

import numpy as np
import pfx
import pytest

from conftest import IMPORT, SOURCE_DIR, run_program

MODELS = [os.path.join(SOURCE_DIR, "tests/programs/import/models", m)
          for m in ("assimp_style/crates.obj", "tinyobj_style/cubes.obj", "broken/broken.obj")]
MODELS += [os.path.join(SOURCE_DIR, "tests/objimport/fuzz/corpus", m)
           for m in ("every_statement.obj", "concave_and_degenerate.obj", "triangle.obj")]
MODELS += ["/usr/share/glmark2/models/bunny.obj"]


@pytest.mark.parametrize("path", MODELS, ids=os.path.basename)
def test_import_model_agrees_with_pfx_import(path):
    expected = json.loads(run_program(IMPORT, path, "--json"))
    model = pfx.import_model(path)
    n = len(model.positions)
    assert n == expected["vertices"]
    assert len(model.indices) == 3 * expected["triangles"]
    assert len(model.submeshes) == expected["submeshes"]
    assert len(model.materials) == expected["materials"]
    assert model.lines_skipped == expected["lines"] and model.points_skipped == expected["points"]
    assert model.warning_total == expected["warnings_total"]
    bounds = model.bounds_min.tolist() + model.bounds_max.tolist()
    assert bounds == pytest.approx(expected["bounds"][0] + expected["bounds"][1], rel=1e-6)

    assert model.positions.shape == (n, 3) and model.positions.dtype == np.float32
    assert model.normals.shape == (n, 3)
    assert model.uvs is None or model.uvs.shape == (n, 2)
    assert model.indices.dtype == np.uint32 and (model.indices < max(n, 1)).all()
    assert model.submeshes.shape == (len(model.submeshes), 3)
    if n:
        assert np.allclose(model.positions.min(axis=0), model.bounds_min)
        assert np.allclose(model.positions.max(axis=0), model.bounds_max)


def test_a_file_no_importer_takes_raises(tmp_path):
    path = tmp_path / "model.stl"
    path.write_text("solid x\nendsolid x\n")
    with pytest.raises(pfx.Error, match="no importer takes this kind of file.*obj"):
        pfx.import_model(str(path))


def test_a_missing_file_raises_with_its_name(tmp_path):
    with pytest.raises(pfx.Error, match="missing.obj"):
        pfx.import_model(str(tmp_path / "missing.obj"))
