// The external dependencies the FMU states (documentation/externalDependencies.txt, issue 46
// item 1): read from the packed library's ELF file, checked against binutils' own reading of it
// (objdump -T: the dynamic symbols and the versions they need) and against glibc alone.
#include "modaltyre/fmu/elf_needs.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "fmu_host.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::fmu::test {
namespace {

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string run(const std::string& cmd) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  pclose(p);
  return out;
}

const std::string& unzipped() {
  static const std::string folder =
      pack_and_unzip(std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml");
  return folder;
}

TEST(FmuExternalDependencies, TheStatedGlibcIsTheNewestVersionObjdumpReads) {
  ASSERT_FALSE(unzipped().empty());
  const std::filesystem::path so =
      std::filesystem::path(unzipped()) / "binaries/linux64/ModalTyre.so";
  const ElfNeeds needs = read_elf_needs(read_all(so), so.string());
  // binutils' reading: every (GLIBC_x.y) of the dynamic symbol table.
  const std::string dump = run("objdump -T '" + so.string() + "'");
  ASSERT_NE(dump.find("fmi2DoStep"), std::string::npos) << dump.substr(0, 400);
  std::set<std::string> versions_objdump;
  const std::regex glibc("\\((GLIBC_[0-9.]+)\\)");
  for (auto it = std::sregex_iterator(dump.begin(), dump.end(), glibc);
       it != std::sregex_iterator(); ++it)
    versions_objdump.insert((*it)[1]);
  std::set<std::string> versions_read;
  for (const auto& v : needs.versions)
    for (const std::string& name : v.versions) versions_read.insert(name);
  // Every version a symbol needs is among the file's requirements (objdump lists per symbol).
  for (const std::string& v : versions_objdump) EXPECT_TRUE(versions_read.count(v)) << v;
  const std::string newest = newest_glibc_version(needs);
  EXPECT_TRUE(versions_objdump.count(newest)) << newest;
  const std::string text =
      read_all(std::filesystem::path(unzipped()) / "documentation/externalDependencies.txt");
  EXPECT_NE(text.find("version " + newest.substr(6) + " or newer"), std::string::npos) << text;
#ifndef MODALTYRE_FMU_SANITIZED
  // The self-contained library: glibc's libraries only.
  for (const std::string& lib : needs.libraries) EXPECT_TRUE(glibc_library(lib)) << lib;
  EXPECT_NE(text.find("Nothing else"), std::string::npos) << text;
#endif
}

TEST(FmuExternalDependencies, ABrokenFileIsAnInputErrorNamingIt) {
  EXPECT_THROW(read_elf_needs("not an ELF file at all, but long enough to hold a header........"
                              "................................",
                              "x.so"),
               InputError);
  // A real header whose section table lies beyond the file's end.
  const std::filesystem::path so =
      std::filesystem::path(unzipped()) / "binaries/linux64/ModalTyre.so";
  const std::string head = read_all(so).substr(0, 4096);
  try {
    read_elf_needs(head, "cut.so");
    ADD_FAILURE() << "a truncated file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cut.so"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace modaltyre::fmu::test
