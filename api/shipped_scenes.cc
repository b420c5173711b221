#include <api/shipped_scenes.hpp>

#include <algorithm>

#include <api/methods_file.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {

namespace fs = std::filesystem;

std::vector<ShippedScene> shipped_scenes() {
  std::vector<ShippedScene> out;
  const fs::path root = data_root();
  std::error_code ec;
  if (root.empty() || !fs::is_directory(root / "verification/scenes", ec)) return out;
  for (const auto& e : fs::recursive_directory_iterator(root / "verification/scenes", ec))
    if (e.is_regular_file(ec) && e.path().extension() == ".toml")
      out.push_back({e.path().stem().string(), e.path().lexically_normal()});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.file < b.file; });
  return out;
}

fs::path resolve_data_file(const std::string& arg) {
  std::error_code ec;
  const fs::path p(arg);
  if (arg.empty() || fs::exists(p, ec) || p.is_absolute()) return p;
  if (const fs::path root = data_root(); !root.empty() && fs::is_regular_file(root / p, ec))
    return (root / p).lexically_normal();
  return p;
}

fs::path resolve_scene(const std::string& arg) {
  std::error_code ec;
  const fs::path given(arg);
  if (arg.empty() || given.is_absolute() || fs::exists(given, ec)) return given;  // rule 1
  const fs::path root = data_root();
  if (root.empty()) return given;
  for (const fs::path& p : {root / given, root / "verification/scenes" / given})  // rules 2 and 3
    if (fs::is_regular_file(p, ec)) return p.lexically_normal();
  if (arg.find('/') != std::string::npos) return given;  // rule 5
  const std::string name = given.extension() == ".toml" ? given.stem().string() : arg;
  std::vector<fs::path> found;  // rule 4
  for (const ShippedScene& s : shipped_scenes())
    if (s.name == name) found.push_back(s.file);
  if (found.size() > 1) {
    std::string list;
    for (const fs::path& f : found) list += (list.empty() ? "" : ", ") + f.string();
    throw InputError(arg, "",
                     "expected a scene file or the name of one shipped scene; '" + name +
                         "' names several: " + list + " (give the path)");
  }
  return found.empty() ? given : found.front();
}

}  // namespace beamimpact
