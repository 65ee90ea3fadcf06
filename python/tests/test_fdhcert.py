"""The Python module against the fdhcert program on the same inputs (ctest python_module)."""
import csv
import json
import os
import shutil
import subprocess
import tempfile
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import fdhcert

FDHCERT = os.environ["FDHCERT_BIN"]
SOURCE = Path(os.environ["FDH_SOURCE_DIR"])
DATA = SOURCE / "tests" / "data"
SAMPLE = os.environ.get("FDH_CCD_SAMPLE", "")  # the build's benchmark sample, empty for none


@pytest.fixture
def scratch():
    """A folder of this test's own (mkdtemp, named fdh_pytest.*), removed when it ends, passed or
    failed; kept, and its path printed, with FDH_KEEP_TEST_FILES=1 (as the C++ tests do)."""
    folder = Path(tempfile.mkdtemp(prefix="fdh_pytest."))
    try:
        yield folder
    finally:
        if os.environ.get("FDH_KEEP_TEST_FILES") == "1":
            print(f"FDH_KEEP_TEST_FILES: kept {folder}")
        else:
            shutil.rmtree(folder, ignore_errors=True)


def program(*args):
    return subprocess.run([FDHCERT, *map(str, args)], capture_output=True, text=True)


def without_times(tallies):
    """A classify dict with the timings (which differ from run to run) taken out."""
    out = json.loads(json.dumps(tallies))
    for block in [out] + out.get("files", []):
        for m in block["methods"].values():
            m.pop("ns_per_query", None)
    return out


def read_vf(path):
    """The queries of a native file as (kinds, N×8×3 points, truths)."""
    kinds, points, truths = [], [], []
    for line in Path(path).read_text().splitlines():
        f = line.split()
        if not f or f[0].startswith("#"):
            continue
        kinds.append("vertex-face" if f[0] == "vf" else "edge-edge")
        points.append([float.fromhex(x) if "0x" in x else float(x) for x in f[2:26]])
        truths.append(int(f[26]) if len(f) > 26 else -1)
    return kinds, np.array(points).reshape(-1, 8, 3), truths


def per_query(path, folder):
    """The program's per-query verdicts: {method: [0/1/None per query]}, through FOLDER."""
    out = folder / "per_query.csv"
    assert program("classify", path, "--per-query", out).returncode == 0
    with out.open() as f:
        rows = list(csv.DictReader(f))
    return {m: [None if r[m] == "n/a" else int(r[m]) for r in rows] for m in fdhcert.methods()}


def test_the_registry_lists_the_twin_first_and_robust():
    assert fdhcert.methods()[0] == "exact"
    assert "robust" in fdhcert.methods()


@pytest.mark.parametrize("name", ["static.vf", "moving.vf"])
def test_classify_of_files_gives_the_programs_tallies(name):
    cli = json.loads(program("classify", DATA / name, "--json").stdout)
    assert without_times(fdhcert.classify([str(DATA / name)])) == without_times(cli)


def test_classify_time_gives_the_programs_cpu_time_fields():
    """`classify(time=True)` is `classify --time --json`: per method median <= p90 <= max."""
    mine = fdhcert.classify([str(DATA / "moving.vf")], methods=["exact", "robust", "paper-literal"],
                            time=True, rounds=2)
    cli = json.loads(program("classify", DATA / "moving.vf", "--methods",
                             "exact,robust,paper-literal", "--time", "--rounds", "2",
                             "--json").stdout)
    assert mine["cpu_time"]["rounds"] == cli["cpu_time"]["rounds"] == 2
    for name, t in mine["cpu_time"]["methods"].items():
        assert t.keys() == cli["cpu_time"]["methods"][name].keys()
        assert t["queries"] == cli["cpu_time"]["methods"][name]["queries"]
    robust = mine["cpu_time"]["methods"]["robust"]
    assert 0 < robust["median_ns"] <= robust["p90_ns"] <= robust["max_ns"]
    assert mine["cpu_time"]["methods"]["paper-literal"]["max_ns"] is None
    assert "cpu_time" not in fdhcert.classify([str(DATA / "moving.vf")])


def test_classify_at_a_minimum_distance_is_the_programs():
    """`classify(min_distance=D)` is `classify --min-distance D --json`; 0 is the call without it;
    a negative, NaN or infinite D is a ValueError."""
    path = DATA / "moving.vf"
    mine = fdhcert.classify([path], methods=["exact", "robust"], min_distance=0.125)
    cli = json.loads(program("classify", path, "--methods", "exact,robust", "--min-distance",
                             "0.125", "--json").stdout)
    assert mine["min_distance"] == 0.125
    assert without_times(mine) == without_times(cli)
    assert without_times(fdhcert.classify([path], min_distance=0)) == \
        without_times(fdhcert.classify([path]))
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="min distance"):
            fdhcert.classify([path], min_distance=bad)


def test_classify_takes_the_modules_one_vocabulary_for_the_kind():
    """kind is 'vertex-face' or 'edge-edge' across the module ('vf' was classify's alone)."""
    path = DATA / "moving.vf"
    assert without_times(fdhcert.classify([path], kind="edge-edge")) == \
        without_times(fdhcert.classify([path]))  # a native file says its own kinds
    with pytest.raises(ValueError, match="vertex-face"):
        fdhcert.classify([path], kind="vf")


def test_classify_of_arrays_gives_the_programs_tallies(scratch):
    kinds, points, truths = read_vf(DATA / "static.vf")
    keep = [i for i, t in enumerate(truths) if t >= 0]
    mine = fdhcert.classify_arrays(points[keep], truth=np.array(truths)[keep])
    text = "".join(l for l in (DATA / "static.vf").read_text().splitlines(True)
                   if l.startswith("#") or len(l.split()) > 26 or not l.split())
    path = scratch / "labelled.vf"
    path.write_text(text)
    cli = json.loads(program("classify", path, "--json").stdout)
    for name, tally in cli["methods"].items():
        for count in ("tp", "tn", "fp", "fn", "na"):
            assert mine["methods"][name][count] == tally[count], (name, count)


@pytest.mark.parametrize("name", ["static.vf", "moving.vf"])
def test_batched_verdicts_match_the_programs_per_query_verdicts(name, scratch):
    kinds, points, _ = read_vf(DATA / name)
    expected = per_query(DATA / name, scratch)
    for method in ("exact", "robust", "float-cubic"):
        for i, kind in enumerate(kinds):
            one = points[i:i + 1]
            if kind == "edge-edge":
                got = fdhcert.edge_edge_ccd(one, method)
            elif name == "static.vf":
                got = fdhcert.point_triangle(one, method)
            else:
                got = fdhcert.vertex_face_ccd(one, method)
            assert int(got[0]) == expected[method][i], (method, i)


@pytest.mark.skipif(not SAMPLE or not Path(SAMPLE).is_dir(), reason="no CCD benchmark sample (FDH_CCD_SAMPLE)")
def test_robust_equals_exact_on_the_ccd_sample_in_batches():
    for path in sorted(Path(SAMPLE).glob("*/*/*.csv"))[::4]:
        # 8 rows per query: x_num,x_den,y_num,y_den,z_num,z_den,truth (exact doubles)
        rows = [line.split(",") for line in path.read_text().split()]
        coords = [[float(Fraction(int(r[i]), int(r[i + 1]))) for i in (0, 2, 4)] for r in rows]
        queries = np.array(coords).reshape(-1, 8, 3)
        test = fdhcert.edge_edge_ccd if "edge-edge" in str(path) else fdhcert.vertex_face_ccd
        assert (test(queries, "robust") == test(queries, "exact")).all(), path


def toi_per_query(path, methods):
    """`classify --toi --per-query --json`: the JSON and the per-query rows."""
    with tempfile.TemporaryDirectory(prefix="fdh_pytest_toi.") as folder:
        out = Path(folder) / "per-query.csv"
        r = program("classify", path, "--toi", "--json", "--methods", methods, "--per-query", out)
        assert r.returncode == 0, r.stderr
        rows = list(csv.DictReader(out.open()))
    return json.loads(r.stdout), rows


def sample_queries(path):
    """A CCD benchmark CSV as an N×8×3 array (8 rows per query, exact rationals)."""
    rows = [line.split(",") for line in path.read_text().split()]
    coords = [[float(Fraction(int(r[i]), int(r[i + 1]))) for i in (0, 2, 4)] for r in rows]
    return np.array(coords).reshape(-1, 8, 3)


def toi_files():
    files = [DATA / "moving.vf", DATA / "moving_times.vf"]
    if SAMPLE and Path(SAMPLE).is_dir():
        files += sorted(Path(SAMPLE).glob("*/*/*.csv"))[::6]
    return files


@pytest.mark.parametrize("path", toi_files(), ids=lambda p: p.name)
def test_times_of_impact_agree_with_the_program(path):
    methods = ["exact", "robust", "float-cubic"]
    cli, rows = toi_per_query(path, ",".join(methods))
    assert set(cli["toi"]["methods"]) == set(methods)
    if path.suffix == ".csv":
        points = sample_queries(path)
        kinds = ["edge-edge" if "edge-edge" in str(path) else "vertex-face"] * len(points)
    else:
        kinds, points, _ = read_vf(path)
    assert len(rows) == len(points)
    for method in methods:
        for kind in set(kinds):
            keep = [i for i, k in enumerate(kinds) if k == kind]
            toi = fdhcert.edge_edge_toi if kind == "edge-edge" else fdhcert.vertex_face_toi
            hit, t_lo, t_hi = toi(points[keep], method, 2**-30)
            for j, i in enumerate(keep):
                lo, hi = rows[i][f"{method} t_lo"], rows[i][f"{method} t_hi"]
                assert bool(hit[j]) == (lo != ""), (method, i)
                if hit[j]:
                    assert (t_lo[j], t_hi[j]) == (float(lo), float(hi)), (method, i)
                else:
                    assert (t_lo[j], t_hi[j]) == (1.0, 1.0)
    # robust's enclosures are exact, as the program's checker says.
    assert cli["toi"]["methods"]["robust"]["late"] == 0
    assert cli["toi"]["methods"]["robust"]["broken"] == 0


def test_a_time_of_impact_is_enclosed_and_at_most_the_width_wide():
    # The triangle rises through the still point: contact at t = 1/2 exactly.
    tri = [[0, 0, -1], [1, 0, -1], [0, 1, -1]]
    q = np.array([[[0.25, 0.25, 0], *tri, [0.25, 0.25, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1]]],
                 dtype=float)
    hit, t_lo, t_hi = fdhcert.vertex_face_toi(q, width=2**-40)
    assert hit[0] and t_lo[0] <= 0.5 <= t_hi[0] and t_hi[0] - t_lo[0] <= 2**-40
    with pytest.raises(ValueError):
        fdhcert.vertex_face_toi(q, "paper-literal")
    with pytest.raises(ValueError):
        fdhcert.vertex_face_toi(q, width=0)


def test_the_exact_contact_time_is_a_fraction():
    _, points, _ = read_vf(DATA / "moving.vf")
    rising = fdhcert.contact_time(points[0], "vertex-face")
    assert rising == {"hit": True, "time": Fraction(1, 2), "interval": (Fraction(1, 2),) * 2}
    assert fdhcert.contact_time(points[2], "edge-edge")["hit"] is False


@pytest.mark.parametrize("k", [6, 14, 18, 26])
def test_a_kdop_contains_its_points_exactly(k):
    pts = np.random.default_rng(k).normal(size=(50, 3)) * 1e3
    lo, hi, dirs = fdhcert.kdop(pts, k)
    assert lo.shape == hi.shape == (k // 2,) and dirs.shape == (k // 2, 3)
    for p in pts:
        for s, d in enumerate(dirs):
            dot = sum(Fraction(int(c)) * Fraction(x) for c, x in zip(d, p))
            assert Fraction(lo[s]) <= dot <= Fraction(hi[s])


def test_a_scene_runs_into_arrays():
    run = fdhcert.simulate(str(SOURCE / "corpus/scenes/table.scene"), frames=20, grid=10,
                           every=5)
    assert run["frames"] == [5, 10, 15, 20]
    assert run["positions"].shape == (4, 100, 3)
    assert run["triangles"].shape == (2 * 9 * 9, 3)
    assert (run["positions"][-1] == run["final"]).all()
    assert run["summary"]["frames"] == 20 and run["summary"]["particles"] == 100
    # Not checked: no audit counts.
    assert run["summary"]["crossing"] is None and run["summary"]["self_crossing"] is None


def test_a_checked_scene_has_the_frame_audit():
    # The exact frame audit of simulate --json (the audit engine): the obstacles, and with the
    # self-collision pass the cloth against itself.
    run = fdhcert.simulate(str(SOURCE / "corpus/scenes/windy-bar.scene"), frames=30, grid=8,
                           check=True)
    assert run["summary"]["crossing"] == 0 and run["summary"]["self_crossing"] == 0
    run = fdhcert.simulate(str(SOURCE / "corpus/scenes/table.scene"), frames=10, grid=8,
                           check=True)
    assert run["summary"]["crossing"] == 0 and run["summary"]["self_crossing"] is None


def test_bad_input_raises_the_programs_message(scratch):
    bad = scratch / "bad.vf"
    bad.write_text("vf 1\n0 0 0\n")
    cli = program("classify", bad)
    assert cli.returncode == 2
    with pytest.raises(fdhcert.InputError) as e:
        fdhcert.classify([str(bad)])
    assert cli.stderr.strip().endswith(str(e.value))
    assert str(e.value).startswith(f"{bad}:1: ")


def test_bad_arrays_raise_value_errors():
    with pytest.raises(ValueError, match="N×8×3"):
        fdhcert.vertex_face_ccd(np.zeros((2, 7, 3)))
    with pytest.raises(ValueError, match="not finite"):
        fdhcert.point_triangle(np.full((1, 8, 3), np.nan))
    with pytest.raises(ValueError, match="triangle moves"):
        fdhcert.point_triangle(np.arange(24.0).reshape(1, 8, 3))
    with pytest.raises(ValueError, match="k must be"):
        fdhcert.kdop(np.zeros((3, 3)), 10)
    with pytest.raises(ValueError, match="paper-intended does not decide"):
        fdhcert.edge_edge_ccd(np.zeros((1, 8, 3)), "paper-intended")
