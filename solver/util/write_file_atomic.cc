#include <solver/util/write_file_atomic.hpp>

#include <fstream>
#include <stdexcept>

namespace beamimpact {

void write_file_atomic(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path tmp = file.string() + ".partial";
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw std::runtime_error("cannot write " + tmp.string());
      out << text;
      if (!out) throw std::runtime_error("error writing " + tmp.string());
    }
    std::filesystem::rename(tmp, file);  // fails when file is a directory
  } catch (...) {
    std::error_code ignored;  // no half-written .partial left behind
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

void remove_stale_outputs(const std::filesystem::path& dir, std::initializer_list<const char*> names) {
  if (dir.empty()) return;  // no output directory: nothing is written, nothing to remove
  for (const char* name : names)
    for (const std::filesystem::path& f : {dir / name, dir / (std::string(name) + ".partial")}) {
      std::error_code ec;
      if (!std::filesystem::exists(std::filesystem::symlink_status(f, ec)))
        continue;  // absent, or dir not one
      std::filesystem::remove(f, ec);
      if (ec)
        throw std::runtime_error("cannot remove the earlier output " + f.string() + ": " + ec.message());
    }
}

}  // namespace beamimpact
