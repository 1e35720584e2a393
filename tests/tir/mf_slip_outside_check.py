#!/usr/bin/python3
"""An outside check of `modaltyre tir export`'s longitudinal laws (issue 46 item 5, "done when").

It shares no code with ModalTyre's tir/ module: the exported .tir is read with the outside
vertical check's small parser (mf_outside_check.py), the Magic Formula 6.2 laws are evaluated
here from their published form, and the model's own slip curve is measured through the model's
FMU (`modaltyre fmu`), driven by the example ctypes host (examples/fmu/fmi2_host.py, which knows
nothing of ModalTyre) at constant wheel speed, as a vehicle model would drive it.

  F_x0 = D sin(C atan(B k - E (B k - atan(B k)))) + S_Vx,  k = kappa + S_Hx
         (Pacejka 2012, Tire and Vehicle Dynamics, 3rd ed., 4.E9-4.E18; zero camber)
  M_y  = -R0 F_z0 LMY (QSY1 + QSY2 F_x/F_z0 + QSY3 |V/V0| + QSY4 (V/V0)^4) (F_z/F_z0)^QSY7
         (MF-Tyre 6.1/6.2)
  R_e  = R0 (Q_RE0 + Q_V1 (R0 Omega/V0)^2) - F_z0/C_z (FREFF F_z/F_z0 + DREFF atan(BREFF F_z/F_z0))
         (Pacejka 2012 A3.1, A3.6); kappa = Omega R_e / V - 1, as an MF tool computes it

The runs: at three loads between the export's fitted ones (0.6, 0.9, 1.3 x FNOMIN) the hub is
held at the height where the standing tyre carries the load (secant in initialization mode);
the speed ramps to LONGVL, the wheel then spins freely (I dOmega/dt = M_y, I = 1 kg m^2) to free
rolling, and is then held at 16 spins from braking to driving (kappa -0.3 ... 0.3 of the measured
free rolling) for 0.1 s each. At the middle load the wheel also rolls freely at 40 and 100 km/h.

Criteria (issue 46): |F_x,MF - F_x| <= 5 % of F_z at every slip and load; the rolling-resistance
moment at free rolling within 10 % at every load and speed.

Usage: /usr/bin/python3 tests/tir/mf_slip_outside_check.py FILE.tir FILE.fmu
Prints one JSON object; exit 0 when the criteria hold, 1 when one fails, 2 on bad input.
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "examples", "fmu"))
from fmi2_host import Fmu, Instance  # noqa: E402
from mf_outside_check import read_tir  # noqa: E402

LOAD_SHARES = (0.6, 0.9, 1.3)
SLIPS = (-0.3, -0.2, -0.12, -0.06, -0.03, -0.015, -0.006, -0.002,
         0.002, 0.006, 0.015, 0.03, 0.06, 0.12, 0.2, 0.3)
EXTRA_SPEEDS_KMH = (40.0, 100.0)
STEP, RAMP, FREE, HOLD, TAIL = 1e-3, 0.3, 0.6, 0.1, 0.04
INERTIA = 1.0


def fail(message):
    print(message, file=sys.stderr)
    sys.exit(2)


class Tir:
    """The keys the laws need; scaling factors 1 and other coefficients 0 when not stated."""

    def __init__(self, path):
        self.sections = read_tir(path)
        units = self.sections.get("UNITS", {})
        for k, si in (("LENGTH", "meter"), ("FORCE", "newton"), ("TIME", "second")):
            if units.get(k, si).lower() != si:
                fail(f"{path}: [UNITS] {k} is not {si}: this check reads SI files only")

    def get(self, section, key, default=None):
        text = self.sections.get(section, {}).get(key)
        if text is None:
            if default is None:
                fail(f"[{section}] {key} missing")
            return default
        return float(text.replace("D", "e").replace("d", "e"))


def fx0(t, kappa, fz):
    g = t.get
    fz0 = g("VERTICAL", "FNOMIN") * g("SCALING_COEFFICIENTS", "LFZO", 1.0)
    dfz = (fz - fz0) / fz0
    L = {k: g("SCALING_COEFFICIENTS", k, 1.0) for k in ("LCX", "LMUX", "LEX", "LKX", "LHX", "LVX")}
    c = {k: g("LONGITUDINAL_COEFFICIENTS", k, 0.0)
         for k in ("PCX1", "PDX1", "PDX2", "PEX1", "PEX2", "PEX3", "PEX4", "PKX1", "PKX2", "PKX3",
                   "PHX1", "PHX2", "PVX1", "PVX2")}
    lmu_prime = 10 * L["LMUX"] / (1 + 9 * L["LMUX"])
    shx = (c["PHX1"] + c["PHX2"] * dfz) * L["LHX"]
    svx = fz * (c["PVX1"] + c["PVX2"] * dfz) * L["LVX"] * lmu_prime
    k = kappa + shx
    cx = c["PCX1"] * L["LCX"]
    dx = (c["PDX1"] + c["PDX2"] * dfz) * L["LMUX"] * fz
    ex = (c["PEX1"] + c["PEX2"] * dfz + c["PEX3"] * dfz**2) * (1 - c["PEX4"] * math.copysign(1, k))
    ex = min(ex * L["LEX"], 1.0)
    kx = fz * (c["PKX1"] + c["PKX2"] * dfz) * math.exp(c["PKX3"] * dfz) * L["LKX"]
    bx = kx / (cx * dx + 1e-6)
    return dx * math.sin(cx * math.atan(bx * k - ex * (bx * k - math.atan(bx * k)))) + svx


def rolling_moment(t, fx, fz, v):
    g = t.get
    r0, fz0, v0 = g("DIMENSION", "UNLOADED_RADIUS"), g("VERTICAL", "FNOMIN"), g("MODEL", "LONGVL")
    q = {k: g("ROLLING_COEFFICIENTS", k, 0.0) for k in ("QSY1", "QSY2", "QSY3", "QSY4", "QSY7")}
    return (-r0 * fz0 * g("SCALING_COEFFICIENTS", "LMY", 1.0)
            * (q["QSY1"] + q["QSY2"] * fx / fz0 + q["QSY3"] * abs(v / v0) + q["QSY4"] * (v / v0)**4)
            * (fz / fz0)**q["QSY7"])


def effective_radius(t, fz, omega):
    g = t.get
    r0, fz0, v0 = g("DIMENSION", "UNLOADED_RADIUS"), g("VERTICAL", "FNOMIN"), g("MODEL", "LONGVL")
    cz = g("VERTICAL", "VERTICAL_STIFFNESS")
    r_omega = r0 * (g("VERTICAL", "Q_RE0") + g("VERTICAL", "Q_V1", 0.0) * (r0 * omega / v0)**2)
    x = fz / fz0
    return r_omega - fz0 / cz * (g("VERTICAL", "FREFF", 0.0) * x
                                 + g("VERTICAL", "DREFF", 0.0) * math.atan(g("VERTICAL", "BREFF", 0.0) * x))


class Wheel:
    """The FMU's tyre on a hub at a fixed height, at a prescribed or a freely spinning speed."""

    def __init__(self, fmu, load, r0):
        self.inst = Instance(fmu, f"slip{load:.0f}", quiet=True)
        self.inst.enter_initialization()
        z0, z1, f0 = r0 - 0.01, r0 - 0.02, None
        for _ in range(40):  # the height that carries the load standing (secant)
            if f0 is None:
                f0 = self._fz_at(z0) - load
            f1 = self._fz_at(z1) - load
            if abs(f1) < 1e-7 * load or f1 == f0:
                break
            z0, z1, f0 = z1, z1 - f1 * (z1 - z0) / (f1 - f0), f1
        self.z, self.x, self.spin, self.speed = z1, 0.0, 0.0, 0.0
        self.inst.exit_initialization()

    def _fz_at(self, z):
        self.inst.set({"wheel_state.pos.z": z})
        return self.inst.get(["wheel_load.force.z"])["wheel_load.force.z"]

    def step(self, speed, spin=None):
        """One 1 ms step; spin None: free (the tyre's moment turns the wheel)."""
        self.speed = speed
        if spin is not None:
            self.spin = spin
        self.inst.set({"wheel_state.pos.x": self.x, "wheel_state.pos.z": self.z,
                       "wheel_state.lin_vel.x": speed, "wheel_state.ang_vel.y": self.spin})
        self.inst.step(STEP)
        o = self.inst.get(["wheel_load.force.x", "wheel_load.force.z", "wheel_load.moment.y"])
        if spin is None:
            self.spin += STEP * o["wheel_load.moment.y"] / INERTIA
        self.x += STEP * speed
        return o["wheel_load.force.x"], o["wheel_load.force.z"], o["wheel_load.moment.y"]

    def hold(self, duration, speed, spin=None):
        """Means over the last TAIL s of F_x, F_z, the contact's rolling moment and the spin."""
        n, tail = round(duration / STEP), round(TAIL / STEP)
        acc = [0.0] * 4
        for i in range(n):
            fx, fz, my = self.step(speed, spin)
            if i >= n - tail:
                # The hub moment is M_r - r F_x, r = the hub's height over the road.
                for j, v in enumerate((fx, fz, my + self.z * fx, self.spin)):
                    acc[j] += v / tail
        return acc

    def ramp_to(self, speed, r0):
        start = self.speed
        n = round(RAMP / STEP)
        for i in range(n):
            s = (i + 0.5) / n
            v = start + (speed - start) * s * s * (3 - 2 * s)
            self.step(v, v / (0.975 * r0) if start == 0 else None)


def main():
    if len(sys.argv) != 3:
        print(__doc__.split("Usage: ")[1].splitlines()[0], file=sys.stderr)
        return 2
    tir_path, fmu_path = sys.argv[1:]
    t = Tir(tir_path)
    r0, fz0, v0 = t.get("DIMENSION", "UNLOADED_RADIUS"), t.get("VERTICAL", "FNOMIN"), t.get(
        "MODEL", "LONGVL")
    fmu = Fmu(fmu_path)
    out = {"tir": tir_path, "fmu": fmu_path, "longvl_m_s": v0, "loads": [], "rolling": []}
    worst_fx, worst_my = 0.0, 0.0

    def rolling_row(wheel, speed, free):
        nonlocal worst_my
        fx, fz, mr, spin = free
        mf = rolling_moment(t, fx, fz, speed)
        rel = (mf - mr) / abs(mr)
        worst_my = max(worst_my, abs(rel))
        out["rolling"].append({"speed_kmh": round(speed * 3.6, 2), "fz_N": round(fz, 1),
                               "model_my_Nm": round(mr, 4), "mf_my_Nm": round(mf, 4),
                               "rel_diff": round(rel, 5)})

    for share in LOAD_SHARES:
        load = share * fz0
        wheel = Wheel(fmu, load, r0)
        wheel.ramp_to(v0, r0)
        free = wheel.hold(FREE, v0)
        omega_free = free[3]
        rolling_row(wheel, v0, free)
        rows = []
        for kappa in SLIPS:
            fx, fz, _, spin = wheel.hold(HOLD, v0, omega_free * (1 + kappa))
            # kappa as an MF tool computes it from the wheel's spin and the file's R_e ...
            k_mf = spin * effective_radius(t, fz, spin) / v0 - 1
            mf = fx0(t, k_mf, fz)
            worst_fx = max(worst_fx, abs(mf - fx) / fz)
            rows.append({"kappa": kappa, "kappa_mf": round(k_mf, 6), "fz_N": round(fz, 1),
                         "model_fx_N": round(fx, 2), "mf_fx_N": round(mf, 2),
                         "diff_over_fz": round((mf - fx) / fz, 5)})
        # ... and the model's own effective radius against the file's.
        re_model = v0 / omega_free
        re_mf = effective_radius(t, free[1], omega_free)
        out["loads"].append({"load_N": round(load, 1), "hub_height_mm": round(wheel.z * 1e3, 4),
                             "model_re_mm": round(re_model * 1e3, 4),
                             "mf_re_mm": round(re_mf * 1e3, 4), "rows": rows,
                             "max_abs_diff_over_fz": max(abs(r["diff_over_fz"]) for r in rows)})
        if share == LOAD_SHARES[1]:
            for kmh in EXTRA_SPEEDS_KMH:
                wheel.ramp_to(kmh / 3.6, r0)
                rolling_row(wheel, kmh / 3.6, wheel.hold(FREE, kmh / 3.6))
        wheel.inst.free()
    out["max_abs_fx_diff_over_fz"] = round(worst_fx, 5)
    out["max_abs_rolling_rel_diff"] = round(worst_my, 5)
    ok = worst_fx <= 0.05 and worst_my <= 0.10
    out["criteria_met"] = bool(ok)
    print(json.dumps(out, indent=1))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
