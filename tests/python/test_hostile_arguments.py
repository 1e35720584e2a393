"""Issue 44 item 5, Python: careless arguments are the module's InputError naming the argument,
never a path cut short at a NUL byte, a bool taken for a count, or Python's own RuntimeError /
OverflowError; init's numbers given as 0 or below are refused, not read as "not given"."""
import os

import pytest

from conftest import src

SF350_2D = src("configs", "sf350_2d_table3.yaml")
LETE = src("configs", "soils", "lete_sand.yaml")
FREQ = [90, 105, 124, 146, 170, 195]


def test_a_nul_byte_in_a_path_is_refused_not_cut_short(modaltyre, tmp_path):
    with pytest.raises(modaltyre.InputError, match="config_path.*NUL"):
        modaltyre.traction(SF350_2D + "\0junk", [3000], [0.2], ground=LETE)
    out = tmp_path / "new.yaml"
    with pytest.raises(modaltyre.InputError, match="output.*NUL"):
        modaltyre.init("205/55R16", test_pressure_kPa=200, frequencies_hz=FREQ,
                       output=str(out) + "\0.csv")
    assert not os.listdir(tmp_path), "nothing written"


def test_counts_and_orders_are_ints_in_range(modaltyre):
    with pytest.raises(modaltyre.InputError, match="passes.*int.*bool"):
        modaltyre.traction(SF350_2D, [3000], [0.2], ground=LETE, passes=True)
    with pytest.raises(modaltyre.InputError, match="orders.*outside 0-999"):
        modaltyre.init("205/55R16", test_pressure_kPa=200, frequencies_hz=FREQ,
                       orders=[2**70, 2, 3, 4, 5, 6])
    with pytest.raises(modaltyre.InputError, match="orders.*int"):
        modaltyre.init("205/55R16", test_pressure_kPa=200, frequencies_hz=FREQ,
                       orders=[True, 2, 3, 4, 5, 6])


def test_a_number_too_large_for_a_float_is_an_input_error(modaltyre):
    with pytest.raises(modaltyre.InputError, match="test_pressure_kPa.*too large"):
        modaltyre.init("205/55R16", test_pressure_kPa=10**400, frequencies_hz=FREQ)
    with pytest.raises(modaltyre.InputError, match="loads_N.*too large"):
        modaltyre.traction(SF350_2D, [10**400], [0.2], ground=LETE)


@pytest.mark.parametrize("arg,option", [
    ("pressure_kPa", "--pressure-kPa"), ("belt_mass_kg", "--belt-mass-kg"),
    ("wheel_mass_kg", "--wheel-mass-kg"), ("belt_width_mm", "--belt-width-mm"),
    ("tread_depth_mm", "--tread-depth-mm"), ("tread_width_mm", "--tread-width-mm"),
    ("fnomin_N", "--fnomin")])
def test_init_numbers_at_or_below_zero_are_refused(modaltyre, arg, option):
    for value in (0, -1):
        # Named as the Python argument (the module's translation of the option).
        with pytest.raises(modaltyre.InputError, match=f"^({arg}|{option[2:]}): .*> 0"):
            modaltyre.init("205/55R16", test_pressure_kPa=200, frequencies_hz=FREQ,
                           **{arg: value})
    got = modaltyre.init("205/55R16", test_pressure_kPa=200, frequencies_hz=FREQ, **{arg: None})
    assert "tyre:" in got["config"]
