#pragma once
// The soil file `identify bevameter|shear DATA --write-ground OUT [--into-ground BASE]` writes
// (docs/soil.md section 6): a YAML document with a top-level `ground:` section that `--ground`
// reads. A plate test gives a Bekker soil (n, k_c, k_phi and, with unloading cycles, Wong's k0
// and Au); a shear test its Janosi-Hanamoto keys. Both tests go into one file with
// --into-ground: BASE's text with the identified keys set in place (its comments kept), written
// to OUT (never over BASE).
#include <string>
#include <vector>

#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/report/identify_run.h"

namespace modaltyre::report {

struct IdentifiedGround {
  std::string text;                ///< the soil file
  std::vector<std::string> notes;  ///< what was set, and how (the file's header says them too)
  ground::GroundSettings ground;   ///< the file read back as --ground reads it
};

/// InputError: a method other than bevameter or shear; a shear test without BASE (it has no
/// pressure-sinkage law of its own); a plate test into a BASE whose soil is not Bekker's; an
/// identified value outside the range the soil reader takes (named with its key).
IdentifiedGround identified_ground_file(const IdentifyRun& run, const std::string& data_file,
                                        const std::string& base_path, const std::string& out_path);

}  // namespace modaltyre::report
