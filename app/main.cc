// modaltyre: command-line front end. Exit codes: 0 success, 1 a computation failed (with its
// reason and residual), 2 bad input or usage (with file, line and key).
#include <malloc.h>

#include <csignal>
#include <iostream>
#include <string>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/thread_env.h"

int main(int argc, char** argv) {
  CLI::App app{
      "ModalTyre: tyre-road contact from experimental modal parameters (seed 001, Guan Dihua "
      "rolling theory) and rheological parameter identification (seed 000)."};
  app.require_subcommand(1);
  // Usage errors as one line like every other input error (exit 2): "error: --load: ...".
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "error: " + std::string(e.what()) + " (see modaltyre <command> --help)\n";
  });
  app.set_version_flag("--version", "modaltyre 0.1.0");
  modaltyre::app::register_fit_modes(app);
  modaltyre::app::register_footprint(app);
  modaltyre::app::register_identify(app);
  modaltyre::app::register_validate(app);
  modaltyre::app::register_sweep(app);
  modaltyre::app::register_transient(app);
  modaltyre::app::register_effects(app);
  modaltyre::app::register_discover(app);
  modaltyre::app::register_ema(app);
  modaltyre::app::register_tir(app);
  modaltyre::app::register_init(app);
  modaltyre::app::register_traction(app);
  modaltyre::app::register_fmu(app);
  modaltyre::app::require_decimal_numbers(app);
  modaltyre::app::check_output_paths(app);

  // Every footprint of the effects path allocates and frees a few dense candidate-unit matrices
  // (~250 kB on the 2 mm mesh). glibc returns such memory to the kernel when the top of the heap
  // exceeds its trim threshold and faults it in again on the next call: 40 % of discover's time
  // went to page faults. Keep up to 256 MB of freed memory per arena and serve blocks below
  // 32 MB from the heap (docs/discover.md, "Cost").
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);

  // A file-size limit (ulimit -f) then fails the write with EFBIG, which the atomic writer
  // reports and cleans up, instead of killing the program with a half-written temporary.
  std::signal(SIGXFSZ, SIG_IGN);
  if (argc > 1 && argv[1][0] != '-') {
    const std::string name = argv[1];
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known = known || sub->get_name() == name;
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "error: unknown command '" << name << "'; the commands are: " << names
                << " (modaltyre <command> --help for each)\n";
      return 2;
    }
  }

  // A result (or the help text) printed to a full disk or a closed pipe must not end with exit 0.
  auto stdout_written = [](int code) {
    std::cout.flush();
    if (code == 0 && !std::cout) {
      std::cerr << "error: writing the result to standard output failed (disk full?)\n";
      return 2;
    }
    return code;
  };
  try {
    // Every command may start OpenMP threads (sweeps, discover, Eigen's products).
    modaltyre::check_omp_num_threads();
    app.parse(argc, argv);
    return stdout_written(0);
  } catch (const modaltyre::app::QuietExit& e) {
    return e.code;
  } catch (const CLI::CallForHelp& e) {
    return stdout_written(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return stdout_written(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return stdout_written(app.exit(e));
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const modaltyre::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const modaltyre::ComputationError& e) {
    std::cerr << "computation failed: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "computation failed: out of memory (reduce the problem size)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return 1;
  }
}
