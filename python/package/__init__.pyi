# Type stubs of the modaltyre package (the extension modaltyre._modaltyre). Units are in the
# names: _N newton, _mm millimetre, _kPa kilopascal, _s second, _hz hertz.
import os
from typing import Any, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

# Paths: a str or a pathlib.Path (any os.PathLike).
StrPath = Union[str, os.PathLike[str]]

class InputError(ValueError):
    file: str
    line: int
    key: str

class ComputationError(RuntimeError): ...

class Footprint:
    load_N: float
    sinking_mm: float
    length_mm: float
    width_mm: Optional[float]
    converged: bool
    iterations: int
    valid: bool
    x_mm: npt.NDArray[np.float64]
    pressure_kPa: npt.NDArray[np.float64]
    map: Optional[dict[str, npt.NDArray[np.float64]]]
    data: dict[str, Any]

class Tyre:
    name: str
    patch: str
    loads_N: list[float]
    def __init__(self, config_path: StrPath, overrides: dict[str, Any] = ...) -> None: ...
    def footprint(
        self,
        load_N: float,
        horizontal_force_N: Optional[float] = None,
        conditions: dict[str, Any] = ...,
    ) -> Footprint: ...
    def footprints(
        self,
        loads_N: Sequence[float],
        horizontal_force_N: Optional[float] = None,
        conditions: dict[str, Any] = ...,
    ) -> list[Footprint]: ...
    def report(
        self,
        loads_N: Sequence[float] = ...,
        horizontal_force_N: Optional[float] = None,
        conditions: dict[str, Any] = ...,
    ) -> dict[str, Any]: ...

def fit_modes(path: StrPath) -> dict[str, Any]: ...
def validate(
    config_path: StrPath,
    measured_csv: StrPath,
    overrides: dict[str, Any] = ...,
    conditions: dict[str, Any] = ...,
) -> dict[str, Any]: ...
def sweep(
    sweep_yaml: StrPath,
    threads: Optional[int] = None,
    overrides: dict[str, Any] = ...,
    warm_start: bool = False,
) -> dict[str, npt.NDArray[Any]]: ...
def transient(
    config_path: StrPath,
    scenario: str,
    overrides: dict[str, Any] = ...,
    conditions: dict[str, Any] = ...,
) -> dict[str, Any]: ...
def traction(
    config_path: StrPath,
    loads_N: Sequence[float],
    slips: Sequence[float],
    ground: Optional[StrPath] = None,
    overrides: dict[str, Any] = ...,
    passes: int = 1,
    slip_reference: str = "rolling",
    speed_km_h: Optional[float] = None,
) -> dict[str, Any]: ...
def effects() -> list[dict[str, Any]]: ...
def discover(
    config_path: StrPath,
    measured_csv: StrPath,
    overrides: dict[str, Any] = ...,
    threads: Optional[int] = None,
) -> dict[str, Any]: ...
def identify(
    method: str,
    path: Optional[StrPath] = None,
    *,
    config: Optional[StrPath] = None,
    r0_mm: Optional[float] = None,
    tread_width_mm: Optional[float] = None,
    mass_kg: Optional[float] = None,
    contact_length_mm: Optional[float] = None,
    section_height_mm: Optional[float] = None,
    pressure_kPa: Optional[float] = None,
    static: Optional[StrPath] = None,
    samples: int = 6,
    sampling: str = "deflection",
    intercept: bool = False,
    max_h_r0: float = 0.117,
) -> dict[str, Any]: ...
def init(
    size: str,
    *,
    test_pressure_kPa: float,
    pressure_kPa: Optional[float] = None,
    frequencies_hz: Optional[Sequence[float]] = None,
    damping_ratios: Optional[Sequence[float]] = None,
    orders: Optional[Sequence[Union[int, str]]] = None,
    hammer_csv: Optional[StrPath] = None,
    belt_mass_kg: Optional[float] = None,
    boundary: str = "free",
    wheel_mass_kg: Optional[float] = None,
    belt_width_mm: Optional[float] = None,
    tread_depth_mm: Optional[float] = None,
    tread_width_mm: Optional[float] = None,
    fnomin_N: Optional[float] = None,
    name: str = "",
    two_d: bool = False,
    output: Optional[StrPath] = None,
) -> dict[str, Any]: ...
