#pragma once
// Reader of Universal File Format dataset 58 ("function at nodal DOF"), the export format of
// modal test software, in ASCII and in the binary variant 58b.
//
// A file is a sequence of datasets, each between lines "    -1"; datasets other than 58 and
// datasets 58 whose function type (record 6 field 1) is not 4 (frequency response function)
// are skipped. Records 6-11 are read in the specification's fixed columns, with a fallback to
// blank-separated fields for writers that do not keep the columns; the data record 12 likewise
// (E13.5 / E20.12 columns, or blank-separated, Fortran 'D' exponents accepted). Binary 58b
// (IEEE 754, either byte order) takes its byte count from records 7 and the ordinate type.
//
// Mapping to a tyre (docs/ema.md): the node number is the point, direction +-3 is radial and
// +-1 tangential in the point's local frame; a negative direction flips the sign of the FRF.
// The FRF type comes from the ordinate numerator's data type (record 9 field 1: 12
// acceleration, 11 velocity, 8 displacement) over force (record 10 field 1: 13); units are SI.
// Every problem is an InputError naming the file, the line and the record and field.
#include <string>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre::ema {

FrfSet read_uff58(const std::string& path, const FrfLimits& limits = {});

}  // namespace modaltyre::ema
