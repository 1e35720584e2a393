#pragma once
// The files one command reads and writes, checked together before anything is computed: no
// output may be the same file as an input (a measurement turned into a results file is data
// lost) or as another output (two writers, one survivor). "Same file" is file identity, not
// spelling: hard links, symbolic links, "..", "./" and an absolute spelling of a relative path
// are all seen through (an existing file is compared by device and inode, a path that does not
// exist yet by the absolute, normalised form of the file its links finally name: a dangling link
// names the file that writing through it creates, so a link to another output not yet written
// is that output).
#include <string>
#include <vector>

namespace modaltyre {

class CommandFiles {
 public:
  /// A file the command reads; `role` names it in messages ("CONFIG", "modal.hammer_csv",
  /// "base:"). An empty path is ignored (an optional input not given).
  void input(const std::string& path, const std::string& role);
  /// Every input of another list (e.g. the files a config read), with their roles.
  void inputs(const CommandFiles& other);
  /// A file the command will write; `option` names it in messages ("--output", "--plot").
  /// Only call it for an output the user asked for: an empty path is refused by check().
  void output(const std::string& path, const std::string& option);

  /// Refuses (InputError at the output's path and option, exit 2): an empty output path, an
  /// output whose folder does not exist or that is a directory, an output that is the same
  /// file as an input or as another output (the message names both). Nothing is read or written.
  void check() const;

  struct Entry {
    std::string path, role;
  };
  const std::vector<Entry>& input_entries() const { return inputs_; }

 private:
  std::vector<Entry> inputs_, outputs_;
};

/// The absolute, normalised path of the file `path` finally names: the symbolic links of its
/// folders and of the file itself followed, a dangling link's target included (at most 40 links,
/// as the kernel's limit; a loop stops there).
std::string final_target(const std::string& path);

/// Whether two paths name the same file (see the header comment); false when either is empty.
bool same_file(const std::string& a, const std::string& b);

}  // namespace modaltyre
