#pragma once
// Parameter sweeps: sweep_spec.h (the sweep file), sweep_plan.h (cases and models),
// sweep_run.h (OpenMP run, MPI share), sweep_output.h (the CSV).
#include "modaltyre/studies/sweep_output.h"
#include "modaltyre/studies/sweep_plan.h"
#include "modaltyre/studies/sweep_run.h"
#include "modaltyre/studies/sweep_spec.h"
