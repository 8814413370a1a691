// The --out directory of a command: created when missing, reused when Tessera made it, refused when
// it holds other files (unless --force), and never a place where an input file would be
// overwritten.
#pragma once

#include "commands.h"

#include <tessera/view/view_scene.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tessera::cli {

class Output_directory {
public:
  /// Prepares `dir`; `inputs` are the files the command reads. Throws User_error when refused.
  Output_directory(const std::string& dir, bool force, std::vector<std::string> inputs);
  /// Path of output file `name` inside the directory; throws User_error if it is an input file.
  std::string file(const std::string& name) const;
  const std::filesystem::path& path() const { return dir_; }

private:
  std::filesystem::path dir_;
  std::vector<std::string> inputs_;
};

/// Writes a file whole or not at all: `write` gets a temporary path beside `path` with the same
/// extension, which replaces `path` only once `write` has returned; if it throws, the temporary
/// file goes and `path` stays as it was.
template <typename Write> void write_atomically(const std::string& path, Write write) {
  const std::filesystem::path p(path);
  const std::filesystem::path tmp =
      p.parent_path() / ("." + p.stem().string() + ".partial" + p.extension().string());
  try {
    write(tmp.string());
    std::filesystem::rename(tmp, p);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
}

/// "cannot write PATH: REASON", the reason from errno when the system gave one ("No space left on
/// device", "File too large").
std::string write_failure(const std::string& path);

/// `write_atomically` for a writer that says whether it worked: `write(tmp)` returns something
/// that converts to bool. A failure (a full disk, an I/O error) throws User_error naming `path`,
/// and `path` stays as it was.
template <typename Write> void write_checked(const std::string& path, Write write) {
  write_atomically(path, [&](const std::string& tmp) {
    errno = 0;
    if (!write(tmp))
      throw User_error(write_failure(path));
  });
}

/// `write_checked` for a writer of a stream: `write(out)` writes into a file opened on the
/// temporary name and returns false on failure; the file is then closed and checked (the last
/// buffer reaches the disk only at the close).
template <typename Write> void write_checked_stream(const std::string& path, Write write) {
  write_checked(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    const bool written = out && write(static_cast<std::ostream&>(out));
    out.close();
    return written && !out.fail();
  });
}

/// `text` into `path`, whole or not at all (`write_checked`).
void write_text_file(const std::string& path, const std::string& text);

/// `scene`'s page (tessera/view) into `path`, whole or not at all.
void write_view(const View_scene& scene, const std::string& path);

/// `--view` of a command: the flag on `cmd`, into `view`.
void add_view_flag(CLI::App* cmd, bool& view);

/// What `--view` writes: the page of the result in `dir` (as `tessera view` writes it) as
/// view.html there; `mesh` is the command's input. Returns the page's path.
std::string write_result_view(const Output_directory& dir, const std::string& mesh);

/// `written`, plus the page `write_result_view` writes when `view` (a command's --view).
std::vector<std::string> with_view(std::vector<std::string> written, const Output_directory& dir,
                                   bool view, const std::string& mesh);

/// One line on stdout naming the files a command wrote: "wrote A, B, C".
void print_written(const std::vector<std::string>& written);

} // namespace tessera::cli
