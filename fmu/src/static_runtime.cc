// What the FMU's shared library needs from the two runtimes it does not link (docs/fmu.md
// section 1; compiled into ModalTyre.so only, fmu/CMakeLists.txt). Everything here is hidden
// by the library's version script: a host never sees these definitions.
//
// OpenMP. The project's archives are compiled with -fopenmp (solvers/ carries it), so Eigen's
// matrix products and solvers/arrow_lu.cc call GCC's OpenMP runtime. GCC 12's libgomp.a cannot
// go into a shared object (its thread data uses local-exec TLS: R_X86_64_TPOFF32), and a
// libgomp.so.1 beside the FMU would be shadowed by a host's own. The FMU runs OpenMP with a team
// of one thread, the calling one: the five entry points the archives use, with the semantics
// the OpenMP 4.5 specification gives a team of one (sections 2.5 and 3.2). Eigen then takes its
// serial paths (it asks omp_get_max_threads() first). A co-simulation host steps its FMUs on
// its own threads, so the FMU starts none (and none are left running when it is unloaded).
// Should a new OpenMP construct need another entry point, the link fails (-z defs).
//
// glibc's __libc_single_threaded (a char, 1 while a process has one thread). Debian's
// libyaml-cpp.a is compiled as position-independent executable code, not as PIC: it reads this
// variable of libc.so.6 PC-relative, which a shared object cannot (a copy relocation is an
// executable's). A definition inside the FMU takes its place for every object of the FMU: held
// at 0, libstdc++'s inline code (shared_ptr's reference counts) always takes its atomic,
// thread-safe path, which is correct whether the host runs threads or not.
extern "C" {

void GOMP_parallel(void (*fn)(void*), void* data, unsigned /*num_threads*/, unsigned /*flags*/) {
  fn(data);  // the team of one: the region's body on the encountering thread
}
int omp_get_max_threads(void) { return 1; }
int omp_get_num_threads(void) { return 1; }
int omp_get_thread_num(void) { return 0; }
void omp_set_num_threads(int /*num_threads*/) {}

char __libc_single_threaded = 0;  // NOLINT(bugprone-reserved-identifier): glibc's name

}  // extern "C"
