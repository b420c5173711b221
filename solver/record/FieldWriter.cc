#include <solver/record/FieldWriter.hpp>

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace beamimpact {
namespace {

constexpr int kPolyLine = 4;  // VTK cell type VTK_POLY_LINE

std::filesystem::path part_of(const std::filesystem::path& p) { return p.string() + ".part"; }

/// Appends one <DataArray> of `n` tuples; value(i, c) gives component c of tuple i.
template <typename F>
void data_array(fmt::memory_buffer& b, const char* type, const char* name, int n, int components, F value) {
  fmt::format_to(std::back_inserter(b), "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n",
                 type, name, components);
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < components; ++c) {
      const double v = value(i, c);
      if (!std::isfinite(v))
        throw std::runtime_error(fmt::format("non-finite {} in the fields: the run diverged", name));
      fmt::format_to(std::back_inserter(b), "{}{}", c ? " " : "", v);
    }
    b.push_back('\n');
  }
  fmt::format_to(std::back_inserter(b), "</DataArray>\n");
}

}  // namespace

FieldWriter::FieldWriter(const Model& model, std::filesystem::path dir)
    : model_(model),
      dir_(std::move(dir)),
      touching_(model.num_nodes(), 0) {
  std::filesystem::remove(collection(dir_));
  std::filesystem::remove_all(dir_ / "fields");
  std::filesystem::create_directories(dir_ / "fields");
  pvd_.open(part_of(collection(dir_)), std::ios::binary);
  if (!pvd_) throw std::runtime_error("cannot write " + part_of(collection(dir_)).string());
  pvd_ << "<?xml version=\"1.0\"?>\n"
          "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          "<Collection>\n";
  for (const Model::Element& e : model.elements())
    if (!e.rigid) ++touching_[e.n1], ++touching_[e.n2];
  // The piece's points, cells and cell data: the same in every step's file, formatted once.
  const int n = model.num_nodes(), nb = model.num_bodies();
  fmt::memory_buffer b;
  auto out = std::back_inserter(b);
  fmt::format_to(out, "<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<Points>\n", n, nb);
  data_array(b, "Float64", "reference_position", n, 3,
             [&](int i, int c) { return c < 2 ? model.node_position(i)[c] : 0.0; });
  fmt::format_to(out, "</Points>\n<Cells>\n");
  data_array(b, "Int64", "connectivity", n, 1, [](int i, int) { return i; });
  data_array(b, "Int64", "offsets", nb, 1, [&](int body, int) { return body + 1 < nb ? model.node_id(body + 1, 0) : n; });
  data_array(b, "UInt8", "types", nb, 1, [](int, int) { return kPolyLine; });
  fmt::format_to(out, "</Cells>\n<CellData Scalars=\"body\">\n");
  data_array(b, "Int32", "body", nb, 1, [](int body, int) { return body; });
  fmt::format_to(out, "</CellData>\n<PointData Vectors=\"displacement\">\n");
  geometry_ = fmt::to_string(b);
}

FieldWriter::~FieldWriter() {
  if (pvd_.is_open()) {
    pvd_.close();
    std::error_code ec;
    std::filesystem::remove(part_of(collection(dir_)), ec);
  }
}

void FieldWriter::section_forces(const std::vector<std::array<double, 3>>& end_forces) {
  const int n = model_.num_nodes();
  axial_.assign(n, 0.0);
  moment_.assign(n, 0.0);
  for (std::size_t k = 0; k < model_.elements().size(); ++k) {
    const Model::Element& e = model_.elements()[k];
    if (e.rigid) continue;
    const auto [N, M1, M2] = end_forces[k];
    // Sagging positive (EI kappa, kappa = v'' in the element's left-normal axes): the bending
    // moment is -M1 at the first node and +M2 at the second.
    axial_[e.n1] += N / touching_[e.n1];
    axial_[e.n2] += N / touching_[e.n2];
    moment_[e.n1] += -M1 / touching_[e.n1];
    moment_[e.n2] += M2 / touching_[e.n2];
  }
}

void FieldWriter::write(double t, const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                        const std::vector<Vec2>& contact_force, const std::vector<std::array<double, 3>>& end_forces) {
  const int n = model_.num_nodes();
  if (end_forces.size() != model_.elements().size())
    throw std::logic_error("FieldWriter::write: one end-force triple per element expected");
  if (contact_force.size() != static_cast<std::size_t>(n))
    throw std::logic_error("FieldWriter::write: one contact force per node expected");
  section_forces(end_forces);

  fmt::memory_buffer b;
  auto out = std::back_inserter(b);
  fmt::format_to(out,
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                 "<UnstructuredGrid>\n<FieldData>\n"
                 "<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n"
                 "</FieldData>\n",
                 t);
  b.append(geometry_.data(), geometry_.data() + geometry_.size());
  auto vec = [&](const Eigen::VectorXd& X) {
    return [&](int i, int c) { return c < 2 ? model_.node_vector(X, i)[c] : 0.0; };
  };
  data_array(b, "Float64", "displacement", n, 3, vec(U));
  data_array(b, "Float64", "velocity", n, 3, vec(V));
  data_array(b, "Float64", "rotation", n, 1, [&](int i, int) {
    const int eq = model_.equation(i, 2);
    return eq >= 0 ? U(eq) : 0.0;
  });
  data_array(b, "Float64", "axial_force", n, 1, [&](int i, int) { return axial_[i]; });
  data_array(b, "Float64", "bending_moment", n, 1, [&](int i, int) { return moment_[i]; });
  data_array(b, "Float64", "contact_force", n, 3,
             [&](int i, int c) { return c < 2 ? contact_force[static_cast<std::size_t>(i)][c] : 0.0; });
  fmt::format_to(out, "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");

  const std::string name = fmt::format("fields/step_{:06d}.vtu", count_++);
  std::ofstream f(dir_ / name, std::ios::binary);
  f.write(b.data(), static_cast<std::streamsize>(b.size()));
  if (!f) throw std::runtime_error("cannot write " + (dir_ / name).string());
  pvd_ << fmt::format("<DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t, name);
}

void FieldWriter::finish() {
  pvd_ << "</Collection>\n</VTKFile>\n";
  pvd_.close();
  if (!pvd_) throw std::runtime_error("cannot write " + part_of(collection(dir_)).string());
  std::filesystem::rename(part_of(collection(dir_)), collection(dir_));
}

}  // namespace beamimpact
