#pragma once
// The transient (time-domain) tyre on a rigid road: modal carcass, Kelvin-Voigt tread, hub DOF,
// unilateral contact; integrated with CVODE (BDF) + KLU. Derivations in docs/transient.md.
//   model.h       the transient model built from a static TyreModel (equations stated there)
//   scenario.h    load-hold, free-vibration, rolling, cleat: F(t), V(t), road, initial state
//   ode_system.h  right-hand side, Jacobian and contact root functions
//   tread_window.h  the units that can touch in a scenario (the ODE's tread states)
//   driver.h      run_transient(): integration, contact switches, output samples
//   cell_model.h  the 3D patch's cells on the transient carcass (run_transient_3d)
//   hub_motion.h, driven_tyre.h  the tyre driven by a prescribed hub (DrivenTyre, run_prescribed)
#include "modaltyre/transient/cell_model.h"
#include "modaltyre/transient/decay.h"
#include "modaltyre/transient/driven_tyre.h"
#include "modaltyre/transient/driver.h"
#include "modaltyre/transient/hub_motion.h"
#include "modaltyre/transient/model.h"
#include "modaltyre/transient/ode_system.h"
#include "modaltyre/transient/scenario.h"
#include "modaltyre/transient/tread_window.h"
