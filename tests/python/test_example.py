"""examples/python/table3.py runs from the source tree and draws its figure (when matplotlib is
installed), with the validation's RMS errors in its output."""
import os
import subprocess
import sys

from conftest import SRC


def test_table3_example_runs(tmp_path):
    plot = tmp_path / "pressure.png"
    p = subprocess.run([sys.executable, os.path.join("examples", "python", "table3.py"),
                        "--plot", str(plot)], cwd=SRC, capture_output=True, text=True,
                       timeout=600)
    assert p.returncode == 0, p.stderr
    assert "sinking_mm:" in p.stdout and "length_mm:" in p.stdout
    assert p.stdout.count("\n") > 10
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        assert "no plot" in p.stdout
    else:
        assert plot.stat().st_size > 1000
