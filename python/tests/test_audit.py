"""fdhcert.audit over numpy arrays against `fdhcert audit --json` on the same frames written as
OBJ files (ctest python_module): the same certificate, timings aside, and a planted crossing
found by both."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import fdhcert

FDHCERT = os.environ["FDHCERT_BIN"]


def grid(n):
    """An n×n sheet in the plane z = 0: vertices (n²×3) and triangles."""
    u = np.linspace(0.0, 1.0, n)
    x, y = np.meshgrid(u, u, indexing="ij")
    verts = np.stack([x.ravel(), y.ravel(), np.zeros(n * n)], axis=1)
    faces = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
            faces += [[a, b, c], [a, c, d]]
    return verts, np.array(faces, dtype=np.int64)


def sequence(frames=5, n=8):
    """A sheet falling and waving above a fixed floor triangle pair, frames F×N×3."""
    verts, faces = grid(n)
    out = []
    for f in range(frames):
        v = verts.copy()
        v[:, 2] = 1.0 - 0.1 * f + 0.02 * np.sin(3 * v[:, 0] + f)
        out.append(v)
    floor = np.array([[-1, -1, 0], [2, -1, 0], [2, 2, 0], [-1, 2, 0]], dtype=float)
    floor_faces = np.array([[0, 1, 2], [0, 2, 3]])
    return np.array(out), faces, floor, floor_faces


def write_obj(path, verts, faces, name=None):
    lines = [f"o {name}"] if name else []
    lines += [f"v {x!r} {y!r} {z!r}" for x, y, z in verts]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    Path(path).write_text("\n".join(lines) + "\n")


def cli(frames, faces, obstacle, obstacle_faces, folder):
    frame_dir = folder / "frames"
    frame_dir.mkdir()
    for f, v in enumerate(frames):
        write_obj(frame_dir / f"frame_{f}.obj", v, faces)
    write_obj(folder / "floor.obj", obstacle, obstacle_faces)
    r = subprocess.run([FDHCERT, "audit", str(frame_dir), "--obstacle", str(folder / "floor.obj"),
                        "--json"], capture_output=True, text=True)
    assert r.returncode in (0, 1), r.stderr
    return r.returncode, json.loads(r.stdout)


def comparable(cert):
    """The certificate without what differs from run to run or names files: the cost, and the
    violations' FILE:LINE places (OBJ input only)."""
    out = json.loads(json.dumps(cert))
    out.pop("cost")
    for v in out["kept"] + ([out["first_violation"]] if out["first_violation"] else []):
        v.pop("places", None)
    return out


def test_clean_sequence_agrees_with_the_program(tmp_path):
    frames, faces, floor, floor_faces = sequence()
    status, program = cli(frames, faces, floor, floor_faces, tmp_path)
    module = fdhcert.audit(frames, faces, obstacles=floor, obstacle_faces=floor_faces)
    assert status == 0
    assert module["clean"] and module["frames"] == 5 and module["steps"] == 4
    assert comparable(module) == comparable(program)
    assert module["cost"]["peak_memory_bytes"] > 0


def test_planted_crossing_found_by_both(tmp_path):
    frames, faces, floor, floor_faces = sequence()
    frames[3, 27, 2] = -0.5  # one vertex pushed through the floor in the step from frame 2 to 3
    status, program = cli(frames, faces, floor, floor_faces, tmp_path)
    module = fdhcert.audit(frames, faces, obstacles=floor, obstacle_faces=floor_faces, threads=1)
    assert status == 1
    assert comparable(module) == comparable(program)
    first = module["first_violation"]
    assert first["kind"] == "cloth-vertex-obstacle"
    assert first["vertices"][0] == 27
    assert (first["frame"], first["to_frame"]) == (2, 3)
    assert 0 < first["toi"]["t_lo"] <= first["toi"]["t_hi"] <= 1
    assert program["first_violation"]["places"][0].endswith("frame_2.obj:28")


def test_obstacles_per_frame_agree_with_the_program(tmp_path):
    """A floor rising through the falling sheet: `--obstacle DIR` (one file per frame) against
    F×P×3 obstacles."""
    frames, faces, floor, floor_faces = sequence(frames=4)
    moving = np.stack([floor + [0, 0, 0.4 * f] for f in range(4)])
    (tmp_path / "frames").mkdir()
    (tmp_path / "floor").mkdir()
    for f in range(4):
        write_obj(tmp_path / "frames" / f"f{f}.obj", frames[f], faces)
        write_obj(tmp_path / "floor" / f"f{f}.obj", moving[f], floor_faces)
    r = subprocess.run([FDHCERT, "audit", str(tmp_path / "frames"), "--obstacle",
                        str(tmp_path / "floor"), "--json"], capture_output=True, text=True)
    assert r.returncode == 1, r.stderr
    d = fdhcert.audit(frames, faces, obstacles=moving, obstacle_faces=floor_faces)
    assert comparable(d) == comparable(json.loads(r.stdout))
    assert d["obstacles"] == {"vertices": 4, "triangles": 2}
    assert d["totals"]["obstacle-vertex-cloth"] + d["totals"]["cloth-vertex-obstacle"] > 0


def test_bad_input():
    frames, faces, floor, floor_faces = sequence(frames=3)
    with pytest.raises(ValueError):
        fdhcert.audit(frames, np.array([[0, 1, 99]]))
    with pytest.raises(ValueError):
        fdhcert.audit(frames[0], faces)
    with pytest.raises(ValueError):
        fdhcert.audit(frames, faces, obstacles=floor)
    bad = frames.copy()
    bad[1, 0, 0] = np.nan
    with pytest.raises(ValueError):
        fdhcert.audit(bad, faces)


def test_refuses_what_it_would_change():
    # As the other functions (docs/python.md, "What the module refuses"): no silent conversion.
    frames, faces, _, _ = sequence(frames=2)
    with pytest.raises(ValueError, match="complex"):
        fdhcert.audit(frames.astype(np.complex128), faces)
    with pytest.raises(ValueError, match="2\\^53"):
        fdhcert.audit(np.full(frames.shape, 2**53 + 1, dtype=np.int64), faces)
    with pytest.raises(ValueError, match="integer"):
        fdhcert.audit(frames, faces.astype(np.float64) + 0.5)
    assert fdhcert.audit(frames.astype(np.float32), faces)["frames"] == 2


def two_sheets(n=6):
    """Two n×n sheets, the second 0.5 above the first in frame 0 and exactly 1/64 above it in
    frames 1 and 2 (issue 31)."""
    verts, faces = grid(n)
    both = np.concatenate([verts, verts + [0, 0, 0.5]])
    near = both.copy()
    near[n * n:, 2] = 2.0**-6
    return np.array([both, near, near]), np.concatenate([faces, faces + n * n])


@pytest.mark.parametrize("d, status", [(None, 0), (0.015625, 1), (0.0156249, 0)])
def test_min_distance_agrees_with_the_program(tmp_path, d, status):
    frames, faces = two_sheets()
    (tmp_path / "frames").mkdir()
    for f in range(3):
        write_obj(tmp_path / "frames" / f"f{f}.obj", frames[f], faces)
    args = [FDHCERT, "audit", str(tmp_path / "frames"), "--json"]
    if d is not None:
        args += ["--min-distance", repr(d)]
    r = subprocess.run(args, capture_output=True, text=True)
    assert r.returncode == status, r.stderr
    module = fdhcert.audit(frames, faces, min_distance=d or 0.0)
    assert comparable(module) == comparable(json.loads(r.stdout))
    assert module["clean"] == (status == 0)
    if d is None:
        assert "proximity" not in module
        assert "self-proximity" not in module["totals"]
    elif status == 1:
        assert module["proximity"]["nearest"]["self"]["squared"] == "1/4096"
        assert module["totals"]["self-proximity"] > 0
        assert module["first_violation"]["kind"].endswith("-proximity")
    else:
        # The sheets' boxes are 1/64 apart, more than D: no pair within reach.
        assert module["proximity"]["nearest"] == {"self": None, "obstacle": None}
        assert module["totals"]["self-proximity"] == 0
