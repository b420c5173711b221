/// @file module.cc
/// @brief The compiled part of the Python package `beamimpact` (beamimpact._core): scene loading,
/// runs through the method registry, reading run directories and the compare command's norms,
/// each a thin call into the C++ library. The package's __init__.py builds the Python API on it.

#include <fstream>
#include <sstream>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <api/methods_file.hpp>
#include <api/registry.hpp>
#include <api/run.hpp>
#include <api/shipped_scenes.hpp>
#include <beamimpact/version.hpp>
#include <solver/record/ContactStats.hpp>
#include <solver/record/output_files.hpp>
#include <solver/scene/Override.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/Progress.hpp>
#include <verification/compare/compare_runs.hpp>
#include <verification/matrix/conform.hpp>
#include <verification/matrix/score.hpp>
#include <verification/matrix/sweep.hpp>
#include <verification/matrix/verify.hpp>
#include <verification/study/run_study.hpp>

#include "dict_to_toml.hpp"

namespace py = pybind11;

namespace beamimpact::python {
namespace {

using verification::StoredRun;

/// Columns as a dict of 1-D float64 arrays, in the order of `names`.
py::dict columns_dict(const std::vector<std::string>& names,
                      const std::map<std::string, std::vector<double>>& columns) {
  py::dict d;
  for (const std::string& n : names)
    if (auto it = columns.find(n); it != columns.end())
      d[py::str(n)] = py::array_t<double>(static_cast<py::ssize_t>(it->second.size()), it->second.data());
  return d;
}

/// A JSON value as the Python value json.loads would make of its text (dict, list, str, int,
/// float, bool, None), without the text.
py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& [k, v] : j.items()) d[py::str(k)] = to_python(v);
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& v : j) l.append(to_python(v));
      return l;
    }
    case nlohmann::json::value_t::string: return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    default: return py::none();
  }
}

/// A Python value of the kinds to_python makes (numpy scalars too) as JSON, without the text.
nlohmann::json from_python(py::handle o) {
  if (o.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(o)) return o.cast<bool>();
  if (py::isinstance<py::str>(o)) return o.cast<std::string>();
  if (py::isinstance<py::dict>(o)) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, v] : o.cast<py::dict>()) j[py::str(k).cast<std::string>()] = from_python(v);
    return j;
  }
  if (py::isinstance<py::list>(o) || py::isinstance<py::tuple>(o)) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& v : o) j.push_back(from_python(v));
    return j;
  }
  if (py::isinstance<py::int_>(o)) return o.cast<std::int64_t>();
  if (py::isinstance<py::float_>(o)) return o.cast<double>();
  if (py::hasattr(o, "__index__")) return o.attr("__index__")().cast<std::int64_t>();  // numpy integers
  return o.cast<double>();                                                             // numpy floats
}

/// Runs a loaded scene with the GIL released (on `threads` threads when given, as RunOptions::threads);
/// returns (summary dict, column names, rows x columns array).
py::tuple run_scene(const Scene& scene, const std::string& method, std::optional<std::filesystem::path> out,
                    std::optional<py::function> progress, std::optional<int> threads) {
  std::optional<Progress::Silence> quiet;  // no callback: no progress; the setting comes back after
  if (progress)
    Progress::set_listener([progress](const std::string& label, double value, double total) {
      py::gil_scoped_acquire gil;
      (*progress)(label, value, total);
    });
  else
    quiet.emplace();
  struct Restore {  // the listener holds a Python object: dropped (with the GIL held) on every path
    ~Restore() { Progress::set_listener({}); }
  } restore;
  SimulationResult r;
  {
    py::gil_scoped_release nogil;
    RunOptions options;
    options.out = out;
    options.threads = threads;
    r = beamimpact::run(scene, method, options);
  }
  const auto names = history_columns(static_cast<int>(scene.contacts.size()));
  py::array_t<double> rows(
      {static_cast<py::ssize_t>(r.history.size()), static_cast<py::ssize_t>(names.size())});
  auto w = rows.mutable_unchecked<2>();
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    const std::vector<double> v = history_values(r.history[i]);
    for (std::size_t c = 0; c < v.size(); ++c)
      w(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(c)) = v[c];
  }
  return py::make_tuple(to_python(summary_json(scene, r)), names, rows);
}

/// A StoredRun from a Python run: its columns (dict of arrays) and summary (dict).
StoredRun stored(const std::map<std::string, std::vector<double>>& columns, const py::dict& summary,
                 const std::string& label) {
  return StoredRun::from_columns(columns, from_python(summary), label);
}

/// Reads a run directory: (summary dict, dict of columns).
py::tuple read_run(const std::filesystem::path& dir) {
  const StoredRun r = StoredRun::read(dir);
  return py::make_tuple(to_python(r.summary()), columns_dict(history_columns(r.contacts()), r.columns()));
}

/// The compare command's norms of run a against reference b (columns, summary dict, label each).
py::object compare(const std::map<std::string, std::vector<double>>& a, const py::dict& summary_a,
                   const std::string& label_a, const std::map<std::string, std::vector<double>>& b,
                   const py::dict& summary_b, const std::string& label_b, double grid_step, double window,
                   double merge_gap, double threshold) {
  verification::CompareOptions o;
  o.grid_step = grid_step;
  o.window = window;
  o.merge_gap = merge_gap;
  o.threshold = threshold;
  const StoredRun run = stored(a, summary_a, label_a), reference = stored(b, summary_b, label_b);
  return to_python(verification::compare_runs(run.view(), reference.view(), o).to_json());
}

/// The verify command (verification::verify) with the GIL released; writes the reports, returns
/// norms.json's dict.
py::object verify(const std::filesystem::path& matrix, const std::filesystem::path& out,
                  const std::string& tier, const std::string& only, int jobs,
                  const std::filesystem::path& exe, bool fresh) {
  // exe "": every run in this process; a program: each run a process of it (isolation).
  verification::VerifyOptions o;
  o.matrix = matrix;
  o.out = out;
  o.tier = tier;
  o.only = only;
  o.jobs = jobs;
  o.fresh = fresh;
  o.exe = exe;
  std::optional<verification::VerifyResult> r;
  {
    py::gil_scoped_release release;
    r = verification::verify(o);
  }
  verification::write_verify_reports(o, *r);
  return to_python(verification::norms_json(r->context, r->items));
}

/// The score command (verification::score) with the GIL released; writes each scorecard.json and
/// returns the verdict, the exit code, the command, the cache, the files written and each method's
/// scorecard (scorecard.json's dict, with its ratchet against the baseline when one was given).
py::dict score(const verification::ScoreOptions& o) {
  verification::ScoreResult r;
  std::vector<std::filesystem::path> written;
  {
    py::gil_scoped_release release;
    r = *verification::score(o);  // one rank in this process: always a result
    written = verification::write_score_reports(o, r);
  }
  py::dict cards;
  for (const verification::MethodScore& m : r.methods) {
    nlohmann::json j = verification::scorecard_json(verification::score_context(o, r, m), m.rows, m.verdict);
    j["ratchet"] = m.ratchet ? nlohmann::json{{"grown", m.ratchet->grown}, {"improved", m.ratchet->improved}}
                             : nlohmann::json();
    cards[py::str(m.method)] = to_python(j);
  }
  py::dict d;
  d["passed"] = r.passed();
  d["exit_code"] = r.exit_code();
  d["command"] = r.command;
  d["cache"] = r.cache;
  d["paths"] = written;
  d["scorecards"] = cards;
  return d;
}

/// The conform command (verification::conform) with the GIL released; writes junit.xml and
/// conform.json and returns conform.json's dict with "passed" and the files written ("paths").
py::object conform(const verification::ConformOptions& o) {
  verification::ConformResult r;
  std::vector<std::filesystem::path> written;
  {
    py::gil_scoped_release release;
    r = verification::conform(o);
    written = verification::write_conform_reports(o, r);
  }
  nlohmann::json j = verification::conform_json(o, r);
  j["passed"] = r.passed();
  py::dict d = to_python(j);
  d["paths"] = written;
  return d;
}

/// One sweep point as Python's sweep() returns it: the step asked for (dt, s; or the fraction and
/// the step used, s), the mesh when the sweep has meshes, steps, the method's wall time (s), the
/// sweep command's norms the comparison has, and the outcome's status and message when the run did
/// not finish.
py::dict sweep_row(const verification::SweepOptions& o, const verification::SweepPoint& p,
                   std::size_t index) {
  const std::size_t meshes = o.meshes.empty() ? 1 : o.meshes.size();  // points: steps x meshes
  const jobs::JobOutcome& out = p.outcome;
  py::dict row;
  if (o.fractions.empty()) {
    row["dt"] = o.dts.at(index / meshes);
  } else {
    row["fraction"] = o.fractions.at(index / meshes);
    row["dt"] = out.dt > 0.0 ? py::object(py::float_(out.dt)) : py::object(py::none());
  }
  if (!o.meshes.empty()) row["mesh"] = o.meshes[index % meshes];
  row["steps"] = out.steps;
  row["wall_seconds"] = out.solver_seconds;
  if (p.comparison)
    for (const std::string& n : verification::sweep_norms())
      if (const verification::Norm* x = p.comparison->find(n))
        row[py::str(n)] = x->value ? py::object(py::float_(*x->value)) : py::object(py::none());
  if (out.status != jobs::JobOutcome::Status::kOk) {
    row["status"] = jobs::to_string(out.status);
    row["message"] = out.message;
  }
  return row;
}

/// The sweep command (verification::sweep) with the GIL released; writes sweep.md, sweep.csv and
/// sweep.json to o.out and returns one dict per point (sweep_row), in the order dts x meshes.
py::list sweep(const verification::SweepOptions& o) {
  verification::SweepResult r;
  {
    py::gil_scoped_release release;
    r = *verification::sweep(o);  // one rank in this process: always a result
    verification::write_sweep(o, r);
  }
  py::list rows;
  for (std::size_t i = 0; i < r.points.size(); ++i) rows.append(sweep_row(o, r.points[i], i));
  return rows;
}

/// The TOML text of a Python scene: its file's tables (or the dict's) with its overrides put in as
/// the scene loader puts them (a step in seconds drops the fraction of dt = "auto"), for the
/// commands that read a scene file.
std::string scene_toml_of(const py::object& source, bool is_dict, const py::list& overrides) {
  const std::string label = is_dict ? "<dict>" : py::str(source).cast<std::string>();
  toml::table root;
  if (is_dict) {
    root = table_from_dict(source.cast<py::dict>(), label);
  } else {
    std::ifstream in(label, std::ios::binary);
    if (!in) throw InputError(label, "", "cannot open the scene file");
    std::stringstream text;
    text << in.rdbuf();
    try {
      root = toml::parse(text.str(), label);
    } catch (const toml::parse_error& e) {  // changed since the Scene was loaded
      throw InputError(label, "", std::string("TOML syntax error: ") + std::string(e.description()));
    }
  }
  bool step = false, fraction = false;
  for (const Override& o : overrides_from_python(overrides, label)) {
    apply_override(root, label, o);
    step = step || o.key == "time.dt";
    fraction = fraction || o.key == "time.fraction";
  }
  if (toml::table* time = root["time"].as_table(); step && !fraction && time && (*time)["dt"].is_number())
    time->erase("fraction");
  std::ostringstream os;
  os << root << "\n";
  return os.str();
}

/// The study command (study::run_study) with the GIL released; writes its tables to o.out and
/// returns study.json's dict.
py::object run_study(const study::StudyOptions& o) {
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    const std::optional<study::StudyResult> r = study::run_study(o);  // one rank: always a result
    study::write_study_reports(o, *r);
    j = study::study_json(*r, kVersion);
  }
  return to_python(j);
}

/// One contact's statistics from its samples by ContactStats (the rule of every C++ method).
py::dict contact_stats(const std::vector<double>& t, const std::vector<double>& R,
                       const std::vector<double>& tau, const std::vector<double>& dt,
                       const std::vector<std::string>& states, double merge_gap) {
  ContactStats stats(merge_gap, "");
  for (std::size_t i = 0; i < t.size(); ++i)
    stats.add(t.at(i), R.at(i), tau.at(i), dt.at(i),
              states.at(i) == "stick"  ? ContactState::kStick
              : states.at(i) == "slip" ? ContactState::kSlip
                                       : ContactState::kClosed);
  ContactSummary c;
  stats.fill(c);
  py::dict d;
  d["intervals"] = c.intervals;
  d["impulse_normal"] = c.impulse_normal;
  d["impulse_tangential"] = c.impulse_tangential;
  d["peak_R"] = c.peak_R;
  d["peak_R_excluding_closure"] = c.peak_R_excluding_closure;
  d["first_step_R"] = c.first_step_R;
  d["stick_steps"] = c.stick_steps;
  d["slip_steps"] = c.slip_steps;
  return d;
}

/// The score and conform commands (score(), conform()), their options, and methods files.
void add_protocol(py::module_& m) {
  py::class_<verification::ScoreOptions>(m, "ScoreOptions", "verification::ScoreOptions (score.hpp)")
      .def(py::init<>())
      .def_readwrite("methods", &verification::ScoreOptions::methods)
      .def_readwrite("out", &verification::ScoreOptions::out)
      .def_readwrite("cards", &verification::ScoreOptions::cards)
      .def_readwrite("cache", &verification::ScoreOptions::cache)
      .def_readwrite("baseline", &verification::ScoreOptions::baseline)
      .def_readwrite("jobs", &verification::ScoreOptions::jobs)
      .def_readwrite("timeout", &verification::ScoreOptions::timeout)
      .def_readwrite("exe", &verification::ScoreOptions::exe)
      .def_readwrite("sets", &verification::ScoreOptions::sets)
      .def_readwrite("scenes", &verification::ScoreOptions::scenes)
      .def_readwrite("references", &verification::ScoreOptions::references)
      .def_readwrite("ladder", &verification::ScoreOptions::ladder)
      .def_readwrite("rungs", &verification::ScoreOptions::rungs);
  m.def("score", &score, py::arg("options"),
        "The score command as a library call (runs in this process unless options.exe isolates them); "
        "writes each scorecard.json");
  py::class_<verification::ConformOptions>(m, "ConformOptions", "verification::ConformOptions (conform.hpp)")
      .def(py::init<>())
      .def_readwrite("method", &verification::ConformOptions::method)
      .def_readwrite("out", &verification::ConformOptions::out)
      .def_readwrite("timeout", &verification::ConformOptions::timeout)
      .def_readwrite("scenes", &verification::ConformOptions::scenes);
  m.def("conform", &conform, py::arg("options"),
        "The conform command as a library call; writes junit.xml and conform.json, returns its dict");
  m.def("load_methods_file", &load_methods_file, py::arg("file"),
        "Adds a methods file's external methods to the registry (as --methods FILE)");
}

/// The sweep and study commands (sweep(), run_study()) and their options.
void add_sweep_and_study(py::module_& m) {
  py::class_<verification::SweepOptions>(m, "SweepOptions", "verification::SweepOptions (sweep.hpp)")
      .def(py::init<>())
      .def_readwrite("scene", &verification::SweepOptions::scene)
      .def_readwrite("method", &verification::SweepOptions::method)
      .def_readwrite("dts", &verification::SweepOptions::dts)
      .def_readwrite("fractions", &verification::SweepOptions::fractions)
      .def_readwrite("meshes", &verification::SweepOptions::meshes)
      .def_readwrite("reference", &verification::SweepOptions::reference)
      .def_readwrite("out", &verification::SweepOptions::out)
      .def_readwrite("jobs", &verification::SweepOptions::jobs)
      .def_readwrite("timeout", &verification::SweepOptions::timeout)
      .def_readwrite("threads", &verification::SweepOptions::threads)
      .def_readwrite("exe", &verification::SweepOptions::exe);
  m.def("sweep", &sweep, py::arg("options"),
        "The sweep command as a library call; writes sweep.md, sweep.csv and sweep.json, returns one "
        "dict per point");
  py::class_<study::StudyOptions>(m, "StudyOptions", "study::StudyOptions (run_study.hpp)")
      .def(py::init<>())
      .def_readwrite("file", &study::StudyOptions::file)
      .def_readwrite("out", &study::StudyOptions::out)
      .def_readwrite("keep_runs", &study::StudyOptions::keep_runs)
      .def_readwrite("fresh", &study::StudyOptions::fresh);
  m.def("study", &run_study, py::arg("options"),
        "The study command as a library call; writes study.csv, study.json, study.md and timing.*, "
        "returns study.json's dict");
}

/// The scene class and the loaders: a file (with --set text or typed overrides) or a dict.
void add_scene(py::module_& m) {
  py::class_<Scene>(m, "_Scene")
      .def_readonly("name", &Scene::name)
      .def_readonly("file", &Scene::file)
      .def_readonly("sha256", &Scene::sha256)
      .def_readonly("description", &Scene::description)
      .def_readonly("assumed", &Scene::assumed)
      .def_readonly("overrides", &Scene::overrides)
      .def_property_readonly("bodies",
                             [](const Scene& s) {
                               std::vector<std::string> n;
                               for (const Body& b : s.bodies) n.push_back(b.name);
                               return n;
                             })
      .def_property_readonly("contacts", [](const Scene& s) { return s.contacts.size(); })
      .def_property_readonly("end_time", [](const Scene& s) { return s.time.end; });

  m.def("load_scene", &load_scene, py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
        "Loads and validates a scene file (raises InputError as the CLI reports it)");
  m.def(
      "load_scene_with",
      [](const std::string& path, const py::list& overrides) {
        return load_scene_with(path, overrides_from_python(overrides, path));
      },
      py::arg("path"), py::arg("overrides"),
      "Loads a scene file with overrides given as \"key=value\" text or (key, value, text) triples");
  m.def("scene_toml", &scene_toml_of, py::arg("source"), py::arg("is_dict"), py::arg("overrides"),
        "A scene (its file's path or its dict, with overrides as load_scene_with takes them) as TOML "
        "text: the file the commands that take a scene file read");
  m.def(
      "load_scene_dict",
      [](const py::dict& tables, const std::string& label, const py::list& overrides) {
        return load_scene_table(table_from_dict(tables, label), label,
                                overrides_from_python(overrides, label));
      },
      py::arg("tables"), py::arg("label"), py::arg("overrides") = py::list(),
      "Loads a scene given as a dict of the scene's tables (Scene.from_dict), without TOML text");
}

}  // namespace
}  // namespace beamimpact::python

PYBIND11_MODULE(_core, m) {
  using namespace beamimpact;
  using namespace beamimpact::python;
  m.doc() = "beamimpact's compiled core; use the package `beamimpact`, not this module";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  m.attr("__version__") = kVersion;

  add_scene(m);
  m.attr("max_threads") = thread_limit();  // the largest `threads` a run takes (the registry's)
  m.def("run", &run_scene, py::arg("scene"), py::arg("method"), py::arg("out") = py::none(),
        py::arg("progress") = py::none(), py::arg("threads") = py::none(),
        "Runs a scene with a registry method; returns (summary JSON, column names, rows array)");
  m.def("methods", [] {
    std::vector<std::string> names;
    for (const Method& me : methods()) names.push_back(me.name);
    return names;
  });
  m.def("data_root", &data_root,
        "The folder of the shipped data (verification/, references/): the repository or the installed "
        "share/beamimpact (empty when none is found)");
  m.def("program_path", &program_path, "The beamimpact program the module finds (its runs' program)");
  m.def(
      "resolve_scene", [](const std::string& arg) { return resolve_scene(arg); }, py::arg("arg"),
      "The file a scene argument names: a path, or a shipped scene's name (api/shipped_scenes.hpp)");
  m.def(
      "resolve_data_file", [](const std::string& arg) { return resolve_data_file(arg); }, py::arg("arg"),
      "A data file argument: as given when it exists, else under the data root");
  m.def(
      "shipped_scenes",
      [] {
        std::vector<std::pair<std::string, std::filesystem::path>> out;
        for (const ShippedScene& s : shipped_scenes()) out.emplace_back(s.name, s.file);
        return out;
      },
      "The shipped scenes as (name, file) pairs, sorted by file");
  m.def("read_run", &read_run, py::arg("dir"),
        "Reads a run directory; returns (summary dict, dict of columns)");
  m.def("compare", &compare,
        "The compare command's norms of run a against reference b, as the dict compare --json writes");
  m.def("sweep_norms", &verification::sweep_norms, "The norms the sweep command tabulates");
  m.def("verify", &verify, py::arg("matrix"), py::arg("out"), py::arg("tier"), py::arg("only"),
        py::arg("jobs"), py::arg("exe"), py::arg("fresh") = false,
        "The verify command as a library call (runs started with exe); writes its reports to out and "
        "returns norms.json's dict");
  add_protocol(m);
  add_sweep_and_study(m);
  m.attr("merge_steps") = kMergeSteps;  // the default merge gap's open steps (ContactIntervals.hpp)
  m.def("default_merge_gap", &default_merge_gap, py::arg("step"),
        "s, the default merge gap of samples step s apart (solver/record/ContactIntervals.hpp)");
  m.def("contact_stats", &contact_stats, py::arg("t"), py::arg("R"), py::arg("tau"), py::arg("dt"),
        py::arg("states"), py::arg("merge_gap"),
        "A contact's statistics from its samples (t, R, tau, dt; state names) by the C++ rule every "
        "method's summary uses (solver/record/ContactStats, ContactIntervals): for conformance tests");
}
