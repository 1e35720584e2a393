// The rheology identification CSV readers, each tried on the same input (a file meant for one
// is rejected by the others' headers), and the identification each feeds, with the geometry of
// the bundled test data (tests/data/rheology); the soil's plate-sinkage and shear tests
// (docs/soil.md) and the ground's road-profile CSV.
#include <string>

#include "fuzz_support.h"
#include "modaltyre/ground/road_profile.h"
#include "modaltyre/rheology/bevameter.h"
#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/free_vibration.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"

namespace r = modaltyre::rheology;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static modaltyre::fuzz::ScratchFile file("rheology");
  const std::string& path = file.write(data, size);
  using modaltyre::fuzz::guarded;

  guarded([&] {
    r::LoadDeflectionOptions o;
    o.r0_m = 0.2948;
    (void)r::identify_load_deflection(r::read_load_deflection_csv(path), o);
  });
  guarded([&] {
    r::ContactStressOptions o;
    o.r0_m = 0.2948;
    o.tread_width_m = 0.13;
    (void)r::identify_contact_stress(r::read_contact_stress_csv(path), o);
  });
  guarded([&] {
    const r::SoilOptions o{0.5, 0.3};
    (void)r::identify_soil(r::read_soil_rolling_csv(path), o);
  });
  r::ThreeElementOptions three;
  three.r0_m = 0.2948;
  three.tread_width_m = 0.13;
  three.section_height_m = 0.117;
  three.mass_kg = 350.0;
  guarded([&] { (void)r::identify_static_loop(r::read_static_loop_csv(path), three); });
  guarded([&] {
    (void)r::identify_free_vibration(r::read_free_vibration_csv(path), nullptr, three);
  });
  guarded([&] { (void)r::identify_bevameter(r::read_plate_sinkage_csv(path)); });
  guarded([&] { (void)r::identify_shear(r::read_shear_csv(path)); });
  guarded([&] {
    const auto profile = modaltyre::ground::read_road_profile_csv(path);
    (void)profile.height_at(0.5 * (profile.x_m.front() + profile.x_m.back()));
  });
  return 0;
}
