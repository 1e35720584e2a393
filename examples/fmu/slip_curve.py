#!/usr/bin/env python3
"""Braking slip curve of a tyre FMU, measured through its FMI functions (issue 34's check).

    modaltyre fmu configs/sf350_2d_table3.yaml --output sf350.fmu
    python3 examples/fmu/slip_curve.py sf350.fmu --load-N 4000 --speed-kmh 30

A wheel hub of 20 kg carries the load on the tyre (load control by the host, with a damper that
settles the hub's bounce); the wheel first rolls freely (spin integrated from the tyre's moment,
inertia 1 kg m^2): its spin gives the effective rolling radius R_e = V / Omega_free, SAE's
reference for the slip. Then the spin is held at V (1 + kappa) / R_e for each slip in turn.
Prints F_x and F_z per slip, the slip stiffness C_kappa (from kappa = -0.005) over F_z and the
free-rolling F_x / F_z.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fmi2_host import Fmu, Instance  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("fmu")
    ap.add_argument("--load-N", type=float, default=4000.0)
    ap.add_argument("--speed-kmh", type=float, default=30.0)
    ap.add_argument("--mu", type=float, default=0.8)
    ap.add_argument("--slips", default="-0.005,-0.02,-0.05,-0.1,-0.2,-0.3")
    a = ap.parse_args()
    fmu = Fmu(a.fmu)
    inst = Instance(fmu, "slip", quiet=True)
    h, m, c, inertia = 1e-3, 20.0, 2000.0, 1.0
    R0 = [float(sv[0].get("start")) for sv in __import__("xml.etree.ElementTree", fromlist=["x"])
          .parse(os.path.join(fmu.folder, "modelDescription.xml")).getroot().find("ModelVariables")
          if sv.get("name") == "wheel_state.pos.z"][0]
    speed = a.speed_kmh / 3.6
    # The static wheel height under the load, by secant in initialization mode.
    inst.enter_initialization()
    z0, z1, f0 = R0 - 0.005, R0 - 0.015, None
    for _ in range(30):
        if f0 is None:
            inst.set({"wheel_state.pos.z": z0})
            f0 = inst.get(["wheel_load.force.z"])["wheel_load.force.z"] - a.load_N
        inst.set({"wheel_state.pos.z": z1})
        f1 = inst.get(["wheel_load.force.z"])["wheel_load.force.z"] - a.load_N
        if abs(f1) < 1e-6 * a.load_N or f1 == f0:
            break
        z0, z1, f0 = z1, z1 - f1 * (z1 - z0) / (f1 - f0), f1
    inst.exit_initialization()
    st = {"z": z1, "w": 0.0, "x": 0.0, "angle": 0.0, "spin": 0.0}
    ramp = 0.5

    def roll(until, spin_of=None):
        rows = []
        while inst.time < until - 1e-9:
            s = min(inst.time / ramp, 1.0)
            v = speed * s * s * (3 - 2 * s)
            if spin_of:
                st["spin"] = spin_of(v)
            q = (math.cos(st["angle"] / 2), 0.0, math.sin(st["angle"] / 2), 0.0)
            inst.set({"wheel_state.pos.x": st["x"], "wheel_state.pos.z": st["z"],
                      "wheel_state.lin_vel.x": v, "wheel_state.lin_vel.z": st["w"],
                      "wheel_state.rot.e0": q[0], "wheel_state.rot.e2": q[2],
                      "wheel_state.ang_vel.y": st["spin"], "terrain_mu": a.mu})
            inst.step(h)
            o = inst.get(["wheel_load.force.x", "wheel_load.force.z", "wheel_load.moment.y"])
            st["w"] += h * ((o["wheel_load.force.z"] - a.load_N) - c * st["w"]) / m
            st["z"] += h * st["w"]
            if not spin_of:
                st["spin"] += h * o["wheel_load.moment.y"] / inertia
            st["angle"] += h * st["spin"]
            st["x"] += h * v
            rows.append((o["wheel_load.force.x"], o["wheel_load.force.z"]))
        return rows

    free = roll(1.5)[-200:]
    fx_free = sum(r[0] for r in free) / len(free)
    fz_free = sum(r[1] for r in free) / len(free)
    Re = speed / st["spin"]
    print(f"free rolling at {a.speed_kmh:g} km/h: Fx/Fz {fx_free / fz_free:.5f}, "
          f"R_e {Re * 1e3:.2f} mm")
    t = 1.5
    results = []
    for kappa in (float(k) for k in a.slips.split(",")):
        t += 0.3
        rows = roll(t, lambda v, k=kappa: v * (1 + k) / Re)[-100:]
        fx = sum(r[0] for r in rows) / len(rows)
        fz = sum(r[1] for r in rows) / len(rows)
        results.append((kappa, fx, fz))
        print(f"kappa {kappa:+.3f}: Fx {fx:9.1f} N  Fz {fz:7.1f} N  |Fx|/(mu Fz) "
              f"{abs(fx) / (a.mu * fz):.3f}")
    k0, fx0, fz0 = results[0]
    print(f"C_kappa {(fx0 - fx_free) / k0:.0f} N, C_kappa / Fz {(fx0 - fx_free) / k0 / fz0:.2f}")
    inst.free()


if __name__ == "__main__":
    main()
