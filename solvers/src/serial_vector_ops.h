#pragma once
// Replacement kernels for the SUNDIALS serial N_Vector operations that CVODE uses every step.
//
// Why: Debian's libsundials serial vector costs ~20 instructions per element and operation
// (callgrind: N_VWSqrSumLocal_Serial 17,000 instructions for 819 entries), and a transient tyre
// step runs some forty of them; after the structured Newton solver they were 75 % of a free
// vibration's instructions. These loops are the same arithmetic compiled with the project's
// flags (vectorised; the norms sum in four interleaved partial sums). Vectors cloned from one
// that carries them (CVODE clones every work vector from y0) carry them too.
#include <nvector/nvector_serial.h>

namespace modaltyre::solvers {

/// Installs the kernels in v's operation table (a serial vector).
void install_serial_vector_ops(N_Vector v);

}  // namespace modaltyre::solvers
