"""Shared helpers of the Python module's tests: the source tree, the built CLI (from ctest's
environment: MODALTYRE_SOURCE_DIR, MODALTYRE_CLI) and the comparison of documents."""
import json
import math
import os
import subprocess

import pytest

SRC = os.environ.get("MODALTYRE_SOURCE_DIR",
                     os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
CLI = os.environ.get("MODALTYRE_CLI", os.path.join(SRC, "build", "modaltyre"))


def src(*parts):
    return os.path.join(SRC, *parts)


def run_cli(*args, expect=0):
    """Runs `modaltyre ARGS`; returns (stdout, stderr) after checking the exit code."""
    p = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=600)
    assert p.returncode == expect, p.stderr
    return p.stdout, p.stderr


def cli_json(*args):
    return json.loads(run_cli(*args, "--json")[0])


def assert_same(a, b, rel=1e-12, path="doc"):
    """Every key, list element, string and bool equal; numbers to `rel` relative."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), f"{path}: keys {set(a) ^ set(b)}"
        for k in a:
            assert_same(a[k], b[k], rel, f"{path}.{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), f"{path}: lengths differ"
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, rel, f"{path}[{i}]")
    elif isinstance(a, bool) or a is None or isinstance(a, str):
        assert a == b, f"{path}: {a!r} != {b!r}"
    else:
        assert not isinstance(b, bool), f"{path}: {a!r} != {b!r}"
        assert math.isclose(a, b, rel_tol=rel, abs_tol=0.0) or a == b, f"{path}: {a} != {b}"


@pytest.fixture(scope="session")
def modaltyre():
    import modaltyre as m
    return m
