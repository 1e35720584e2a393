#!/usr/bin/python3
"""Side by side: the same footprint contact problem solved by SciPy's nnls and by ModalTyre.

For m = 250, 1000, 4000 candidate units (or the sizes given after BUILD_DIR),
`contact_problem_export` (built with the project) writes the compliance C, the initial gaps s,
ModalTyre's load-controlled solutions (forces f and sinking delta) and their median solve times:
on the exported dense matrix, and the footprint's own matrix-free solve (Toeplitz operator of the
contact block, FFT products; its forces are compared with SciPy's too). At that sinking the contact problem is the
non-negative quadratic programme  min 1/2 f^T C f - (delta - s)^T f,  f >= 0,  which with the
Cholesky factor C = L L^T is the NNLS problem  min |L^T f - L^{-1}(delta - s)|,  f >= 0.
SciPy solves it (timed: nnls only, median of several runs, in this same run of the script) and
the two force vectors are compared. One JSON line per size, with the instruction set ModalTyre's
kernels ran (MODALTYRE_ISA=portable times the portable ones; solvers/instruction_set.h).

Usage: /usr/bin/python3 bench/compare_nnls.py [BUILD_DIR [M ...]]   (default build 250 1000 4000)
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.linalg import cholesky, solve_triangular
from scipy.optimize import nnls


def load(path):
    with open(path, "rb") as fh:
        m = int(np.frombuffer(fh.read(8), dtype="<i8")[0])
        C = np.frombuffer(fh.read(8 * m * m), dtype="<f8").reshape((m, m), order="F")
        s = np.frombuffer(fh.read(8 * m), dtype="<f8")
        f = np.frombuffer(fh.read(8 * m), dtype="<f8")
        delta, t = np.frombuffer(fh.read(16), dtype="<f8")
        f_mf = np.frombuffer(fh.read(8 * m), dtype="<f8")
        delta_mf, t_mf = np.frombuffer(fh.read(16), dtype="<f8")
    return m, C, s, f, float(delta), float(t), f_mf, float(delta_mf), float(t_mf)


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    exe = os.path.join(build, "bench", "contact_problem_export")
    sizes = [int(a) for a in sys.argv[2:]] or [250, 1000, 4000]
    for m_target in sizes:
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "problem.bin")
            run = subprocess.run([exe, str(m_target), path, "5"], check=True,
                                 capture_output=True, text=True)
            m, C, s, f_ours, delta, t_ours, f_mf, delta_mf, t_mf = load(path)
        L = cholesky(0.5 * (C + C.T), lower=True)
        A = L.T.copy()
        y = solve_triangular(L, delta - s, lower=True)
        repeats = 5 if m <= 1000 else 3
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            f_scipy, _ = nnls(A, y, maxiter=50 * m)
            times.append(time.perf_counter() - t0)
        t_scipy = float(np.median(times))
        diff = float(np.max(np.abs(f_scipy - f_ours)) / np.max(np.abs(f_ours)))
        diff_mf = float(np.max(np.abs(f_scipy - f_mf)) / np.max(np.abs(f_mf)))
        isa = [line.split(": ", 1)[1] for line in run.stdout.splitlines()
               if line.startswith("instruction_set: ")]
        print(json.dumps({"m": m, "instruction_set": isa[0] if isa else "", "scipy_s": t_scipy, "modaltyre_s": t_ours,
                          "ratio": t_scipy / t_ours, "max_rel_diff": diff,
                          "footprint_s": t_mf, "footprint_ratio": t_scipy / t_mf,
                          "footprint_max_rel_diff": diff_mf}), flush=True)


if __name__ == "__main__":
    main()
