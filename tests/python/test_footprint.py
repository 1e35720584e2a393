"""modaltyre.Tyre against `modaltyre footprint --json`: the same numbers, arrays that own their
memory, solves in parallel threads equal to serial ones."""
import gc
import threading

import numpy as np

from conftest import assert_same, cli_json, src

SF350 = src("configs", "sf350.yaml")
SF350_2D = src("configs", "sf350_2d_table3.yaml")


def test_3d_footprint_equals_the_cli(modaltyre):
    tyre = modaltyre.Tyre(SF350)
    cli = cli_json("footprint", SF350, "--load", "4000")
    # The run's conditions: the config's defaults without --set.
    assert cli["conditions"] == {"pressure_kPa": 230.0, "hold_s": 0.0, "speed_kmh": 0.0,
                                 "branch": "load", "surface": "rigid"}
    assert_same(tyre.report([4000]), cli)
    f = tyre.footprint(4000)
    case = cli["cases"][0]
    assert f.sinking_mm == case["sinking_mm"] and f.length_mm == case["contact_length_mm"]
    assert f.width_mm == case["width_mm"]
    assert f.converged and f.iterations == case["iterations"]
    np.testing.assert_array_equal(f.x_mm, [u["x_mm"] for u in case["units"]])
    np.testing.assert_array_equal(f.pressure_kPa, [u["pressure_kPa"] for u in case["units"]])
    np.testing.assert_array_equal(f.map["pressure_kPa"], np.array(case["map"]["pressure_kPa"]))
    assert f.map["pressure_kPa"].shape == (len(case["map"]["y_mm"]), len(case["map"]["x_mm"]))
    assert_same(f.data, case)


def test_2d_footprints_with_a_horizontal_force_equal_the_cli(modaltyre):
    loads = [2131, 5478, 8321]
    tyre = modaltyre.Tyre(SF350_2D, {"contact.unit_length_mm": 1.0})
    args = ["footprint", SF350_2D, "--set", "contact.unit_length_mm=1.0", "--fx", "500"]
    for load in loads:
        args += ["--load", str(load)]
    cli = cli_json(*args)
    assert cli["conditions"]["hold_s"] == 0.0  # the config's defaults
    assert_same(tyre.report(loads, 500.0), cli)
    for f, case in zip(tyre.footprints(loads, 500.0), cli["cases"]):
        assert f.width_mm is None and f.map is None  # the 2D patch's width is an input
        assert f.load_N == case["load_N"] and f.sinking_mm == case["sinking_mm"]
        np.testing.assert_array_equal(f.pressure_kPa, [u["pressure_kPa"] for u in case["units"]])


def test_arrays_own_their_memory_after_the_tyre_is_deleted(modaltyre):
    tyre = modaltyre.Tyre(SF350_2D)
    f = tyre.footprint(5478)
    x, p = f.x_mm, f.pressure_kPa
    expected = (x.copy(), p.copy())
    assert x.flags["OWNDATA"] and p.flags["OWNDATA"]
    del tyre, f
    gc.collect()
    garbage = [modaltyre.Tyre(SF350_2D).footprint(8321) for _ in range(2)]  # reuse the heap
    np.testing.assert_array_equal(x, expected[0])
    np.testing.assert_array_equal(p, expected[1])
    assert len(garbage) == 2
    m3 = modaltyre.Tyre(SF350).footprint(3000).map
    assert m3["pressure_kPa"].flags["OWNDATA"]


def test_two_threads_on_two_tyres_give_the_serial_results(modaltyre):
    loads = [2131, 3261, 5478, 6502]
    tyres = [modaltyre.Tyre(SF350), modaltyre.Tyre(SF350_2D)]
    serial = [t.report(loads) for t in tyres]
    parallel = [None, None]

    def work(i):
        parallel[i] = tyres[i].report(loads)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert parallel[0] == serial[0] and parallel[1] == serial[1]


def test_conditions_equal_the_cli_set(modaltyre):
    """conditions={'hold_s': 60, 'surface': 'soil'} = --set hold_s=60 --set surface=soil: the
    held, relaxed tread (seed 001 eq. (10)) on soil sinks deeper than at rest on a rigid road."""
    sets = {"contact.unit_length_mm": 2, "effects.tread_relaxation.enabled": True,
            "effects.soil_compliance.enabled": True}
    tyre = modaltyre.Tyre(SF350_2D, sets)
    args = ["footprint", SF350_2D, "--load", "4000"]
    for k, v in sets.items():
        args += ["--set", f"{k}={str(v).lower()}"]
    cli = cli_json(*args, "--set", "hold_s=60", "--set", "surface=soil")
    got = tyre.report([4000], conditions={"hold_s": 60, "surface": "soil"})
    assert got["conditions"]["hold_s"] == 60.0 and got["conditions"]["surface"] == "soil"
    assert_same(got, cli)
    held = tyre.footprint(4000, conditions={"hold_s": 60, "surface": "soil"})
    assert held.sinking_mm == cli["cases"][0]["sinking_mm"]
    assert held.sinking_mm > 1.01 * tyre.footprint(4000).sinking_mm
