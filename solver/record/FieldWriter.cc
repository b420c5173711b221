#include <solver/record/FieldWriter.hpp>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <mutex>
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

/// Appends the empty <DataArray> element of a binary array of `n` tuples of `components` values
/// of type T to `xml` (its offset pointing into the appended data) and its block to `raw`: the
/// UInt64 byte count at `used` (+ `base` in the file), then room for the values in the machine's
/// little-endian order. `raw` grows when it must and is otherwise reused (a row of the last
/// row's layout writes over it without clearing it); `used` moves past the block. Returns where
/// in `raw` the values go.
template <typename T>
std::size_t reserve_block(std::string& xml, std::string& raw, std::size_t& used, std::size_t base,
                          const char* name, int n, int components) {
  static_assert(std::endian::native == std::endian::little, "the VTK files declare LittleEndian");
  fmt::format_to(std::back_inserter(xml),
                 "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
                 "offset=\"{}\"/>\n",
                 vtk_type<T>(), name, components, base + used);
  const std::uint64_t bytes = sizeof(T) * static_cast<std::uint64_t>(n) * components;
  const std::size_t at = used;
  used += sizeof bytes + bytes;
  if (raw.size() < used) raw.resize(used);
  std::memcpy(raw.data() + at, &bytes, sizeof bytes);
  return at + sizeof bytes;
}

/// Stores `count` values v as T at p (unaligned); false when one cannot be held (not finite, or
/// beyond T's range: the conversion would be undefined), which is then stored as 0.
template <typename T>
bool store(char* p, const double* v, int count) {
  constexpr double kMax = static_cast<double>(std::numeric_limits<T>::max());
  bool storable = true;
  for (int c = 0; c < count; ++c, p += sizeof(T)) {
    const bool ok = std::abs(v[c]) <= kMax;  // false for NaN too
    storable &= ok;
    const T x = ok ? static_cast<T>(v[c]) : T{};
    std::memcpy(p, &x, sizeof x);
  }
  return storable;
}

/// Stores the tuples [first, last) of a block of C-component values as T (tuple(i, v) gives
/// tuple i as doubles); false when one cannot be held (stored as 0).
template <typename T, int C, typename F>
bool fill(char* block, long long first, long long last, const F& tuple) {
  bool storable = true;
  double v[C];
  for (long long i = first; i < last; ++i) {
    tuple(static_cast<int>(i), v);
    storable &= store<T>(block + sizeof(T) * C * i, v, C);
  }
  return storable;
}

/// Throws unstorable for the first of the `n` tuples of `components` values (tuple(i, v)) that T
/// cannot hold: what a block that fill() could not store reports.
template <typename T, typename F>
void throw_first_unstorable(const char* name, int n, int components, const F& tuple) {
  double v[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < n; ++i) {
    tuple(i, v);
    for (int c = 0; c < components; ++c)
      if (!(std::abs(v[c]) <= static_cast<double>(std::numeric_limits<T>::max())))
        throw unstorable<T>(name, v[c]);
  }
}

/// Appends one <DataArray> of `n` tuples of `components` (1 or 3) values of type T; tuple(i, v)
/// writes tuple i's components into v[0..components) as doubles, each then rounded to T. ASCII:
/// the values inline in `xml`, in T's shortest round-trip form. Binary: reserve_block, then
/// fill(). A value T cannot hold throws (unstorable).
template <typename T, typename F>
void data_array(std::string& xml, std::string& raw, std::size_t& used, std::size_t base, FieldFormat format,
                const char* name, int n, int components, F tuple) {
  if (format == FieldFormat::kBinary) {
    const std::size_t at = reserve_block<T>(xml, raw, used, base, name, n, components);  // may move raw
    const bool storable =
        components == 3 ? fill<T, 3>(raw.data() + at, 0, n, tuple) : fill<T, 1>(raw.data() + at, 0, n, tuple);
    if (!storable) throw_first_unstorable<T>(name, n, components, tuple);
    return;
  }
  constexpr double kMax = static_cast<double>(std::numeric_limits<T>::max());
  auto out = std::back_inserter(xml);
  fmt::format_to(out, "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n",
                 vtk_type<T>(), name, components);
  double v[3];
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
    : model_(model), dir_(std::move(dir)), format_(format), precision_(precision) {
  std::filesystem::remove(collection(dir_));
  // An earlier run's files: moved aside at once, removed by the writer thread while the run goes
  // on (thousands of large files take seconds to delete).
  std::filesystem::remove_all(stale());  // left by a run that stopped before removing it
  if (std::filesystem::exists(dir_ / "fields")) std::filesystem::rename(dir_ / "fields", stale());
  std::filesystem::create_directories(dir_ / "fields");
  pvd_.open(part_of(collection(dir_)), std::ios::binary);
  if (!pvd_) throw std::runtime_error("cannot write " + part_of(collection(dir_)).string());
  pvd_ << "<?xml version=\"1.0\"?>\n"
          "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          "<Collection>\n";
  touch_start_.assign(static_cast<std::size_t>(model.num_nodes()) + 1, 0);
  for (const Model::Element& e : model.elements())
    if (!e.rigid) ++touch_start_[e.n1 + 1], ++touch_start_[e.n2 + 1];
  for (int i = 0; i < model.num_nodes(); ++i) touch_start_[i + 1] += touch_start_[i];
  touch_.resize(static_cast<std::size_t>(touch_start_.back()));
  std::vector<int> next(touch_start_.begin(), touch_start_.end() - 1);
  for (int k = 0; k < static_cast<int>(model.elements().size()); ++k)  // each node's in element order
    if (const Model::Element& e = model.elements()[k]; !e.rigid) {
      touch_[next[e.n1]++] = 2 * k;
      touch_[next[e.n2]++] = 2 * k + 1;
    }
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
  writer_ = std::thread([this] { write_files(); });
}

FieldWriter::~FieldWriter() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  if (writer_.joinable()) writer_.join();  // after the file in hand, if any
  if (pvd_.is_open()) {
    pvd_.close();
    std::error_code ec;
    std::filesystem::remove(part_of(collection(dir_)), ec);
  }
}

double FieldWriter::section_force(int i, const std::vector<std::array<double, 3>>& end_forces,
                                  bool moment) const {
  // Sagging positive (EI kappa, kappa = v'' in the element's left-normal axes): the bending moment
  // is -M1 at an element's first node and +M2 at its second.
  const int first = touch_start_[i], last = touch_start_[i + 1];
  double sum = 0.0;
  for (int k = first; k < last; ++k) {
    const auto [N, M1, M2] = end_forces[static_cast<std::size_t>(touch_[k] >> 1)];
    sum += !moment ? N : (touch_[k] & 1) ? M2 : -M1;
  }
  return last > first ? sum / (last - first) : 0.0;
}

template <typename F>
void FieldWriter::point_arrays(const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                               const std::vector<Vec2>& contact_force,
                               const std::vector<std::array<double, 3>>& end_forces, const F& f) const {
  using One = std::integral_constant<int, 1>;
  using Three = std::integral_constant<int, 3>;
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
  f("displacement", Three{}, vec(U));
  f("velocity", Three{}, vec(V));
  f("rotation", One{}, [&](int i, double* v) {
    const int eq = eq_[i][2];
    v[0] = eq >= 0 ? U(eq) : 0.0;
  });
  f("axial_force", One{}, [&](int i, double* v) { v[0] = section_force(i, end_forces, false); });
  f("bending_moment", One{}, [&](int i, double* v) { v[0] = section_force(i, end_forces, true); });
  f("contact_force", Three{}, [&](int i, double* v) {
    const Vec2& c = contact_force[static_cast<std::size_t>(i)];
    v[0] = c[0], v[1] = c[1], v[2] = 0.0;
  });
}

template <typename T>
void FieldWriter::write_point_data(const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                                   const std::vector<Vec2>& contact_force,
                                   const std::vector<std::array<double, 3>>& end_forces, ThreadTeam* team) {
  const int n = model_.num_nodes();
  auto arrays = [&](const auto& f) { point_arrays(U, V, contact_force, end_forces, f); };
  if (format_ == FieldFormat::kAscii) {
    arrays([&](const char* name, auto components, const auto& tuple) {
      data_array<T>(xml_, raw_, raw_used_, 0, format_, name, n, components, tuple);
    });
    return;
  }
  std::size_t at[kPointArrays];
  int k = 0;
  arrays([&](const char* name, auto components, const auto&) {
    at[k++] = reserve_block<T>(xml_, raw_, raw_used_, geometry_raw_.size(), name, n, components);
  });
  // The nodes in one range per thread: each writes its own tuples of every block.
  std::atomic<bool> storable{true};
  run_ranges(team, n, [&](long long first, long long last) {
    int a = 0;
    arrays([&](const char*, auto components, const auto& tuple) {
      if (!fill<T, decltype(components)::value>(raw_.data() + at[a++], first, last, tuple))
        storable.store(false, std::memory_order_relaxed);
    });
  });
  if (storable) return;
  arrays([&](const char* name, auto components, const auto& tuple) {  // the first culprit, for the message
    throw_first_unstorable<T>(name, n, components, tuple);
  });
}

void FieldWriter::write(double t, const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                        const std::vector<Vec2>& contact_force,
                        const std::vector<std::array<double, 3>>& end_forces, ThreadTeam* team) {
  if (end_forces.size() != model_.elements().size())
    throw std::logic_error("FieldWriter::write: one end-force triple per element expected");
  if (contact_force.size() != static_cast<std::size_t>(model_.num_nodes()))
    throw std::logic_error("FieldWriter::write: one contact force per node expected");
  wait_idle();  // the last row's file is out of the buffers (or its error is thrown)
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
  if (precision_ == FieldPrecision::kSingle)
    write_point_data<float>(U, V, contact_force, end_forces, team);
  else
    write_point_data<double>(U, V, contact_force, end_forces, team);
  xml_ += "</PointData>\n</Piece>\n</UnstructuredGrid>\n";
  if (binary) xml_ += "<AppendedData encoding=\"raw\">\n_";

  const std::string name = fmt::format("fields/step_{:06d}.vtu", count_++);
  pvd_ << fmt::format("<DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t, name);
  std::unique_lock<std::mutex> lock(mutex_);
  file_ = dir_ / name;
  lock.unlock();
  changed_.notify_one();
}

void FieldWriter::wait_idle() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return file_.empty(); });
  if (!error_.empty()) throw std::runtime_error(error_);
}

void FieldWriter::write_files() {
  std::error_code ignored;  // what cannot be removed stays hidden, and goes with the next run
  std::filesystem::remove_all(stale(), ignored);
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stop_ || !file_.empty(); });
    if (file_.empty()) return;  // stopped, nothing left
    const std::filesystem::path path = file_;
    lock.unlock();
    const bool written = write_file(path);
    lock.lock();
    if (!written && error_.empty()) error_ = "cannot write " + path.string();
    file_.clear();
    changed_.notify_all();
  }
}

bool FieldWriter::write_file(const std::filesystem::path& path) const {
  std::ofstream f(path, std::ios::binary);
  f.write(xml_.data(), static_cast<std::streamsize>(xml_.size()));
  if (format_ == FieldFormat::kBinary) {
    f.write(geometry_raw_.data(), static_cast<std::streamsize>(geometry_raw_.size()));
    f.write(raw_.data(), static_cast<std::streamsize>(raw_used_));
    f << "\n</AppendedData>\n";
  }
  f << "</VTKFile>\n";
  return static_cast<bool>(f);
}

void FieldWriter::finish() {
  wait_idle();
  pvd_ << "</Collection>\n</VTKFile>\n";
  pvd_.close();
  if (!pvd_) throw std::runtime_error("cannot write " + part_of(collection(dir_)).string());
  std::filesystem::rename(part_of(collection(dir_)), collection(dir_));
}

}  // namespace beamimpact
