#include <verification/study/finished_points.hpp>

#include <cmath>

#include <fmt/format.h>

#include <solver/util/sha256.hpp>
#include <verification/jobs/finished_runs.hpp>

namespace beamimpact::study {
namespace {

namespace fs = std::filesystem;

fs::path record_file(const fs::path& out, std::size_t index) {
  return out / "points" / fmt::format("{}.json", index);
}

nlohmann::json point_input(const nlohmann::json& base, std::size_t index, const Point& p) {
  return {{"study", base}, {"index", index}, {"values", p.values}};
}

/// JSON has no NaN or infinity (they would come back as null): such a result is not recorded.
bool finite(const PointResult& r) {
  auto ok = [](double v) { return std::isfinite(v); };
  if (!ok(r.reference_seconds)) return false;
  for (const auto& c : r.cases) {
    if (!ok(c.dt) || !ok(c.seconds) || (c.energy_growth && !ok(*c.energy_growth))) return false;
    for (const auto& n : c.norms)
      if (n && !ok(*n)) return false;
  }
  return true;
}

}  // namespace

nlohmann::json study_input(const Study& s) {
  return {{"program", jobs::program_input()},
          {"study_sha256", file_sha256(s.file)},
          {"scene_sha256", file_sha256(s.scene)},
          {"keep_runs", s.keep_runs}};
}

void record_point(const fs::path& out, const nlohmann::json& base, std::size_t index, const Point& p,
                  const PointResult& r) {
  if (!finite(r)) return;  // it runs again on a restart
  fs::create_directories(out / "points");
  jobs::write_record(record_file(out, index), point_input(base, index, p),
                     {{"rank", r.rank}, {"point", r.to_json()}});
}

std::optional<PointResult> recorded_point(const fs::path& out, const nlohmann::json& base, std::size_t index,
                                          const Point& p) {
  const auto j = jobs::read_record(record_file(out, index), point_input(base, index, p));
  if (!j) return std::nullopt;
  try {
    PointResult r = PointResult::from_json(j->at("point"));
    r.rank = j->at("rank").get<int>();
    return r;
  } catch (const std::exception&) {  // not a record this version writes: run the point again
    return std::nullopt;
  }
}

void prepare_point_records(const fs::path& out, bool fresh) {
  const fs::path dir = out / "points";
  if (fresh) {
    fs::remove_all(dir);
    return;
  }
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".partial") fs::remove(e.path());
}

}  // namespace beamimpact::study
