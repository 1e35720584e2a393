"""Bad input raises modaltyre.InputError (a ValueError) with the CLI's file/line/key message."""
import re

import pytest

from conftest import run_cli, src


def misspelt_config(tmp_path):
    text = open(src("configs", "sf350.yaml")).read()
    text = text.replace("hammer_csv: data/", "hammer_csv: " + src("configs", "data") + "/")
    assert "  modulus_MPa: 3.0" in text
    path = tmp_path / "misspelt.yaml"
    path.write_text(text.replace("  modulus_MPa: 3.0", "  modulus_MPz: 3.0"))
    return str(path)


def test_misspelt_key_raises_input_error_with_the_cli_message(modaltyre, tmp_path):
    path = misspelt_config(tmp_path)
    with pytest.raises(modaltyre.InputError) as e:
        modaltyre.Tyre(path)
    assert isinstance(e.value, ValueError)
    assert "modulus_MPz" in str(e.value) and path in str(e.value)
    assert e.value.file == path and e.value.line > 0 and "modulus_MPz" in e.value.key
    _, err = run_cli("footprint", path, expect=2)
    assert err.strip() == "error: " + str(e.value)


def test_bad_override_and_bad_load(modaltyre):
    with pytest.raises(modaltyre.InputError, match=re.escape("tread.modulus_MPa")):
        modaltyre.Tyre(src("configs", "sf350_2d_table3.yaml"), {"tread.modulus_MPa": -1})
    tyre = modaltyre.Tyre(src("configs", "sf350_2d_table3.yaml"))
    for load in (-5.0, 1e-9, 2e7, float("nan")):
        with pytest.raises(modaltyre.InputError, match="load_N") as e:
            tyre.footprint(load)
        assert "--load" not in str(e.value)
    with pytest.raises(modaltyre.InputError, match="1.5 F_z"):
        tyre.footprint(1000.0, 5000.0)


def test_missing_files_and_error_classes(modaltyre, tmp_path):
    with pytest.raises(modaltyre.InputError):
        modaltyre.fit_modes(str(tmp_path / "absent.csv"))
    with pytest.raises(modaltyre.InputError):
        modaltyre.Tyre(str(tmp_path / "absent.yaml"))
    assert issubclass(modaltyre.ComputationError, RuntimeError)


def test_conditions_are_checked_as_the_cli_checks_them(modaltyre):
    """Names, ranges and words of the catalogue (core/conditions.h), errors at 'conditions'."""
    tyre = modaltyre.Tyre(src("configs", "sf350_2d_table3.yaml"))
    with pytest.raises(modaltyre.InputError, match=re.escape("[0, 1e7] s")) as e:
        tyre.footprint(4000, conditions={"hold_s": -1})
    assert e.value.key == "hold_s" and e.value.file == "conditions"
    with pytest.raises(modaltyre.InputError, match="surface"):
        tyre.footprint(4000, conditions={"surface": "mud"})
    with pytest.raises(modaltyre.InputError, match="does not apply here"):
        tyre.footprint(4000, conditions={"load_N": 3000})  # the load is the argument
    with pytest.raises(modaltyre.InputError, match="not an operating condition"):
        tyre.footprint(4000, conditions={"tread.modulus_MPa": 3})
    with pytest.raises(modaltyre.InputError, match="does not apply here"):
        modaltyre.transient(src("configs", "sf350_2d_table3.yaml"), "rolling",
                            conditions={"hold_s": 60})


def test_python_arguments_are_named_and_typed(modaltyre):
    """Issue 38: a pathlib.Path is a path, True is not a load, threads=0 is refused as the CLI
    refuses --threads 0, and errors name the Python argument, not the CLI option."""
    import pathlib

    cfg = pathlib.Path(src("configs", "sf350_2d_table3.yaml"))
    tyre = modaltyre.Tyre(cfg)
    assert tyre.footprint(4000).sinking_mm > 0
    assert modaltyre.fit_modes(pathlib.Path(src("configs", "data", "sf350_hammer_12pt.csv")))
    with pytest.raises(modaltyre.InputError, match="load_N: must be a number, got bool") as e:
        tyre.footprint(True)
    assert e.value.file == "load_N"
    with pytest.raises(modaltyre.InputError, match="loads_N: must be a number, got bool"):
        tyre.footprints([4000, False])
    with pytest.raises(modaltyre.InputError, match="config_path: must be a path"):
        modaltyre.Tyre(42)
    measured = pathlib.Path(src("configs", "data", "sf350_footprint_table3.csv"))
    with pytest.raises(modaltyre.InputError, match="threads: 0 is not a thread count") as e:
        modaltyre.discover(cfg, measured, threads=0)
    assert e.value.file == "threads"
    with pytest.raises(modaltyre.InputError, match="mass_kg") as e:
        modaltyre.identify("free-vibration", src("tests", "data", "rheology", "free_vibration.csv"),
                           mass_kg=-1.0, section_height_mm=117.0)
    assert "--" not in str(e.value)
