"""ModalTyre from Python: tyre-road contact from experimental modal parameters.

A thin layer over the C++ library: every result is the one the `modaltyre` command prints
with --json (same library functions), numeric series as NumPy arrays. Errors:
InputError (a ValueError; file, line and key as the CLI's exit code 2) and
ComputationError (a RuntimeError; the CLI's exit code 1). See README.md, "From Python".
"""
from ._modaltyre import *  # noqa: F401,F403
from ._modaltyre import __doc__ as _ext_doc  # noqa: F401
