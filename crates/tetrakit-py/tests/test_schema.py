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


def sphere(n, r, seed):
    g = np.random.default_rng(seed).normal(size=(n, 3))
    return r * g / np.linalg.norm(g, axis=1)[:, None]


@pytest.mark.parametrize("flips, method, limit", [(True, "cap", None), (False, "bigcap", None),
                                                  (True, "cap", 0.0)])
def test_shell_json_follows_the_schema(tmp_path, flips, method, limit):
    outer, inner = sphere(40, 2.0, 1), sphere(15, 1.0, 2)
    s = schema("shell")
    result = tetrakit.shell(outer, inner, method=method, flips=flips, time_limit=limit)
    jsonschema.validate(fields(result), s)
    assert result.verdict == ("undecided" if limit == 0.0 else "yes")
    (tmp_path / "o.xyz").write_text("\n".join(" ".join(repr(float(x)) for x in p) for p in outer))
    (tmp_path / "i.xyz").write_text("\n".join(" ".join(repr(float(x)) for x in p) for p in inner))
    args = ["shell", tmp_path / "o.xyz", tmp_path / "i.xyz", "--method", method]
    args += [] if flips else ["--no-flips"]
    args += [] if limit is None else ["--time-limit", "0"]
    out = subprocess.run([str(EXE), *map(str, args), "--json"], capture_output=True, text=True)
    assert out.returncode == (3 if limit == 0.0 else 0), out.stderr
    cli = json.loads(out.stdout)
    jsonschema.validate(cli, s)
    shared = set(cli) - {"seconds"}
    assert {k: cli[k] for k in shared} == {k: fields(result)[k] for k in shared if k in cli}
