#include <solver/util/write_file_atomic.hpp>

#include <fstream>
#include <stdexcept>

namespace beamimpact {

void write_file_atomic(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path tmp = file.string() + ".partial";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
    out << text;
    if (!out) throw std::runtime_error("error writing " + tmp.string());
  }
  std::filesystem::rename(tmp, file);
}

}  // namespace beamimpact
