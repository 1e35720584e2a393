#!/usr/bin/env python3
"""The net hoop tension's share H/(p b R) on a radial carcass's natural sidewall shape.

docs/ring_model.md section 3a: with no hoop force in the sidewall, r N = C along the meridian
and cos(psi) = (r^2 - r_m^2) cos(psi_e) / (r_e^2 - r_m^2) (psi the meridian's angle to the axis).
The shape through the belt edge (b/2, r_e), the widest point (W/2 - t, r_m) and the bead on the
rim (w_rim/2, r_bead) fixes the two unknowns r_m and psi_e; the share is
1 - (r_e^2 - r_m^2) tan(psi_e) / (b r_e). A check of init's stated section (widest point at
mid-height, psi_e 30-45 deg), not used by the program.

usage: scripts/natural_shape_share.py W_mm b_mm r_e_mm rim_width_mm r_bead_mm [sidewall_mm]
e.g.   scripts/natural_shape_share.py 205 158 301.5 152.4 208   (205/60R15 on a 6.0J rim)
"""
import math
import sys


def offsets(rm, psi, re, rb, n=2000):
    a = math.cos(psi) / (re * re - rm * rm)

    def integral(lo, hi):
        h, s = (hi - lo) / n, 0.0
        for i in range(n):
            r = lo + (i + 0.5) * h
            c = a * (r * r - rm * rm)
            if abs(c) >= 1:
                return float("nan")
            s += abs(c) / math.sqrt(1 - c * c) * h
        return s

    return integral(rm, re), integral(rb, rm)


def solve(W, b, re, rim_w, rb, t=6.0):
    ym = W / 2 - t
    up, low = ym - b / 2, ym - rim_w / 2
    best = None
    for i in range(1, 200):
        rm = rb + (re - rb) * i / 200
        f = lambda p: offsets(rm, p, re, rb)[0] - up
        ps = [0.01 + 1.54 * k / 60 for k in range(61)]
        vals = [f(p) for p in ps]
        for k in range(60):
            fa, fb = vals[k], vals[k + 1]
            if fa == fa and fb == fb and fa * fb <= 0:
                pa, pb = ps[k], ps[k + 1]
                for _ in range(40):
                    pm = (pa + pb) / 2
                    if f(pa) * f(pm) <= 0:
                        pb = pm
                    else:
                        pa = pm
                psi = (pa + pb) / 2
                lo = offsets(rm, psi, re, rb)[1]
                if lo == lo and (best is None or abs(lo - low) < abs(best[0])):
                    best = (lo - low, rm, psi)
    if best is None:
        sys.exit("no natural shape through these points")
    err, rm, psi = best
    share = 1 - (re * re - rm * rm) * math.tan(psi) / (b * re)
    print(f"r_m {rm:.1f} mm ({(rm - rb) / (re - rb):.2f} of the bead-to-belt height), "
          f"psi_e {math.degrees(psi):.1f} deg, share {share:.3f} (bead offset residual {err:.2f} mm)")


if __name__ == "__main__":
    if len(sys.argv) not in (6, 7):
        sys.exit(__doc__)
    solve(*[float(x) for x in sys.argv[1:]])
