#include <solver/record/FieldWriter.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

namespace beamimpact {
namespace {

constexpr int kPolyLine = 4;  // VTK cell type VTK_POLY_LINE

std::filesystem::path part_of(const std::filesystem::path& p) { return p.string() + ".part"; }

/// VTK's name of the element type T.
template <typename T>
constexpr const char* vtk_type() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  if constexpr (std::is_same_v<T, float>) return "Float32";
  if constexpr (std::is_same_v<T, std::int32_t>) return "Int32";
  if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
}

/// The error for a value of array `name` that T cannot hold: not finite (the run diverged), or
/// finite but beyond single precision's range.
template <typename T>
std::runtime_error unstorable(const char* name, double x) {
  if (!std::isfinite(x))
    return std::runtime_error(fmt::format("non-finite {} in the fields: the run diverged", name));
  return std::runtime_error(
      fmt::format("{} = {:g} in the fields is beyond single precision (|x| > {:g}); set "
                  "output.field_precision = \"double\"",
                  name, x, static_cast<double>(std::numeric_limits<T>::max())));
}

/// Appends one <DataArray> of `n` tuples of `components` (at most 3) values of type T;
/// tuple(i, v) writes tuple i's components into v[0..components) as doubles, each then rounded to
/// T. ASCII: the values inline in `xml`, in T's shortest round-trip form. Binary: an empty element
/// in `xml` whose offset points into the appended data, and the block (UInt64 byte count, then the
/// values in the machine's little-endian order) at `offset` = `used` + `base` in `raw`, written
/// in place (no per-value append; `raw` grows when it must and is otherwise reused, so a row of
/// the last row's layout writes over it without clearing it); `used` moves past the block. A
/// value T cannot hold (not finite, or beyond its range: the conversion would be undefined)
/// throws.
template <typename T, typename F>
void data_array(std::string& xml, std::string& raw, std::size_t& used, std::size_t base, FieldFormat format,
                const char* name, int n, int components, F tuple) {
  static_assert(std::endian::native == std::endian::little, "the VTK files declare LittleEndian");
  auto out = std::back_inserter(xml);
  const bool binary = format == FieldFormat::kBinary;
  fmt::format_to(out, "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"{}\"",
                 vtk_type<T>(), name, components, binary ? "appended" : "ascii");
  constexpr double kMax = static_cast<double>(std::numeric_limits<T>::max());
  double v[3];
  if (binary) {
    fmt::format_to(out, " offset=\"{}\"/>\n", base + used);
    const std::uint64_t bytes = sizeof(T) * static_cast<std::uint64_t>(n) * components;
    const std::size_t at = used;
    used += sizeof bytes + bytes;
    if (raw.size() < used) raw.resize(used);
    char* p = raw.data() + at;
    std::memcpy(p, &bytes, sizeof bytes);
    p += sizeof bytes;
    bool storable = true;
    for (int i = 0; i < n; ++i) {
      tuple(i, v);
      for (int c = 0; c < components; ++c, p += sizeof(T)) {
        storable &= std::abs(v[c]) <= kMax;  // false for NaN too
        const T x = storable ? static_cast<T>(v[c]) : T{};
        std::memcpy(p, &x, sizeof x);
      }
    }
    if (!storable)  // find the first culprit for the message (the run is over)
      for (int i = 0; i < n; ++i) {
        tuple(i, v);
        for (int c = 0; c < components; ++c)
          if (!(std::abs(v[c]) <= kMax)) throw unstorable<T>(name, v[c]);
      }
    return;
  }
  xml += ">\n";
  for (int i = 0; i < n; ++i) {
    tuple(i, v);
    for (int c = 0; c < components; ++c) {
      if (!(std::abs(v[c]) <= kMax)) throw unstorable<T>(name, v[c]);
      fmt::format_to(out, "{}{}", c ? " " : "", static_cast<T>(v[c]));
    }
    xml.push_back('\n');
  }
  xml += "</DataArray>\n";
}

/// data_array of real numbers, in the precision the run asked for.
template <typename F>
void real_array(std::string& xml, std::string& raw, std::size_t& used, std::size_t base, FieldFormat format,
                FieldPrecision precision, const char* name, int n, int components, F tuple) {
  if (precision == FieldPrecision::kSingle)
    data_array<float>(xml, raw, used, base, format, name, n, components, tuple);
  else
    data_array<double>(xml, raw, used, base, format, name, n, components, tuple);
}

}  // namespace

FieldWriter::FieldWriter(const Model& model, std::filesystem::path dir, FieldFormat format,
                         FieldPrecision precision)
    : model_(model),
      dir_(std::move(dir)),
      format_(format),
      precision_(precision),
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
  eq_.resize(static_cast<std::size_t>(model.num_nodes()));
  for (int i = 0; i < model.num_nodes(); ++i) {
    const bool direct =
        model.dofs_per_node() == 3 && !model.rigid(model.body_of_node(i)) && !model.rotated(i);
    eq_[i] = {direct ? model.equation(i, 0) : -2, model.equation(i, 1), model.equation(i, 2)};
  }
  // The piece's points, cells and cell data: the same in every step's file, formatted once.
  const int n = model.num_nodes(), nb = model.num_bodies();
  std::string& x = geometry_;
  std::string& raw = geometry_raw_;
  std::size_t used = 0;
  fmt::format_to(std::back_inserter(x), "<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n<Points>\n", n,
                 nb);
  real_array(x, raw, used, 0, format_, precision_, "reference_position", n, 3, [&](int i, double* v) {
    const Vec2& q = model.node_position(i);
    v[0] = q[0], v[1] = q[1], v[2] = 0.0;
  });
  x += "</Points>\n<Cells>\n";
  data_array<std::int32_t>(x, raw, used, 0, format_, "connectivity", n, 1,
                           [](int i, double* v) { v[0] = i; });
  data_array<std::int32_t>(x, raw, used, 0, format_, "offsets", nb, 1, [&](int body, double* v) {
    v[0] = body + 1 < nb ? model.node_id(body + 1, 0) : n;
  });
  data_array<std::uint8_t>(x, raw, used, 0, format_, "types", nb, 1,
                           [](int, double* v) { v[0] = kPolyLine; });
  x += "</Cells>\n<CellData Scalars=\"body\">\n";
  data_array<std::int32_t>(x, raw, used, 0, format_, "body", nb, 1, [](int body, double* v) { v[0] = body; });
  x += "</CellData>\n<PointData Vectors=\"displacement\">\n";
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

void FieldWriter::write_arrays(const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                               const std::vector<Vec2>& contact_force) {
  const int n = model_.num_nodes();
  const std::size_t base = geometry_raw_.size();
  auto vec = [&](const Eigen::VectorXd& X) {
    return [&](int i, double* v) {
      const std::array<int, 3>& e = eq_[i];
      if (e[0] == -2) {
        const Vec2 x = model_.node_vector(X, i);
        v[0] = x[0], v[1] = x[1];
      } else {  // what node_vector() gives such a node
        v[0] = e[0] >= 0 ? X(e[0]) : 0.0;
        v[1] = e[1] >= 0 ? X(e[1]) : 0.0;
      }
      v[2] = 0.0;
    };
  };
  real_array(xml_, raw_, raw_used_, base, format_, precision_, "displacement", n, 3, vec(U));
  real_array(xml_, raw_, raw_used_, base, format_, precision_, "velocity", n, 3, vec(V));
  real_array(xml_, raw_, raw_used_, base, format_, precision_, "rotation", n, 1, [&](int i, double* v) {
    const int eq = eq_[i][2];
    v[0] = eq >= 0 ? U(eq) : 0.0;
  });
  real_array(xml_, raw_, raw_used_, base, format_, precision_, "axial_force", n, 1,
             [&](int i, double* v) { v[0] = axial_[i]; });
  real_array(xml_, raw_, raw_used_, base, format_, precision_, "bending_moment", n, 1,
             [&](int i, double* v) { v[0] = moment_[i]; });
  real_array(xml_, raw_, raw_used_, base, format_, precision_, "contact_force", n, 3, [&](int i, double* v) {
    const Vec2& f = contact_force[static_cast<std::size_t>(i)];
    v[0] = f[0], v[1] = f[1], v[2] = 0.0;
  });
}

void FieldWriter::write(double t, const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                        const std::vector<Vec2>& contact_force,
                        const std::vector<std::array<double, 3>>& end_forces) {
  if (end_forces.size() != model_.elements().size())
    throw std::logic_error("FieldWriter::write: one end-force triple per element expected");
  if (contact_force.size() != static_cast<std::size_t>(model_.num_nodes()))
    throw std::logic_error("FieldWriter::write: one contact force per node expected");
  section_forces(end_forces);

  const bool binary = format_ == FieldFormat::kBinary;
  xml_.clear();
  raw_used_ = 0;
  fmt::format_to(
      std::back_inserter(xml_),
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\"{}>\n"
      "<UnstructuredGrid>\n<FieldData>\n"
      "<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n"
      "</FieldData>\n",
      binary ? " header_type=\"UInt64\"" : "", t);
  xml_ += geometry_;
  write_arrays(U, V, contact_force);
  xml_ += "</PointData>\n</Piece>\n</UnstructuredGrid>\n";
  if (binary) xml_ += "<AppendedData encoding=\"raw\">\n_";

  const std::string name = fmt::format("fields/step_{:06d}.vtu", count_++);
  std::ofstream f(dir_ / name, std::ios::binary);
  f.write(xml_.data(), static_cast<std::streamsize>(xml_.size()));
  if (binary) {
    f.write(geometry_raw_.data(), static_cast<std::streamsize>(geometry_raw_.size()));
    f.write(raw_.data(), static_cast<std::streamsize>(raw_used_));
    f << "\n</AppendedData>\n";
  }
  f << "</VTKFile>\n";
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
