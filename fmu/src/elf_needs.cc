#include "modaltyre/fmu/elf_needs.h"

#include <elf.h>

#include <cstring>
#include <set>
#include <sstream>

#include "modaltyre/core/errors.h"

namespace modaltyre::fmu {
namespace {

/// Bounds-checked reads of a file's bytes.
class Bytes {
 public:
  Bytes(const std::string& b, const std::string& path) : b_(b), path_(path) {}
  template <class T>
  T at(std::uint64_t offset) const {
    check(offset, sizeof(T));
    T v;
    std::memcpy(&v, b_.data() + offset, sizeof(T));
    return v;
  }
  /// The NUL-terminated string at `offset` of the string table [table, table + size).
  std::string string(std::uint64_t table, std::uint64_t size, std::uint64_t offset) const {
    if (offset >= size) fail("a string offset lies outside its table");
    check(table, size);
    const char* s = b_.data() + table + offset;
    const std::size_t n = strnlen(s, size - offset);
    if (n == size - offset) fail("a string is not terminated inside its table");
    return std::string(s, n);
  }
  void check(std::uint64_t offset, std::uint64_t size) const {
    if (offset > b_.size() || size > b_.size() - offset) fail("a table lies outside the file");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(InputLocation{path_, 0, ""}, "not a readable ELF-64 shared object: " + why);
  }

 private:
  const std::string& b_;
  const std::string& path_;
};

/// "GLIBC_2.35" -> {2, 35}; empty for another name.
std::vector<int> glibc_numbers(const std::string& v) {
  if (v.rfind("GLIBC_", 0) != 0) return {};
  std::vector<int> n;
  std::istringstream in(v.substr(6));
  std::string part;
  while (std::getline(in, part, '.')) {
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos) return {};
    n.push_back(std::stoi(part));
  }
  return n;
}

}  // namespace

ElfNeeds read_elf_needs(const std::string& bytes, const std::string& path) {
  const Bytes f(bytes, path);
  const auto eh = f.at<Elf64_Ehdr>(0);
  if (std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0) f.fail("no ELF magic");
  if (eh.e_ident[EI_CLASS] != ELFCLASS64 || eh.e_ident[EI_DATA] != ELFDATA2LSB)
    f.fail("not a little-endian 64-bit file");
  if (eh.e_shentsize != sizeof(Elf64_Shdr)) f.fail("unexpected section header size");
  std::vector<Elf64_Shdr> sections(eh.e_shnum);
  for (unsigned k = 0; k < eh.e_shnum; ++k)
    sections[k] = f.at<Elf64_Shdr>(eh.e_shoff + std::uint64_t(k) * sizeof(Elf64_Shdr));
  auto linked = [&](const Elf64_Shdr& s) -> const Elf64_Shdr& {
    if (s.sh_link >= sections.size()) f.fail("a section links to no section");
    return sections[s.sh_link];
  };
  ElfNeeds needs;
  for (const Elf64_Shdr& s : sections) {
    if (s.sh_type == SHT_DYNAMIC) {
      const Elf64_Shdr& str = linked(s);
      for (std::uint64_t off = 0; off + sizeof(Elf64_Dyn) <= s.sh_size; off += sizeof(Elf64_Dyn)) {
        const auto d = f.at<Elf64_Dyn>(s.sh_offset + off);
        if (d.d_tag == DT_NULL) break;
        if (d.d_tag == DT_NEEDED)
          needs.libraries.push_back(f.string(str.sh_offset, str.sh_size, d.d_un.d_val));
      }
    } else if (s.sh_type == SHT_GNU_verneed) {
      const Elf64_Shdr& str = linked(s);
      std::uint64_t off = s.sh_offset;
      // sh_info entries, each followed (vn_aux on) by its vn_cnt requirements.
      for (unsigned k = 0; k < s.sh_info; ++k) {
        const auto vn = f.at<Elf64_Verneed>(off);
        ElfNeeds::Versioned v{f.string(str.sh_offset, str.sh_size, vn.vn_file), {}};
        std::uint64_t aux = off + vn.vn_aux;
        for (unsigned a = 0; a < vn.vn_cnt; ++a) {
          const auto va = f.at<Elf64_Vernaux>(aux);
          v.versions.push_back(f.string(str.sh_offset, str.sh_size, va.vna_name));
          if (va.vna_next == 0) break;
          aux += va.vna_next;
        }
        needs.versions.push_back(std::move(v));
        if (vn.vn_next == 0) break;
        off += vn.vn_next;
      }
    }
  }
  return needs;
}

bool glibc_library(const std::string& soname) {
  static const std::set<std::string> glibc = {
      "libc.so.6",  "libm.so.6",      "ld-linux-x86-64.so.2", "libpthread.so.0", "libdl.so.2",
      "librt.so.1", "libresolv.so.2", "libutil.so.1",         "libmvec.so.1"};
  return glibc.count(soname) > 0;
}

std::string newest_glibc_version(const ElfNeeds& needs) {
  std::string best;
  std::vector<int> best_n;
  for (const auto& v : needs.versions)
    for (const std::string& name : v.versions) {
      const std::vector<int> n = glibc_numbers(name);
      if (!n.empty() && n > best_n) best = name, best_n = n;
    }
  return best;
}

std::string external_dependencies_text(const ElfNeeds& needs, const std::string& binary) {
  std::ostringstream t;
  t << "External dependencies of this FMU (FMI 2.0 section 2.3), measured on " << binary
    << "\nwhen the FMU was packed (its ELF dynamic section and symbol version needs).\n\n";
  std::vector<std::string> other;
  for (const std::string& lib : needs.libraries)
    if (!glibc_library(lib)) other.push_back(lib);
  const std::string glibc = newest_glibc_version(needs);
  t << "Platform: Linux on x86-64 (linux64).\n";
  if (!glibc.empty())
    t << "Required: the GNU C library (glibc), version " << glibc.substr(6)
      << " or newer\n(the newest symbol version the library uses is " << glibc << ").\n";
  if (other.empty()) {
    t << "Nothing else: the library needs no shared library outside the FMU but glibc's.\n"
         "Linked into it: the ModalTyre libraries, SUNDIALS (CVODE), KLU and SuiteSparse,\n"
         "yaml-cpp and the GCC C++ runtime (libstdc++, libgcc); OpenMP regions run on the\n"
         "calling thread (no OpenMP runtime is needed).\n";
  } else {
    t << "Also required on the system's library path (not part of glibc):\n";
    for (const std::string& lib : other) t << "  " << lib << "\n";
  }
  t << "\nShared libraries named by the library (DT_NEEDED):";
  for (const std::string& lib : needs.libraries) t << " " << lib;
  t << "\nSymbol versions required, per library:\n";
  for (const auto& v : needs.versions) {
    t << "  " << v.library << ":";
    for (const std::string& name : v.versions) t << " " << name;
    t << "\n";
  }
  return t.str();
}

}  // namespace modaltyre::fmu
