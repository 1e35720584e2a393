"""modaltyre.identify equals `modaltyre identify --json` for every seed-000 method."""
import pytest

from conftest import assert_same, cli_json, src

RHEO = src("tests", "data", "rheology")


def test_identify_equals_the_cli(modaltyre):
    config = src("configs", "sf350_2d_table3.yaml")
    cases = [
        (("load-deflection", f"{RHEO}/load_deflection.csv"), {"config": config},
         ["--config", config]),
        (("contact-stress", f"{RHEO}/contact_stress.csv"), {"config": config},
         ["--config", config]),
        (("soil-rolling", f"{RHEO}/soil_rolling.csv"), {"r0_mm": 500, "tread_width_mm": 300},
         ["--r0-mm", "500", "--tread-width-mm", "300"]),
        (("b-factors",), {"samples": 8, "sampling": "angle"},
         ["--samples", "8", "--sampling", "angle"]),
        (("free-vibration", f"{RHEO}/free_vibration.csv"),
         {"mass_kg": 350, "section_height_mm": 117, "static": f"{RHEO}/static_loop.csv",
          "config": config},
         ["--mass-kg", "350", "--section-height-mm", "117", "--static",
          f"{RHEO}/static_loop.csv", "--config", config]),
    ]
    for args, options, cli_options in cases:
        got = modaltyre.identify(*args, **options)
        assert_same(got, cli_json("identify", *args, *cli_options))
        assert got["parameters"] and all("unit" in p for p in got["parameters"].values())


def test_identify_refuses_bad_input(modaltyre):
    with pytest.raises(modaltyre.InputError, match="needs a measurement FILE"):
        modaltyre.identify("load-deflection")
    with pytest.raises(modaltyre.InputError, match="mass_kg"):
        modaltyre.identify("free-vibration", f"{RHEO}/free_vibration.csv", mass_kg=-3)
    with pytest.raises(modaltyre.InputError, match="not one of"):
        modaltyre.identify("magic", f"{RHEO}/load_deflection.csv")
