#!/usr/bin/python3
"""Reference numbers for the Wong-Reece rigid wheel (tests/ground/wong_reece_test.cc).

Runs the independent open-source rigid-wheel code pyTerramechanics (J. Madsen, 2013, BSD,
github.com/jcmadsen/pyTerramechanics, WongReece.py at commit 11ef69d) on LETE sand and prints
the CSV this folder keeps (reference.csv). The code is not copied: its path is an argument, and
its module is imported as it is published. Only Debian's python3-numpy and python3-scipy are
needed: WongReece.py imports pylab and matplotlib for its plots, which this script replaces with
numpy and an empty stand-in before the import (no plot is drawn with gen_plots=False).

    /usr/bin/python3 make_reference.py /path/to/pyTerramechanics/WongReece.py > reference.csv

Case: LETE sand (Wong, Theory of Ground Vehicles, 4th ed., 2008, Table 2.3: n 0.79, k_c 102
kN/m^(n+1), k_phi 5301 kN/m^(n+2), c 1.3 kPa, phi 31.1 deg; K 12 mm), rigid wheel R 294.8 mm,
width 140 mm, Wong and Reece's c1 0.43, c2 0.32, rear angle theta2 = 0. WongReece.py takes
Reece's form sigma = (k1 + k2 b)(r/b)^n (cos th - cos th1)^n with b the wheel width; Bekker's
(k_c/b_B + k_phi) r^n (cos th - cos th1)^n is that form with k2 = 0, k1 = (k_c/b_B + k_phi) b^n.
Bekker's b_B is the smaller side of the contact, b_B = min(width, R sin th1) (theta2 = 0), solved
here as a fixed point around WongReece's own equilibrium (brentq on R sin th1(b_B) - b_B).
"""
import math
import sys
import types

import numpy
import scipy.optimize

sys.modules["pylab"] = numpy  # WongReece.py uses pylab only for numpy's functions
plt = types.ModuleType("matplotlib.pyplot")
mpl = types.ModuleType("matplotlib")
mpl.pyplot = plt
sys.modules["matplotlib"] = mpl
sys.modules["matplotlib.pyplot"] = plt

R, WIDTH = 0.2948, 0.14
N, KC, KPHI = 0.79, 102.0, 5301.0  # kN/m^(n+1), kN/m^(n+2)
COH, PHI, K = 1.3e3, math.radians(31.1), 0.012
C1, C2 = 0.43, 0.32


def solve(wr_module, load, slip, b_bekker):
    k1 = (KC / b_bekker + KPHI) * 1e3 * WIDTH ** N
    wheel = wr_module.WongReece(COH, PHI, k1, 0.0, N, K, R, WIDTH, load, slip, C1, C2, False, "SI")
    th1 = float(numpy.ravel(wheel.eval_W_integral_driven(slip))[0])
    dp = float(numpy.ravel(wheel.eval_F_integral_driven(th1, slip))[0])
    torque = float(numpy.ravel(wheel.eval_T_integral_driven(th1, slip))[0])
    return th1, dp, torque


def main():
    sys.path.insert(0, __import__("os").path.dirname(sys.argv[1]))
    wr_module = __import__("WongReece")
    print("# pyTerramechanics WongReece.py (11ef69d), made by make_reference.py in this folder")
    print("load_N,slip,bekker_b_mm,sinkage_mm,entry_angle_deg,drawbar_pull_N,torque_Nm")
    for load in (2000.0, 3000.0, 4000.0, 5000.0):
        for slip in (0.05, 0.1, 0.2, 0.3, 0.4):
            th1, _, _ = solve(wr_module, load, slip, WIDTH)
            b = WIDTH
            if R * math.sin(th1) < WIDTH:
                b = scipy.optimize.brentq(
                    lambda bb: R * math.sin(solve(wr_module, load, slip, bb)[0]) - bb,
                    1e-3, WIDTH, xtol=1e-12, rtol=1e-12)
            th1, dp, torque = solve(wr_module, load, slip, b)
            print("%.0f,%.2f,%.6f,%.6f,%.6f,%.6f,%.6f" % (
                load, slip, b * 1e3, R * (1 - math.cos(th1)) * 1e3, math.degrees(th1), dp,
                torque))


if __name__ == "__main__":
    main()
