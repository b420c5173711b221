// The field writer against closed-form section forces: a displacement field the elements
// represent exactly (uniform stretch; uniform curvature, a quadratic deflection that Hermite
// cubics reproduce) must give N = EA eps and M = EI kappa at every node, and the files must say
// what was written (node count, times, a .pvd only once the run is complete).
#include <solver/record/FieldWriter.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include <solver/integrator/InternalForce.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact {
namespace {

using testing::load_paper_scene;
using testing::temp_path;

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The numbers of the DataArray `name` of a .vtu text.
std::vector<double> array(const std::string& vtu, const std::string& name) {
  const auto tag = vtu.find("Name=\"" + name + "\"");
  EXPECT_NE(tag, std::string::npos) << name;
  const auto begin = vtu.find('>', tag) + 1, end = vtu.find("</DataArray>", begin);
  std::istringstream in(vtu.substr(begin, end - begin));
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

TEST(FieldWriter, SectionForcesOfExactlyRepresentedFields) {
  // S4's target B: 10 m from (0, 0) to (10, 0), pin at x = 0, roller at x = 10, E = 1.8e11,
  // A = 0.4, I = 0.4^3/12. Linear kinematics: the small-strain measures of the linear element.
  // Element lengths 1 m and 0.5 m: a moment off by a power of the element length shows.
  for (int elements : {10, 20}) {
    const Scene scene = load_paper_scene(
        "s4_oblique_45", {"model.kinematics=\"linear\"", "bodies.B.elements=" + std::to_string(elements)});
    const Model model(scene, true);
    const paper::InternalForce fint(model, std::vector<bool>(model.num_bodies(), false));
    const int b = scene.body_index("B");
    const double L = 10.0, eps = 1e-6, kappa = 2e-6;
    Eigen::VectorXd U = Eigen::VectorXd::Zero(model.size()), V = U;
    std::vector<Vec2> Fc(static_cast<std::size_t>(model.num_nodes()), Vec2{0.0, 0.0});
    for (int i = 0; i <= elements; ++i) {
      const int n = model.node_id(b, i);
      const double x = model.node_position(n)[0];
      const double values[3] = {eps * x, kappa * x * (x - L) / 2.0, kappa * (2.0 * x - L) / 2.0};
      for (int c = 0; c < 3; ++c)
        if (const int e = model.equation(n, c); e >= 0) U(e) = values[c];
    }
    Fc[static_cast<std::size_t>(model.node_id(b, 5))][1] = -3.0;
    std::vector<std::array<double, 3>> ends;
    fint.end_forces(U, ends);
    const auto dir = temp_path("fields" + std::to_string(elements));
    {
      // The values parsed as text below, in double: the 1e-9 tolerances are the double's.
      FieldWriter w(model, dir, FieldFormat::kAscii, FieldPrecision::kDouble);
      w.write(0.0, U, V, Fc, ends);
      w.finish();
    }
    const std::string vtu = read(dir / "fields/step_000000.vtu");
    const std::vector<double> N = array(vtu, "axial_force"), M = array(vtu, "bending_moment");
    ASSERT_EQ(N.size(), static_cast<std::size_t>(model.num_nodes()));  // 6 striker + target nodes
    EXPECT_EQ(N.size(), static_cast<std::size_t>(6 + elements + 1));
    const double EA = 1.8e11 * 0.4, EI = 1.8e11 * 0.0053333333333333;
    for (int i = 0; i <= elements; ++i) {
      const int n = model.node_id(b, i);
      // Exact up to the rounding of U (relative 1e-9: displacements of 1e-5 m summed and divided).
      EXPECT_NEAR(N[n], EA * eps, 1e-9 * EA * eps) << "node " << i;
      EXPECT_NEAR(M[n], EI * kappa, 1e-9 * EI * kappa) << "node " << i;  // sagging positive: v'' > 0
    }
    const std::vector<double> F = array(vtu, "contact_force");
    EXPECT_EQ(F[3 * model.node_id(b, 5) + 1], -3.0);
    EXPECT_NE(read(dir / "fields.pvd").find("timestep=\"0\""), std::string::npos);
  }
}

TEST(FieldWriter, AnUnfinishedRunLeavesNoCollection) {
  const Scene scene = load_paper_scene("s1_central");
  const Model model(scene, false);
  const auto dir = temp_path("unfinished");
  {
    FieldWriter w(model, dir);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
    w.write(0.0, zero, zero, std::vector<Vec2>(static_cast<std::size_t>(model.num_nodes())),
            std::vector<std::array<double, 3>>(model.elements().size()));
  }  // destroyed without finish(): the run threw
  EXPECT_FALSE(std::filesystem::exists(FieldWriter::collection(dir)));
  EXPECT_FALSE(std::filesystem::exists(dir / "fields.pvd.part"));
}

TEST(FieldWriter, AValueSinglePrecisionCannotHoldIsRefusedNotWrittenAsInfinity) {
  // A contact force of 1e39 N is finite in double but beyond float's 3.4e38: converting it would
  // be undefined behaviour (in practice inf in the file). Both encodings refuse it and name the
  // array and the key that keeps it; in double precision it is written. NaN is refused in both.
  const Scene scene = load_paper_scene("s1_central");
  const Model model(scene, false);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  const std::vector<std::array<double, 3>> ends(model.elements().size());
  for (const FieldFormat format : {FieldFormat::kBinary, FieldFormat::kAscii}) {
    std::vector<Vec2> Fc(static_cast<std::size_t>(model.num_nodes()), Vec2{0.0, 0.0});
    Fc[3][1] = 1e39;
    {
      FieldWriter w(model, temp_path("huge_single"), format);
      try {
        w.write(0.0, zero, zero, Fc, ends);
        ADD_FAILURE() << "expected a refusal";
      } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("contact_force"), std::string::npos) << what;
        EXPECT_NE(what.find("output.field_precision = \"double\""), std::string::npos) << what;
      }
    }
    FieldWriter d(model, temp_path("huge_double"), format, FieldPrecision::kDouble);
    EXPECT_NO_THROW(d.write(0.0, zero, zero, Fc, ends));
    Fc[3][1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(d.write(0.0, zero, zero, Fc, ends), std::runtime_error);
  }
}

TEST(FieldWriter, TheFilesDoNotDependOnTheThreads) {
  // The nodes (and the elements of the end forces) split in one range per thread: every value is
  // formed by one thread alone, so two threads must write the very bytes one writes. A 31-node
  // body and an uneven split (3 threads) put range boundaries inside a body.
  const Scene scene = load_paper_scene("s4_oblique_45", {"bodies.B.elements=25"});
  const Model model(scene, true);
  const paper::InternalForce fint(model, std::vector<bool>(model.num_bodies(), false));
  Eigen::VectorXd U(model.size()), V(model.size());
  for (int i = 0; i < model.size(); ++i) U(i) = 1e-4 * std::sin(0.7 * i), V(i) = 0.3 * std::cos(1.3 * i);
  std::vector<Vec2> Fc(static_cast<std::size_t>(model.num_nodes()), Vec2{0.0, 0.0});
  Fc[7] = {1.5, -2.5};
  std::string files[2];
  for (int k = 0; k < 2; ++k) {
    ThreadTeam team(3);
    ThreadTeam* threads = k == 0 ? nullptr : &team;
    std::vector<std::array<double, 3>> ends;
    fint.end_forces(U, ends, threads);
    const auto dir = temp_path("threads" + std::to_string(k));
    {
      FieldWriter w(model, dir);
      w.write(0.5, U, V, Fc, ends, threads);
      w.finish();
    }
    files[k] = read(dir / "fields/step_000000.vtu");
  }
  EXPECT_GT(files[0].size(), 1000u);
  EXPECT_TRUE(files[0] == files[1]) << "the file written on 3 threads differs from the one on 1";
}

TEST(FieldWriter, AnEarlierRunsFilesAreGoneWhenTheRunIsOver) {
  // Three rows, then a run of one row into the same directory: only its file remains, and the
  // earlier files' folder (moved aside, deleted on the writer's thread) is gone too.
  const Scene scene = load_paper_scene("s1_central");
  const Model model(scene, false);
  const auto dir = temp_path("rerun");
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  const std::vector<Vec2> Fc(static_cast<std::size_t>(model.num_nodes()));
  const std::vector<std::array<double, 3>> ends(model.elements().size());
  for (const int rows : {3, 1}) {
    FieldWriter w(model, dir);
    for (int r = 0; r < rows; ++r) w.write(r, zero, zero, Fc, ends);
    w.finish();
  }
  const auto files = std::distance(std::filesystem::directory_iterator(dir / "fields"),
                                   std::filesystem::directory_iterator{});
  EXPECT_EQ(files, 1);
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_TRUE(entry.path().filename() == "fields" || entry.path().filename() == "fields.pvd")
        << entry.path();
}

TEST(FieldWriter, AFileThatCannotBeWrittenFailsTheRun) {
  // The files are written on the writer's own thread: its failure must still reach the caller
  // (at the next row or at finish()), and no collection vouches for the missing file.
  const Scene scene = load_paper_scene("s1_central");
  const Model model(scene, false);
  const auto dir = temp_path("unwritable");
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.size());
  FieldWriter w(model, dir);
  std::filesystem::remove_all(dir / "fields");  // the file of the row has no folder to go to
  w.write(0.0, zero, zero, std::vector<Vec2>(static_cast<std::size_t>(model.num_nodes())),
          std::vector<std::array<double, 3>>(model.elements().size()));
  try {
    w.finish();
    ADD_FAILURE() << "expected the failed file to be reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write " + (dir / "fields/step_000000.vtu").string()),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(FieldWriter::collection(dir)));
}

}  // namespace
}  // namespace beamimpact
