#include <api/methods_file.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include <solver/scene/TableReader.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

/// The file placeholders, expanded when the file is read: {here} and {beamimpact}.
bool is_file_placeholder(const std::string& name) { return name == "here" || name == "beamimpact"; }

/// The first {name} of `arg` that is neither a run nor a file placeholder, or "".
std::string unknown_placeholder(const std::string& arg) {
  for (std::size_t open = arg.find('{'); open != std::string::npos; open = arg.find('{', open + 1)) {
    const std::size_t close = arg.find('}', open);
    if (close == std::string::npos) return arg.substr(open);
    const std::string name = arg.substr(open + 1, close - open - 1);
    const auto& run = run_placeholders();
    if (!is_file_placeholder(name) && std::find(run.begin(), run.end(), name) == run.end())
      return "{" + name + "}";
  }
  return "";
}

std::vector<fs::path>& files_read() {
  static std::vector<fs::path> files;
  return files;
}

bool mentions(const std::vector<std::string>& command, const std::string& placeholder) {
  return std::any_of(command.begin(), command.end(), [&](const std::string& a) {
    return a.find("{" + placeholder + "}") != std::string::npos;
  });
}

}  // namespace

std::string on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::error_code ec;
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && fs::is_regular_file(fs::path(d) / name, ec) &&
        access((fs::path(d) / name).c_str(), X_OK) == 0)  // as the shell's search
      return (fs::path(d) / name).string();
  return "";
}

namespace {

/// Expands {here} and {beamimpact}; checks placeholders; resolves and checks the program.
std::vector<std::string> read_command(TableReader& r, const std::string& key, const fs::path& here,
                                      const fs::path& program, bool required) {
  std::vector<std::string> c = r.strings(key, required);
  if (required && c.empty()) r.fail(key, "expected a non-empty argument list (program first)");
  const std::map<std::string, std::string> files = {{"here", here.string()},
                                                    {"beamimpact", program.string()}};
  for (std::string& a : c) {
    if (const std::string u = unknown_placeholder(a); !u.empty())
      r.fail(key, "unknown placeholder " + u + " in '" + a +
                      "'; expected {scene} {out} {dt} {mesh} {end} {here} {beamimpact}");
    for (const auto& [name, value] : files) {
      for (std::size_t p = a.find("{" + name + "}"); p != std::string::npos; p = a.find("{" + name + "}"))
        a.replace(p, name.size() + 2, value);
    }
  }
  if (c.empty()) return c;
  std::error_code ec;
  if (!required) {  // check: a bare name is looked up in PATH as command's; one not found fails the check
    if (c[0].find('/') == std::string::npos)
      if (const std::string found = on_path(c[0]); !found.empty()) c[0] = found;
    return c;
  }
  if (c[0].find('/') == std::string::npos) {
    const std::string found = on_path(c[0]);
    if (found.empty()) r.fail(key, "the program '" + c[0] + "' is not on PATH; expected an existing program");
    c[0] = found;
  } else if (!fs::exists(c[0], ec)) {
    r.fail(key, "the program " + c[0] + " does not exist; expected an existing program");
  }
  if (!fs::is_regular_file(c[0], ec) || access(c[0].c_str(), X_OK) != 0)
    r.fail(key, "the program " + c[0] + " is not an executable file; expected a program this user may run");
  for (std::size_t i = 1; i < c.size(); ++i)  // a script named from the methods file's folder
    if (c[i].rfind(here.string() + "/", 0) == 0 && !fs::exists(c[i], ec))
      r.fail(key, "argument " + std::to_string(i) + ": " + c[i] + " does not exist");
  return c;
}

Method::Accepts read_accepts(TableReader& top) {
  Method::Accepts a;
  // Every key left out is false.
  const std::vector<AcceptsKey>& keys = accepts_keys();
  for (const auto& [key, field] : keys) a.*field = false;
  const toml::node* n = top.raw("accepts");
  if (!n) return a;
  if (!n->as_table()) top.fail("accepts", "expected a table { dt = true, friction = false, ... }");
  TableReader r(*n->as_table(), top.file(), top.path("accepts"), nullptr);
  for (const auto& [key, field] : keys) a.*field = r.boolean_or(key, false);
  // Friction anywhere includes friction between rigid bodies, unless the file says otherwise.
  a.rigid_friction = r.boolean_or("rigid_friction", a.friction);
  r.finish();
  return a;
}

Method read_method(TableReader& r, const fs::path& here, const fs::path& program) {
  Method m;
  m.name = r.string("name", "a method name (letters, digits, '_' and '-')");
  if (m.name.empty() || !std::all_of(m.name.begin(), m.name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
      }))
    r.fail("name", "expected letters, digits, '_' and '-', got '" + m.name + "'");
  m.summary = r.has("summary") ? r.string("summary", "a one-line description") : "";
  m.origin = r.file();
  m.options_table = m.name;
  m.command = read_command(r, "command", here, program, true);
  m.check = read_command(r, "check", here, program, false);
  m.check_timeout = r.number_or("check_timeout", m.check_timeout, "seconds, > 0 and at most 3600");
  if (!(m.check_timeout > 0.0 && m.check_timeout <= 3600.0))
    r.fail("check_timeout", "expected seconds, > 0 and at most 3600");
  m.accepts = read_accepts(r);
  m.slow = r.boolean_or("slow", false);
  r.finish();
  for (const char* p : {"scene", "out"})
    if (!mentions(m.command, p))
      r.fail("command", std::string("expected the placeholder {") + p + "} in the argument list");
  if (m.accepts.dt && !mentions(m.command, "dt"))
    r.fail("accepts.dt", "true, but the command has no {dt}: the step asked for would be ignored");
  if (m.accepts.mesh_factor && !mentions(m.command, "mesh"))
    r.fail("accepts.mesh_factor", "true, but the command has no {mesh}: the mesh asked for would be ignored");
  return m;
}

}  // namespace

const std::vector<std::string>& run_placeholders() {
  static const std::vector<std::string> p = {"scene", "out", "dt", "mesh", "end"};
  return p;
}

bool expand_placeholders(std::string& arg, const std::map<std::string, std::string>& values) {
  std::string out = arg;
  for (const auto& [name, value] : values) {
    const std::string token = "{" + name + "}";
    for (std::size_t p = out.find(token); p != std::string::npos; p = out.find(token, p + value.size())) {
      if (value.empty()) return false;
      out.replace(p, token.size(), value);
    }
  }
  arg = out;
  return true;
}

std::vector<Method> read_methods_file(const fs::path& file, const fs::path& program) {
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << e.description() << " (line " << e.source().begin.line << ")";
    std::error_code ec;
    throw InputError(file.string(), "",
                     fs::exists(file, ec) ? "expected valid TOML: " + os.str() : "methods file not found");
  }
  TableReader top(root, file.string(), "", nullptr);
  // [[method]], or [[methods]] as docs/scene-format.md spells it
  const std::string table = root.contains("methods") && !root.contains("method") ? "methods" : "method";
  const toml::node* n = top.raw(table);
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->empty()) top.fail(table, "expected at least one [[method]] table");
  top.finish();
  const fs::path here = fs::absolute(file).parent_path().lexically_normal();
  std::vector<Method> out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string key = table + "[" + std::to_string(i) + "]";
    if (!a->get(i)->as_table()) top.fail(key, "expected a [[method]] table");
    TableReader r(*a->get(i)->as_table(), file.string(), key, nullptr);
    out.push_back(read_method(r, here, program));
    if (!names.insert(out.back().name).second)
      r.fail("name", "'" + out.back().name + "' is declared twice in this file");
  }
  return out;
}

void load_methods_file(const fs::path& file) {
  std::vector<fs::path>& seen = files_read();
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) return;
  std::vector<Method> read = read_methods_file(file, program_path());
  for (std::size_t i = 0; i < read.size(); ++i)
    add_method(std::move(read[i]), file.string(), "method[" + std::to_string(i) + "].name");
  seen.push_back(canonical);
}

const std::vector<fs::path>& loaded_methods_files() { return files_read(); }

std::vector<fs::path> default_methods_files() {
  std::vector<fs::path> out;
  if (const char* env = std::getenv("BEAMIMPACT_METHODS")) {
    std::stringstream list(env);
    for (std::string f; std::getline(list, f, ':');)
      if (!f.empty()) out.emplace_back(f);
  }
  if (const fs::path root = data_root(); !root.empty()) out.push_back(root / "verification/methods.toml");
  return out;
}

fs::path data_root() {
  std::error_code ec;
  // The repository (a build tree lies inside it) or the installed share/beamimpact, from the
  // program upwards, from the file holding this code (the Python module) upwards, else from the
  // working directory upwards.
  Dl_info here{};
  const fs::path code = dladdr(reinterpret_cast<void*>(&data_root), &here) && here.dli_fname
                            ? fs::absolute(here.dli_fname, ec).parent_path()
                            : fs::path();
  for (const fs::path& start : {program_path().parent_path(), code, fs::current_path(ec)}) {
    for (fs::path d = start; !d.empty(); d = d.parent_path()) {
      for (const fs::path& root : {d, d / "share/beamimpact"})
        if (fs::is_regular_file(root / "verification/methods.toml", ec)) return root;
      if (d == d.parent_path()) break;
    }
  }
  return {};
}

fs::path program_path() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && self.filename() == "beamimpact") return self;
  // Another host (the Python module, a test): the program found from the file holding this code
  // upwards, bin/beamimpact of an installed prefix or virtual environment, beamimpact of a build tree.
  Dl_info here{};
  std::error_code up;
  if (dladdr(reinterpret_cast<void*>(&program_path), &here) && here.dli_fname)
    for (fs::path d = fs::absolute(here.dli_fname, up).parent_path(); !d.empty(); d = d.parent_path()) {
      for (const fs::path& p : {d / "bin/beamimpact", d / "beamimpact"})
        if (fs::is_regular_file(p, up) && access(p.c_str(), X_OK) == 0) return p;
      if (d == d.parent_path()) break;
    }
  return ec ? fs::path("beamimpact") : self;
}

}  // namespace beamimpact
