#pragma once
// What a Linux shared library needs from outside itself, read from its ELF file (System V ABI,
// ELF-64 object file format; the GNU symbol versioning of the Linux Standard Base, "Symbol
// Versioning": section .gnu.version_r, SHT_GNU_verneed): the shared libraries it names
// (DT_NEEDED in .dynamic) and, per library, the symbol versions it requires (GLIBC_2.35, ...).
// The FMU writes them into documentation/externalDependencies.txt (FMI 2.0 section 2.3), so that
// the file states what the packed ModalTyre.so needs, measured on it.
#include <string>
#include <vector>

namespace modaltyre::fmu {

struct ElfNeeds {
  std::vector<std::string> libraries;  ///< DT_NEEDED, in the file's order
  struct Versioned {
    std::string library;                ///< vn_file
    std::vector<std::string> versions;  ///< vna_name of each requirement
  };
  std::vector<Versioned> versions;
};

/// The needs of a little-endian ELF-64 shared object given as its bytes. InputError naming
/// `path` when the bytes are not one or a table lies outside the file.
ElfNeeds read_elf_needs(const std::string& bytes, const std::string& path);

/// The libraries of the GNU C library (libc, libm, the loader and glibc's smaller ones).
bool glibc_library(const std::string& soname);

/// The newest "GLIBC_x.y[.z]" among the needs ("" when none).
std::string newest_glibc_version(const ElfNeeds& needs);

/// The text of documentation/externalDependencies.txt for a library `binary` (its path in the
/// archive) with these needs.
std::string external_dependencies_text(const ElfNeeds& needs, const std::string& binary);

}  // namespace modaltyre::fmu
