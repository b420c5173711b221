#include <verification/matrix/sweep.hpp>

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include <api/registry.hpp>
#include <beamimpact/version.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/write_file_atomic.hpp>
#include <verification/compare/compare_runs.hpp>
#include <verification/jobs/Table.hpp>
#include <verification/jobs/interruption.hpp>
#include <verification/matrix/evaluate.hpp>
#include <verification/matrix/reports.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

std::string cell(const Comparison* c, const std::string& name) {
  if (!c) return "";
  const Norm* n = c->find(name);
  return n && n->value ? fmt::format("{:.4g}", *n->value) : "n/a";
}

/// The steps asked for: either --dt or --fraction, positive, fractions at most 1.
void check_steps(const SweepOptions& o) {
  const bool by_fraction = !o.fractions.empty();
  const std::string key = by_fraction ? "--fraction" : "--dt";
  const auto& steps = by_fraction ? o.fractions : o.dts;
  if (steps.empty() || (!o.fractions.empty() && !o.dts.empty()))
    throw InputError(o.scene.string(), "--dt",
                     "expected either --dt LIST or --fraction LIST (for dt = \"auto\" scenes)");
  for (double v : steps)
    if (!(v > 0.0)) throw InputError(o.scene.string(), key, "expected positive values");
  for (double v : o.fractions)
    if (v > 1.0)
      throw InputError(o.scene.string(), key,
                       fmt::format("expected fractions of the critical step in (0, 1], got {:g}", v));
}

/// The command line that makes this sweep.
std::string command_of(const SweepOptions& o) {
  std::string steps, meshes;
  for (double d : o.fractions.empty() ? o.dts : o.fractions)
    steps += fmt::format("{}{:g}", steps.empty() ? "" : ",", d);
  for (const auto& m : o.meshes) meshes += (meshes.empty() ? "" : ",") + m;
  return fmt::format("beamimpact sweep {} --method {} {} {}{} --reference {} --out {} --jobs {}{}",
                     o.scene.string(), o.method, o.fractions.empty() ? "--dt" : "--fraction", steps,
                     meshes.empty() ? "" : " --mesh " + meshes, o.reference, o.out.string(), o.jobs,
                     o.threads > 0 ? fmt::format(" --threads {}", o.threads) : "");
}

/// A sweep whose every run was refused is bad input; an interrupted one says so.
void finish(const SweepOptions& o, SweepResult& r) {
  if (std::all_of(r.points.begin(), r.points.end(), [](const SweepPoint& p) {
        return p.outcome.status == jobs::JobOutcome::Status::kNotApplicable;
      }))
    throw InputError(o.scene.string(), "",
                     "every run of the sweep was refused: " + r.points.front().outcome.message);
  if (jobs::interruption()) r.incomplete = fmt::format("interrupted by signal {}", jobs::interruption());
}

}  // namespace

const std::vector<std::string>& sweep_norms() {
  static const std::vector<std::string> n = {
      "impulse", "I.rel_linf", "R.rel_l2",  "Rw.rel_l2", "peak_R",         "contact_start", "contact_end",
      "impacts", "ua.rel_l2",  "ub.rel_l2", "vb.rel_l2", "final_velocity", "energy_final"};
  return n;
}

SweepPlan plan_sweep(const SweepOptions& o) {
  check_steps(o);
  const bool by_fraction = !o.fractions.empty();
  const auto& steps = by_fraction ? o.fractions : o.dts;
  std::error_code unreadable;  // a path the file system refuses (too long) is not found either
  if (!fs::exists(o.scene, unreadable)) throw InputError(o.scene.string(), "", "scene file not found");
  const Method& method = beamimpact::method(o.method, o.scene.string(), "--method");
  const std::vector<std::string> meshes = o.meshes.empty() ? std::vector<std::string>{""} : o.meshes;

  std::vector<jobs::JobSpec> specs;
  for (double v : steps)
    for (const auto& m : meshes) {
      jobs::JobSpec s{o.scene, o.method, std::nullopt, m, {}};
      if (by_fraction)  // a method that picks its own step refuses both: not applicable
        s.set.push_back(fmt::format("time.fraction={:g}", v));
      else
        s.dt = v;
      specs.push_back(s);
    }

  SweepPlan plan;
  plan.points = specs;
  SweepResult& r = plan.head;
  r.command = command_of(o);
  r.made = utc_now();
  std::optional<jobs::JobSpec>& ref = plan.reference;
  if (o.reference == "self") {
    const double finest = *std::min_element(steps.begin(), steps.end()) / 4;
    ref = jobs::JobSpec{o.scene, o.method, std::nullopt, meshes.back(), {}};
    if (by_fraction)
      ref->set.push_back(fmt::format("time.fraction={:g}", finest));
    else
      ref->dt = finest;
    if (!method.accepts.dt)
      throw InputError(o.scene.string(), "--reference",
                       "give a reference method or directory for " + o.method);
    r.reference_label = ref->settings_label() + " (the finest step / 4 on the finest mesh)";
  } else if (fs::exists(fs::path(o.reference) / "summary.json", unreadable)) {
    r.reference_dir = o.reference;
    r.reference_label = "run directory " + o.reference;
  } else {
    ref = jobs::JobSpec{o.scene, o.reference, std::nullopt, "", {}};
    r.reference_label = o.reference + " (scene defaults)";
  }
  return plan;
}

SweepResult judge_sweep(const SweepOptions& o, const SweepPlan& plan,
                        const std::map<std::string, jobs::JobOutcome>& outcomes) {
  SweepResult r = plan.head;
  const std::optional<jobs::JobSpec>& ref = plan.reference;
  if (ref) {
    const jobs::JobOutcome& ro = outcomes.at(ref->key());
    if (ro.status == jobs::JobOutcome::Status::kNotApplicable)
      throw InputError(o.scene.string(), "--reference",
                       "the reference run " + ref->label() + " was refused: " + ro.message);
    if (ro.status != jobs::JobOutcome::Status::kOk)
      throw std::runtime_error("reference run " + ref->label() + " " + to_string(ro.status) + ": " +
                               ro.message);
    r.reference_dir = ro.dir;
  }
  const auto reference = ref ? jobs::stored_run(outcomes.at(ref->key()))
                             : std::make_shared<const StoredRun>(StoredRun::read(r.reference_dir));
  for (const auto& s : plan.points) {
    SweepPoint p{outcomes.at(s.key()), std::nullopt};
    if (p.outcome.status == jobs::JobOutcome::Status::kOk)
      p.comparison = compare_runs(jobs::stored_run(p.outcome)->view(), reference->view());
    r.points.push_back(std::move(p));
  }
  finish(o, r);
  return r;
}

std::optional<SweepResult> sweep(const SweepOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  remove_stale_outputs(o.out, {"sweep.csv", "sweep.json", "sweep.md"});  // before anything can refuse
  const SweepPlan plan = plan_sweep(o);
  std::vector<jobs::JobSpec> all = plan.points;
  if (plan.reference) all.push_back(*plan.reference);
  // Bad input (a mesh multiplier of 0, an unknown reference method, an --out that cannot be a
  // directory) is refused before any run.
  const jobs::Launcher launcher = jobs::launcher_for(o.exe, o.threads);
  for (const jobs::JobSpec& s : all) launcher.check(s);
  if (std::error_code ec; fs::create_directories(o.out / "runs", ec), ec)
    throw InputError(o.out.string(), "--out", "expected a directory that can be written: " + ec.message());
  const auto ran = jobs::execute_jobs(all, o.out / "runs", launcher, o.jobs, o.timeout);
  if (!ran) return std::nullopt;  // an MPI worker rank: rank 0 compares and writes the outputs
  SweepResult r = judge_sweep(o, plan, *ran);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

namespace {

/// The observed orders between consecutive dts on the same mesh (sweep.md's second table).
jobs::Table order_table(const SweepOptions& o, const SweepResult& r) {
  const auto& names = sweep_norms();
  std::vector<std::string> header{"dt pair", "mesh"};
  header.insert(header.end(), names.begin(), names.end());
  jobs::Table t(header);
  const std::size_t nm = o.meshes.empty() ? 1 : o.meshes.size();
  for (std::size_t i = 0; i + nm < r.points.size(); ++i) {
    const auto& a = r.points[i];
    const auto& b = r.points[i + nm];
    if (!a.comparison || !b.comparison || !(a.outcome.dt > 0.0) || !(b.outcome.dt > 0.0)) continue;
    std::vector<std::string> row{fmt::format("{:.6g} / {:.6g}", a.outcome.dt, b.outcome.dt),
                                 a.outcome.spec.mesh.empty() ? "scene" : a.outcome.spec.mesh};
    for (const auto& n : names) {
      const Norm* x = a.comparison->find(n);
      const Norm* y = b.comparison->find(n);
      const auto p = observed_order(x ? x->value : std::nullopt, y ? y->value : std::nullopt,
                                    a.outcome.dt / b.outcome.dt);
      row.push_back(p ? fmt::format("{:.2f}", *p) : "-");
    }
    t.add(row);
  }
  return t;
}

}  // namespace

void write_sweep(const SweepOptions& o, const SweepResult& r) {
  const std::string header =
      fmt::format("- command: `{}`\n- version: `{}`\n- made {} (UTC), wall time {:.1f} s\n{}", r.command,
                  kVersion, r.made, r.wall_seconds,
                  r.incomplete.empty() ? "" : fmt::format("- **INCOMPLETE: {}**\n", r.incomplete));
  fs::create_directories(o.out);
  const auto& names = sweep_norms();
  // CSV: one row per point, machine-readable; Markdown: the same points for reading.
  std::vector<std::string> csv_head{"dt", "mesh", "status", "steps", "solver_seconds", "process_seconds"};
  std::vector<std::string> md_head{"dt (s)", "mesh", "steps", "solver s", "process s"};
  csv_head.insert(csv_head.end(), names.begin(), names.end());
  md_head.insert(md_head.end(), names.begin(), names.end());
  jobs::Table csv(csv_head), md(md_head);
  nlohmann::json j{{"scene", o.scene.string()},
                   {"method", o.method},
                   {"reference", r.reference_label},
                   {"reference_dir", r.reference_dir.string()}};
  auto& pts = j["points"] = nlohmann::json::array();
  for (const auto& p : r.points) {
    const auto& s = p.outcome.spec;
    const std::string dt =
        p.outcome.dt > 0.0 ? fmt::format("{:.6g}", p.outcome.dt) : (s.dt ? fmt::format("{:g}", *s.dt) : "");
    const Comparison* c = p.comparison ? &*p.comparison : nullptr;
    std::vector<std::string> csv_row{dt,
                                     s.mesh,
                                     to_string(p.outcome.status),
                                     fmt::format("{}", p.outcome.steps),
                                     fmt::format("{:.6g}", p.outcome.solver_seconds),
                                     fmt::format("{:.6g}", p.outcome.process_seconds)};
    std::vector<std::string> md_row{dt, s.mesh.empty() ? "scene" : s.mesh, fmt::format("{}", p.outcome.steps),
                                    fmt::format("{:.4g}", p.outcome.solver_seconds),
                                    fmt::format("{:.4g}", p.outcome.process_seconds)};
    for (const auto& n : names) {
      csv_row.push_back(cell(c, n));
      // A run without a comparison says why once, in its first norm's cell: "not applicable: reason".
      md_row.push_back(c               ? cell(c, n)
                       : n == names[0] ? fmt::format("{}: {}", to_string(p.outcome.status), p.outcome.message)
                                       : "-");
    }
    csv.add(csv_row);
    md.add(md_row);
    nlohmann::json e{{"dt", dt},
                     {"mesh", s.mesh},
                     {"status", to_string(p.outcome.status)},
                     {"message", p.outcome.message},
                     {"steps", p.outcome.steps},
                     {"solver_seconds", p.outcome.solver_seconds},
                     {"process_seconds", p.outcome.process_seconds},
                     {"dir", p.outcome.dir.string()}};
    if (c) e["comparison"] = c->to_json();
    pts.push_back(e);
  }
  std::string text = "# Timestep sensitivity: " + o.scene.stem().string() + "\n\n" + header;
  text += "\nErrors against: " + r.reference_label +
          ". Solver s: the method's own wall time (summary.json); "
          "process s: including start-up and output.\n\n" +
          md.markdown();
  text +=
      "\nObserved order between consecutive dt on the same mesh, p = log(e_i/e_{i+1}) / "
      "log(dt_i/dt_{i+1}):\n\n" +
      order_table(o, r).markdown();
  for (const auto& p : r.points)
    if (p.comparison) {
      text += "\nDefinitions:\n\n";
      for (const auto& n : p.comparison->norms)
        if (std::find(names.begin(), names.end(), n.name) != names.end())
          text += "- `" + n.name + "`: " + n.definition + "\n";
      break;
    }
  write_file_atomic(o.out / "sweep.csv", csv.csv());
  write_file_atomic(o.out / "sweep.json", j.dump(1) + "\n");
  write_file_atomic(o.out / "sweep.md", text);
}

}  // namespace beamimpact::verification
