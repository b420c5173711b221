#include <verification/jobs/program_id.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include <solver/util/sha256.hpp>

namespace beamimpact::jobs {

namespace fs = std::filesystem;

fs::path program_code_file() {
  // Each line of /proc/self/maps: "lo-hi perms offset dev inode [path]"; the path (absolute) may
  // end in " (deleted)" when the file was replaced since it was mapped.
  const auto here = reinterpret_cast<std::uintptr_t>(&program_code_file);
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);) {
    std::istringstream in(line);
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    if (!(in >> std::hex >> lo >> dash >> hi) || dash != '-' || here < lo || here >= hi) continue;
    const auto slash = line.find('/');
    if (slash == std::string::npos) break;
    std::string path = line.substr(slash);
    if (path.ends_with(" (deleted)")) path.resize(path.size() - 10);
    return path;
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

const std::string& program_sha256() {
  static const std::string id = [] {
    const fs::path file = program_code_file();
    std::string sha = file.empty() ? std::string() : file_sha256(file);
    if (sha.empty()) {
      const auto now = std::chrono::system_clock::now().time_since_epoch();
      sha = fmt::format("unread:{}-{}", ::getpid(),
                        std::chrono::duration_cast<std::chrono::nanoseconds>(now).count());
    }
    return sha;
  }();
  return id;
}

}  // namespace beamimpact::jobs
