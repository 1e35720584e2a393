// Calls the footprint solver of an installed ModalTyre: footprint_consumer CONFIG LOAD_N
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "modaltyre/contact/footprint.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: footprint_consumer CONFIG LOAD_N\n");
    return 2;
  }
  try {
    const auto model = modaltyre::contact::build_tyre_model(modaltyre::contact::load_tyre_config(argv[1]));
    const auto r = modaltyre::contact::solve_footprint(model, {std::atof(argv[2]), 0.0});
    if (!r.ok()) {
      std::fprintf(stderr, "no convergence: %s\n", r.message.c_str());
      return 1;
    }
    std::printf("sinking_mm %.3f contact_length_mm %.3f\n", r.sinking_m * 1e3,
                r.contact_length_m * 1e3);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
