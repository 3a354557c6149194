"""The JSON contract (docs/schema/*.json) holds for every command moved to the report
layer: the CLI's --json and the Python result's fields, on valid and invalid inputs."""

import dataclasses
import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

import tetrakit

jsonschema = pytest.importorskip("jsonschema")
ROOT = Path(__file__).resolve().parents[3]
EXE = ROOT / "target" / "release" / "tetrakit"


def schema(name):
    return json.loads((ROOT / "docs" / "schema" / f"{name}.json").read_text())


def cli_json(*args):
    out = subprocess.run([str(EXE), *map(str, args), "--json"], capture_output=True, text=True)
    assert out.returncode in (0, 1), out.stderr
    return json.loads(out.stdout)


def fields(result):
    """A Python result's JSON fields (its arrays left out)."""
    return {f.name: getattr(result, f.name) for f in dataclasses.fields(result)
            if not isinstance(getattr(result, f.name), np.ndarray)}


CUBE = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
KUHN = np.array([[0, 4, 6, 7], [0, 4, 5, 7], [0, 2, 6, 7], [0, 2, 3, 7], [0, 1, 5, 7], [0, 1, 3, 7]])
CASES = {
    "valid": (CUBE, KUHN, {}),
    "convex": (CUBE, KUHN, {"convex": True}),
    "inverted": (CUBE, KUHN[:, [0, 2, 1, 3]], {}),
    "reoriented": (CUBE, KUHN[:, [0, 2, 1, 3]], {"reorient": True}),
    "open": (CUBE, KUHN[:3], {"convex": True}),
    "coincident": (np.vstack([CUBE, CUBE[7:] ]), np.vstack([KUHN[:5], [[0, 1, 3, 8]]]), {}),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_check_json_follows_the_schema(tmp_path, case):
    pts, tets, opts = CASES[case]
    s = schema("check")
    result = tetrakit.check(pts, tets, **opts)
    jsonschema.validate(fields(result), s)
    path = tmp_path / "m.json"
    path.write_text(json.dumps({"points": pts.tolist(), "tets": np.asarray(tets).tolist()}))
    flags = [f"--{k}" for k, v in opts.items() if v]
    out = cli_json("check", path, *flags)
    jsonschema.validate(out, s)
    assert {k: v for k, v in out.items() if k in s["required"]} == {
        k: v for k, v in fields(result).items() if k in s["required"]}


TET_EDGES = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
SQUARE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
DETECT = {
    "tetrahedra": (CUBE[[0, 1, 2, 4]], TET_EDGES),
    "triangles": (SQUARE, np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]])),
    "crossing": (SQUARE, np.array([[0, 1], [1, 2], [2, 3], [3, 0], [0, 2], [1, 3]])),
    "missing": (CUBE[[0, 1, 2, 4]], TET_EDGES[:5]),
}


@pytest.mark.parametrize("case", sorted(DETECT))
def test_detect_json_follows_the_schema(tmp_path, case):
    pts, segs = DETECT[case]
    s = schema("detect")
    result = tetrakit.detect(pts, segs)
    jsonschema.validate(fields(result), s)
    path = tmp_path / "s.json"
    path.write_text(json.dumps({"points": pts.tolist(), "segments": segs.tolist()}))
    out = cli_json("detect", path)
    jsonschema.validate(out, s)
    shared = set(out) - {"seconds", "parse_seconds"}
    assert {k: out[k] for k in shared} == {k: fields(result)[k] for k in shared}
