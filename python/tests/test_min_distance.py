"""min_distance= (issue 30, docs/python.md "Minimum separation"): the module's δ answers against
answers known by construction and against the fdhcert program's on the same queries."""
import csv
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import fdhcert

FDHCERT = os.environ["FDHCERT_BIN"]
DATA = Path(os.environ["FDH_SOURCE_DIR"]) / "tests" / "data"

D = 2.0**-20
TRI = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]


def drifting(points):
    """A query whose 4 points all move by (0, 0, 1): every distance stays what it is at t = 0."""
    p = np.array(points, dtype=float)
    return np.concatenate([p, p + [0, 0, 1]])


def known_vertex_face():
    """Moving vertex-face queries whose least Euclidean distance is exactly D, by construction:
    over the face's interior, beside an edge, beyond a corner (each at D along one axis)."""
    return np.array([drifting([[0.25, 0.25, D], *TRI]),
                     drifting([[-D, 0.25, 0], *TRI]),
                     drifting([[1 + D, 0, 0], *TRI])])


def known_edge_edge():
    """Parallel edges D apart, and crossing edges D apart (one above the other)."""
    return np.array([drifting([[0, 0, 0], [1, 0, 0], [0, D, 0], [1, D, 0]]),
                     drifting([[0, 0, 0], [1, 0, 0], [0.5, -1, D], [0.5, 1, D]])])


def known_static():
    """A point sliding at height D over a still triangle (the static decision)."""
    return np.array([[[0.25, 0.25, D], *TRI, [0.5, 0.25, D], *TRI]], dtype=float)


def exact_answers_min_distance():
    return "exact" in fdhcert.min_distance_methods()


needs_exact = pytest.mark.skipif(not exact_answers_min_distance(),
                                 reason="the exact twin does not answer min_distance > 0 yet")


@needs_exact
@pytest.mark.parametrize("method", ["exact", "robust"])
def test_the_answers_at_a_distance_are_those_known_by_construction(method):
    if method not in fdhcert.min_distance_methods():
        pytest.skip(f"{method} does not answer min_distance > 0 yet")
    for test, queries in ((fdhcert.vertex_face_ccd, known_vertex_face()),
                          (fdhcert.edge_edge_ccd, known_edge_edge()),
                          (fdhcert.point_triangle, known_static())):
        assert test(queries, method, min_distance=D).all(), test.__name__
        assert test(queries, method, min_distance=D * (1 + 2.0**-40)).all(), test.__name__
        assert not test(queries, method, min_distance=D * (1 - 2.0**-40)).any(), test.__name__
        assert not test(queries, method).any(), test.__name__  # never in contact


@needs_exact
def test_the_time_within_a_distance_is_enclosed():
    # The point falls through the face: z = 1 - 2t is within D from t* = (1 - D) / 2 on.
    q = np.array([[[0.25, 0.25, 1], *TRI, [0.25, 0.25, -1], *TRI]], dtype=float)
    t_star = (1 - D) / 2  # exact: a dyadic
    for method in {"exact", "robust"} & set(fdhcert.min_distance_methods()):
        hit, t_lo, t_hi = fdhcert.vertex_face_toi(q, method, 2.0**-40, min_distance=D)
        assert hit[0] and t_lo[0] <= t_star <= t_hi[0] and t_hi[0] - t_lo[0] <= 2.0**-40, method


def test_min_distance_zero_is_the_contact_question_bit_for_bit():
    pts = np.concatenate([known_vertex_face(), known_static()])
    for method in ("exact", "robust", "float-cubic"):
        assert (fdhcert.vertex_face_ccd(pts, method, min_distance=0.0)
                == fdhcert.vertex_face_ccd(pts, method)).all()
        a = fdhcert.vertex_face_toi(pts, method, min_distance=0)
        b = fdhcert.vertex_face_toi(pts, method)
        assert all((x == y).all() for x, y in zip(a, b)), method


def test_a_bad_min_distance_or_a_contact_only_method_is_refused():
    q = known_vertex_face()
    for bad in (-1e-300, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="min_distance"):
            fdhcert.vertex_face_ccd(q, "robust", min_distance=bad)
        with pytest.raises(ValueError, match="min_distance"):
            fdhcert.edge_edge_toi(known_edge_edge(), min_distance=bad)
    for method in set(fdhcert.methods()) - set(fdhcert.min_distance_methods()):
        with pytest.raises(ValueError, match="contact only"):
            fdhcert.point_triangle(known_static(), method, min_distance=D)
        assert fdhcert.point_triangle(known_static(), method).shape == (1,)  # at contact, yes


def program_takes_min_distance():
    r = subprocess.run([FDHCERT, "classify", "--help"], capture_output=True, text=True)
    return "--min-distance" in r.stdout


def write_vf(path, kind, queries):
    """A query file (docs/formats.md), every coordinate in exact hex."""
    with open(path, "w") as f:
        for i, q in enumerate(queries):
            f.write(f"{kind} q{i} " + " ".join(float(v).hex() for v in q.ravel()) + "\n")


@pytest.mark.skipif(not program_takes_min_distance(),
                    reason="fdhcert classify has no --min-distance yet")
@pytest.mark.parametrize("delta", [0.0, D, D * (1 - 2.0**-40), 2.0**-10])
def test_the_answers_equal_the_programs_on_the_same_queries(delta, tmp_path):
    methods = [m for m in ("exact", "robust", "float-cubic")
               if delta == 0 or m in fdhcert.min_distance_methods()]
    if not methods:
        pytest.skip("no method of the registry answers min_distance > 0 yet")
    cases = (("vf", fdhcert.vertex_face_ccd, fdhcert.vertex_face_toi, known_vertex_face()),
             ("ee", fdhcert.edge_edge_ccd, fdhcert.edge_edge_toi, known_edge_edge()))
    for kind, test, toi, queries in cases:
        path, out = tmp_path / f"q.{kind}", tmp_path / f"{kind}.csv"
        write_vf(path, kind, queries)
        r = subprocess.run([FDHCERT, "classify", path, "--methods", ",".join(methods), "--toi",
                            "--min-distance", repr(delta), "--per-query", out],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        rows = list(csv.DictReader(out.open()))
        for method in methods:
            mine = test(queries, method, min_distance=delta)
            assert [int(row[method]) for row in rows] == [int(v) for v in mine], (method, delta)
            hit, t_lo, t_hi = toi(queries, method, 2.0**-30, min_distance=delta)
            for i, row in enumerate(rows):  # the program's enclosure, empty without a hit
                lo, hi = row[f"{method} t_lo"], row[f"{method} t_hi"]
                assert bool(hit[i]) == (lo != ""), (method, delta, i)
                if hit[i]:
                    assert (t_lo[i], t_hi[i]) == (float(lo), float(hi)), (method, delta, i)
