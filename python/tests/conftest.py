"""Fixtures every test module of python/tests shares (ctest python_module)."""
import tempfile
from pathlib import Path

import pytest


@pytest.fixture
def tmp_path():
    """A folder of this test's own, removed when it ends (pytest's own tmp_path keeps the last
    runs' folders in the temporary folder, which ./run test counts as litter)."""
    with tempfile.TemporaryDirectory(prefix="fdh_pytest_") as d:
        yield Path(d)
