"""The catalogue's row for the Python module (issue 22, docs/python.md "What the module refuses"),
run by ctest python_module: it refuses what it would change (integers beyond 2^53, complex
numbers, truths other than 0 and 1, negative frames), takes os.PathLike, reads numbers whatever
the locale, and stops a long call on Ctrl-C within a second."""
import os
import signal
import subprocess
import sys
import tempfile
import time
import shutil
from pathlib import Path

import numpy as np
import pytest

import fdhcert

SOURCE = Path(os.environ["FDH_SOURCE_DIR"])
DATA = SOURCE / "tests" / "data"
SCENE = SOURCE / "corpus" / "scenes" / "table.scene"
LINE = "vf q 0.25 0.25 1  0 0 0  1 0 0  0 1 0  0.25 0.25 -1  0 0 0  1 0 0  0 1 0  1\n"


@pytest.fixture
def scratch():
    """A folder of this test's own, removed when it ends (as test_fdhcert.py's)."""
    folder = Path(tempfile.mkdtemp(prefix="fdh_pytest."))
    try:
        yield folder
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def static_query(dtype, big=0):
    """A point above a still triangle, moving through it; `big` added to one coordinate."""
    points = [[1 + big, 1, 8], [0, 0, 4], [8, 0, 4], [0, 8, 4],
              [1, 1, 0], [0, 0, 4], [8, 0, 4], [0, 8, 4]]  # Python's integers: exact
    return np.array(points, dtype=dtype).reshape(1, 8, 3)


def test_integers_up_to_2_53_are_taken_exactly():
    assert fdhcert.vertex_face_ccd(static_query(np.int64), "exact")[0]
    assert fdhcert.vertex_face_ccd(static_query(np.int64, 2**53 - 1), "exact").shape == (1,)
    assert fdhcert.kdop(np.array([[2**53, 0, -2**53]], dtype=np.int64), 6)[0][0] == 2.0**53


@pytest.mark.parametrize("dtype", [np.int64, np.uint64])
def test_integers_beyond_2_53_are_refused(dtype):
    q = static_query(dtype, 2**53)  # x = 2^53 + 1
    for call in (lambda: fdhcert.point_triangle(q, "exact"),
                 lambda: fdhcert.vertex_face_ccd(q),
                 lambda: fdhcert.vertex_face_toi(q),
                 lambda: fdhcert.classify_arrays(q),
                 lambda: fdhcert.contact_time(q[0]),
                 lambda: fdhcert.kdop(q[0])):
        with pytest.raises(ValueError, match=r"9007199254740993 is beyond 2\^53"):
            call()
    with pytest.raises(ValueError, match=r"beyond 2\^53"):
        fdhcert.kdop(np.array([[-2**63, 0, 0]], dtype=np.int64))


def test_complex_and_object_arrays_are_refused():
    with pytest.raises(ValueError, match="complex numbers"):
        fdhcert.vertex_face_ccd(static_query(np.complex128) + 1j)
    with pytest.raises(ValueError, match="complex numbers"):
        fdhcert.kdop(np.zeros((2, 3), dtype=np.complex64))
    with pytest.raises(ValueError, match="not an array of real numbers"):
        fdhcert.kdop(np.array([[2**70, 0, 0]], dtype=object))


@pytest.mark.parametrize("truth", [0.7, 2**32 + 1, 2, -1, 0.5 + 0.5j])
def test_a_truth_that_is_not_0_or_1_is_refused(truth):
    q = static_query(np.float64)
    with pytest.raises(ValueError, match="truth"):
        fdhcert.classify_arrays(q, truth=np.array([truth]))


@pytest.mark.parametrize("truth", [[1], [1.0], [True], np.array([1], dtype=np.uint8)])
def test_a_truth_of_0_or_1_in_any_type_is_taken(truth):
    c = fdhcert.classify_arrays(static_query(np.float64), truth=truth, methods=["exact"])
    assert c["methods"]["exact"]["tp"] == 1


def test_negative_frames_are_refused_as_the_program_does():
    with pytest.raises(ValueError, match="frames must be 0 or more"):
        fdhcert.simulate(str(SCENE), frames=-5, grid=5)
    with pytest.raises(ValueError, match="frames must be 0 or more"):
        fdhcert.simulate(str(SCENE), frames=-1, grid=5)


def test_paths_may_be_path_like(scratch):
    assert fdhcert.simulate(SCENE, frames=2, grid=5)["summary"]["frames"] == 2
    as_text = fdhcert.classify([str(DATA / "static.vf")], methods=["exact"])
    as_path = fdhcert.classify([DATA / "static.vf"], methods=["exact"])
    as_bytes = fdhcert.classify([os.fsencode(DATA / "static.vf")], methods=["exact"])
    for c in (as_path, as_bytes):
        assert c["methods"]["exact"]["tp"] == as_text["methods"]["exact"]["tp"]
    with pytest.raises(TypeError):
        fdhcert.classify([42])


def decimal_comma_locale(scratch):
    """A decimal-comma locale: an installed one, else de_DE.UTF-8 made with localedef into
    `scratch` (LOCPATH); None when neither can be had."""
    for name in subprocess.run(["locale", "-a"], capture_output=True, text=True).stdout.split():
        if name.lower().startswith(("de_de.utf", "fr_fr.utf")):
            return name, {}
    if not shutil.which("localedef") or not Path("/usr/share/i18n/locales/de_DE").exists():
        return None
    made = subprocess.run(["localedef", "-i", "de_DE", "-f", "UTF-8",
                           str(scratch / "de_DE.UTF-8")], capture_output=True)
    if not (scratch / "de_DE.UTF-8").is_dir():
        return None
    del made
    return "de_DE.UTF-8", {"LOCPATH": str(scratch)}


LOCALE_PROBE = """
import json, locale, sys
import fdhcert
locale.setlocale(locale.LC_ALL, sys.argv[1])
assert locale.localeconv()["decimal_point"] == ",", locale.localeconv()
dot = fdhcert.classify([sys.argv[2]], methods=["exact"])
try:
    fdhcert.classify([sys.argv[3]], methods=["exact"])
    comma = "taken"
except fdhcert.InputError as e:
    comma = str(e)
print(json.dumps({"tp": dot["methods"]["exact"]["tp"], "comma": comma}))
"""


def test_the_readers_ignore_a_decimal_comma_locale(scratch):
    found = decimal_comma_locale(scratch)
    if found is None:
        pytest.skip("no decimal-comma locale installed or makeable (locale -a, localedef)")
    name, env = found
    dot, comma = scratch / "dot.vf", scratch / "comma.vf"
    dot.write_text(LINE)
    comma.write_text(LINE.replace("0.25", "0,25"))
    run = subprocess.run([sys.executable, "-c", LOCALE_PROBE, name, str(dot), str(comma)],
                         capture_output=True, text=True, env={**os.environ, **env})
    assert run.returncode == 0, run.stderr
    said = __import__("json").loads(run.stdout)
    assert said["tp"] == 1
    assert "'0,25' is not a number" in said["comma"]


INTERRUPTED = """
import sys, time
import fdhcert
print("started", flush=True)
try:
    fdhcert.simulate(sys.argv[1], frames=10**7, grid=30)
    print("finished", flush=True)
except KeyboardInterrupt:
    print("interrupted", flush=True)
"""


def test_ctrl_c_stops_a_long_simulate_within_a_second():
    child = subprocess.Popen([sys.executable, "-c", INTERRUPTED, str(SCENE)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline() == "started\n"
        time.sleep(1)
        assert child.poll() is None  # still running
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=10)
        took = time.monotonic() - sent
    finally:
        child.kill()
        child.wait()
    assert out == "interrupted\n", err
    print(f"KeyboardInterrupt {took:.3f} s after SIGINT")
    assert took < 1.0


# Issue 34: a square cloth pierced by an obstacle triangle in every frame (a violation), as
# arrays; each refusal below is run in a child first where it crashed the interpreter before.
SQUARE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
SQUARE_FACES = np.array([[0, 1, 2], [0, 2, 3]])
PIERCING = np.array([[0.5, 0.2, -1], [0.5, 0.2, 1], [0.6, 0.9, 0]], dtype=np.float64)
PIERCING_FACES = np.array([[0, 1, 2]])

KEEP_PROBE = """
import sys
import numpy as np
import fdhcert
frames = np.array([[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]] * 2, dtype=np.float64)
obstacle = np.array([[0.5, 0.2, -1], [0.5, 0.2, 1], [0.6, 0.9, 0]], dtype=np.float64)
try:
    fdhcert.audit(frames, np.array([[0, 1, 2], [0, 2, 3]]), obstacle, np.array([[0, 1, 2]]),
                  keep=int(sys.argv[1]))
    print("taken")
except ValueError as e:
    print("ValueError:", e)
"""


@pytest.mark.parametrize("keep", [0, -1])
def test_audit_keep_below_1_is_refused_not_a_crash(keep):
    run = subprocess.run([sys.executable, "-c", KEEP_PROBE, str(keep)], capture_output=True,
                         text=True)
    assert run.returncode == 0, f"status {run.returncode}: {run.stderr}"
    assert run.stdout.startswith("ValueError: keep must be 1 or more"), run.stdout


MEMORY_PROBE = """
import numpy as np
import fdhcert
# 2^40 points of float32 in 12 bytes (a broadcast view): their float64 copy cannot be made.
huge = np.broadcast_to(np.zeros(3, dtype=np.float32), (2**40, 3))
try:
    fdhcert.kdop(huge, 6)
    print("taken")
except MemoryError:
    print("MemoryError")
"""


def test_an_array_too_large_to_convert_raises_memory_error():
    run = subprocess.run([sys.executable, "-c", MEMORY_PROBE], capture_output=True, text=True)
    assert run.returncode == 0, f"status {run.returncode}: {run.stderr}"
    assert run.stdout == "MemoryError\n"


def test_audit_without_faces_is_refused_as_the_program_does():
    frames = np.stack([SQUARE, SQUARE])
    with pytest.raises(ValueError, match=r"faces: no faces"):
        fdhcert.audit(frames, np.zeros((0, 3), dtype=np.int64), PIERCING, PIERCING_FACES)
    with pytest.raises(ValueError, match=r"obstacle_faces: no faces"):
        fdhcert.audit(frames, SQUARE_FACES, PIERCING, np.zeros((0, 3), dtype=np.int64))


def test_audit_names_the_frame_of_a_nan():
    frames = np.stack([SQUARE, SQUARE, SQUARE])
    frames[2, 1, 0] = np.nan
    with pytest.raises(ValueError, match=r"^frame 2: "):
        fdhcert.audit(frames, SQUARE_FACES)


def test_audit_names_a_uint64_index_as_it_is():
    faces = np.array([[0, 1, 2**64 - 1]], dtype=np.uint64)
    with pytest.raises(ValueError, match=r"vertex index 18446744073709551615 is not in \[0, 4\)"):
        fdhcert.audit(np.stack([SQUARE]), faces)
