#pragma once
// Reader of FRFs in a long CSV, one row per FRF and spectral line:
//   response_point,response_dir,reference_point,reference_dir,freq_hz,re,im
// dir is `radial` or `tangential`; rows of one FRF are in increasing frequency and every FRF
// has the same frequencies. The file does not state the FRF type: the caller gives it
// (modaltyre ema --frf-type, default accelerance). Errors name file, line and column.
#include <string>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre::ema {

FrfSet read_frf_csv(const std::string& path, FrfType type, const FrfLimits& limits = {});

}  // namespace modaltyre::ema
