"""ModalTyre from Python: tyre-road contact from experimental modal parameters.

A thin layer over the C++ library: every result is the one the `modaltyre` command prints
with --json (same library functions), numeric series as NumPy arrays. Errors:
InputError (a ValueError; file, line and key as the CLI's exit code 2) and
ComputationError (a RuntimeError; the CLI's exit code 1). See README.md, "From Python".
"""
try:
    import numpy  # noqa: F401
except ImportError:
    # A second interpreter of the same version without NumPy (e.g. a pyenv python3 ahead of
    # Debian's on the PATH) can use the NumPy the extension was built against: the ABI is the
    # interpreter version's. Any other mismatch is refused with what to run instead.
    import sys as _sys

    from ._build_info import NUMPY_DIR as _numpy_dir
    from ._build_info import PYTHON_EXECUTABLE as _built_for
    from ._build_info import PYTHON_VERSION as _built_version

    if tuple(_sys.version_info[:2]) != _built_version:
        raise ImportError(
            "modaltyre was built for Python %d.%d (%s); this is Python %d.%d: run it with %s"
            % (*_built_version, _built_for, *_sys.version_info[:2], _built_for)
        ) from None
    _sys.path.append(_numpy_dir)
    import numpy  # noqa: F401

from ._modaltyre import *  # noqa: F401,F403
from ._modaltyre import __doc__ as _ext_doc  # noqa: F401
