#include <solver/integrator/InternalForce.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include <solver/model/timoshenko_element.hpp>

namespace beamimpact::paper {
namespace {

/// The element's end forces from its local deformation: axial stretch u (m) and end rotations
/// th1, th2 relative to the chord (rad): N = EA/L u, M1 = EI/L (4 th1 + 2 th2), M2 = EI/L (2 th1 + 4 th2)
/// (a Timoshenko element: timoshenko_end_moments).
std::array<double, 3> section(const Model::Element& el, double u, double th1, double th2) {
  const double N = el.E * el.area / el.length * u;
  if (el.timoshenko) {
    const auto [M1, M2] = timoshenko_end_moments(el.E, el.inertia, el.length, el.phi, th1, th2);
    return {N, M1, M2};
  }
  const double k = el.E * el.inertia / el.length;
  return {N, k * (4 * th1 + 2 * th2), k * (2 * th1 + 4 * th2)};
}

/// A vector with no special structure, the same on every machine, for the check of the blocks:
/// n entries in [0.5, 1.5) from a linear congruential sequence (seed 12345), every one non-zero.
Eigen::VectorXd spread_vector(int n) {
  Eigen::VectorXd q(n);
  unsigned s = 12345u;
  for (int i = 0; i < n; ++i) {
    s = s * 1103515245u + 12345u;
    q(i) = 0.5 + static_cast<double>((s >> 8) & 0xffff) / 65536.0;
  }
  return q;
}

/// kx = K x and scale = |K| x (x > 0: |x| is x) in one sweep over K, each entry summed in the
/// order of Eigen's column-major product.
void product_and_scale(const SparseMatrix& K, const Eigen::VectorXd& x, Eigen::VectorXd& kx,
                       Eigen::VectorXd& scale) {
  kx.setZero();
  scale.setZero();
  for (Eigen::Index j = 0; j < K.outerSize(); ++j) {
    const double xj = x(j);
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
      kx(it.index()) += it.value() * xj;
      scale(it.index()) += std::abs(it.value()) * xj;
    }
  }
}

/// The elastic elements of a model in model order (a rigid body's left out), each one's
/// equations read in place from the model.
class ElasticElements {
 public:
  explicit ElasticElements(const Model& model) : model_(model) {
    const auto& els = model.elements();
    all_ = std::none_of(els.begin(), els.end(), [](const Model::Element& el) { return el.rigid; });
    if (!all_)
      for (int m = 0; m < static_cast<int>(els.size()); ++m)
        if (model.element_group(m) >= 0) index_.push_back(m);
  }
  /// The number of elastic elements.
  int size() const {
    return all_ ? static_cast<int>(model_.elements().size()) : static_cast<int>(index_.size());
  }
  /// The model's index of elastic element e.
  int model_element(int e) const { return all_ ? e : index_[e]; }
  /// Elastic element e's w equations, in place.
  const int* equations(int e) const { return model_.element_dofs(model_element(e)).data(); }

 private:
  const Model& model_;
  bool all_ = true;
  std::vector<int> index_;  ///< the model element of each elastic element, when some are rigid
};

/// The first and the last elastic element (in model order) that touch each of the n equations,
/// -1 for none; w equations an element.
void touching_elements(const ElasticElements& elastic, int n, int w, std::vector<int>& first,
                       std::vector<int>& last) {
  first.assign(n, -1);
  last.assign(n, -1);
  for (int e = 0; e < elastic.size(); ++e) {
    const int* eq = elastic.equations(e);
    for (int i = 0; i < w; ++i)
      if (const int q = eq[i]; q >= 0) {
        if (first[q] < 0) first[q] = e;
        last[q] = e;
      }
  }
}

/// The equations no element touches (first[q] < 0), as ranges [lo, hi).
std::vector<std::array<int, 2>> untouched_ranges(const std::vector<int>& first) {
  std::vector<std::array<int, 2>> ranges;
  for (int q = 0; q < static_cast<int>(first.size()); ++q)
    if (first[q] < 0) {
      if (!ranges.empty() && ranges.back()[1] == q)
        ++ranges.back()[1];
      else
        ranges.push_back({q, q + 1});
    }
  return ranges;
}

}  // namespace

InternalForce::InternalForce(const Model& model, const std::vector<bool>& corotational, int parts)
    : model_(model), K_(&model.K()) {
  if (model.dofs_per_node() != 3) {  // rods never rotate
    build_blocks(parts);
    return;
  }
  for (int e = 0; e < static_cast<int>(model.elements().size()); ++e)
    if (corotational[model.elements()[e].body]) corot_elements_.push_back(e);
  if (corot_elements_.empty()) {
    build_blocks(parts);
    return;
  }
  // Linear part: K minus the corotational elements' reference stiffness.
  std::vector<Eigen::Triplet<double>> t;
  for (int e : corot_elements_) {
    const Eigen::MatrixXd& Ke = model.reference_stiffness(e);
    const Eigen::Matrix<int, 6, 1> eq = model.element_equations(e);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (eq(i) >= 0 && eq(j) >= 0 && Ke(i, j) != 0.0) t.emplace_back(eq(i), eq(j), -Ke(i, j));
  }
  SparseMatrix Kc(model.size(), model.size());
  Kc.setFromTriplets(t.begin(), t.end());
  K_linear_ = model.K() + Kc;
  K_linear_.prune(0.0);
  K_ = &K_linear_;
}

void InternalForce::build_blocks(int parts) {
  // Each group's block: a group follows the last elastic element's (groups are runs of equal
  // consecutive elements), and shares the last block when its matrix is the same.
  const int w = 2 * model_.dofs_per_node();
  std::vector<int> block_of_group;
  int last = -1;  // the group of the last elastic element
  for (int e = 0; e < static_cast<int>(model_.elements().size()); ++e) {
    const int g = model_.element_group(e);
    if (g < 0 || g == last) continue;  // a rigid body's element (no stiffness), or the same block
    const Eigen::MatrixXd& Ke = model_.reference_stiffness(e);
    last = g;
    const std::size_t nb = blocks_.size() / (w * w);
    bool same = nb > 0;
    for (int i = 0; same && i < w; ++i)
      for (int j = 0; same && j < w; ++j) same = blocks_[(nb - 1) * w * w + i * w + j] == Ke(i, j);
    if (!same)
      for (int i = 0; i < w; ++i)
        for (int j = 0; j < w; ++j) blocks_.push_back(Ke(i, j));
    block_of_group.resize(static_cast<std::size_t>(g) + 1, -1);
    block_of_group[g] = static_cast<int>(blocks_.size() / (w * w)) - 1;
  }
  const int n = model_.size();
  use_blocks_ = n > 0 && build_spans(block_of_group, w);
  // Kept only when the blocks are the whole of K (no other stiffness assembled into it): the
  // two products agree on a vector with no special structure, to the roundoff of the sums
  // (1e-12 of sum |K_ij| |x_j| per row; a missing or extra term of K shows at O(1)), and every
  // equation is finished exactly once.
  if (use_blocks_) {
    const Eigen::VectorXd x = spread_vector(n);
    Eigen::VectorXd kx(n), bx(n), scale(n);
    product_and_scale(model_.K(), x, kx, scale);
    std::vector<int> finished(n, 0);
    auto count = [&](int lo, int hi) {
      for (int i = lo; i < hi; ++i) ++finished[i];
    };
    apply_streamed(x, bx, count);
    use_blocks_ = ((kx - bx).cwiseAbs().array() <= 1e-12 * scale.array()).all() &&
                  std::all_of(finished.begin(), finished.end(), [](int c) { return c == 1; });
    if (use_blocks_ && parts > 1) split(parts, x, bx);  // the same vector and its product
  }
  if (!use_blocks_) {
    blocks_.clear();
    spans_.clear();
    untouched_.clear();
  }
}

bool InternalForce::build_spans(const std::vector<int>& block_of_group, int w) {
  const int n = model_.size(), per = w / 2;
  const ElasticElements elastic(model_);
  const int ne = elastic.size();
  std::vector<int> first, last;
  touching_elements(elastic, n, w, first, last);
  untouched_ = untouched_ranges(first);
  // The equations whose first (or last) element is e, as one range [lo, hi); lo = hi = 0 when
  // there are none. False when they are not one range.
  auto owned = [&](int e, const int* eq, const std::vector<int>& owner, int& lo, int& hi) {
    lo = hi = 0;
    int members = 0, mn = n, mx = -1;
    for (int i = 0; i < w; ++i)
      if (const int q = eq[i]; q >= 0 && owner[q] == e) {
        ++members;
        mn = std::min(mn, q);
        mx = std::max(mx, q);
      }
    if (members == 0) return true;
    lo = mn;
    hi = mx + 1;
    return hi - lo == members;
  };
  // The common case first: element e is the next of the last span, a chain, when it has that
  // span's block, its equations advanced by one node's DOFs, and is the first element on its
  // second node's equations and the last on its first node's (what the general test below
  // finds, without forming the element's span).
  auto continues_chain = [&](const int* eq, int e, int block) {
    const Span& p = spans_.back();
    const int q0 = p.eq[0] + p.count * per;
    if (!p.chain || p.block != block) return false;
    for (int i = 0; i < w; ++i)
      if (eq[i] != q0 + i || (first[q0 + i] == e) != (i >= per) || (last[q0 + i] == e) != (i < per))
        return false;
    return true;
  };
  spans_.clear();
  for (int e = 0; e < ne; ++e) {
    const int* eq = elastic.equations(e);
    const int block = block_of_group[model_.element_group(elastic.model_element(e))];
    if (!spans_.empty() && continues_chain(eq, e, block)) {
      ++spans_.back().count;
      continue;
    }
    Span s{};
    s.count = 1;
    s.block = block;
    for (int i = 0; i < 6; ++i) s.eq[i] = i < w ? eq[i] : -1;
    if (!owned(e, eq, first, s.zero_lo, s.zero_hi) || !owned(e, eq, last, s.done_lo, s.done_hi)) {
      spans_.clear();
      untouched_.clear();
      return false;
    }
    bool contiguous = true;
    for (int i = 0; i < w; ++i) contiguous = contiguous && s.eq[i] >= 0 && s.eq[i] == s.eq[0] + i;
    s.chain = contiguous && s.zero_lo == s.eq[0] + per && s.zero_hi == s.eq[0] + w && s.done_lo == s.eq[0] &&
              s.done_hi == s.eq[0] + per;
    // Element e joins the last span when it is that span's next element: the same block, and
    // equations and ranges advanced by one node's DOFs.
    if (!spans_.empty()) {
      Span& p = spans_.back();
      const int o = p.count * per;
      auto next_of = [o](int a, int b) { return (a < 0 && b < 0) || (a >= 0 && b == a + o); };
      auto next_range = [o](int alo, int ahi, int blo, int bhi) {
        return (alo == ahi && blo == bhi) || (alo < ahi && blo == alo + o && bhi == ahi + o);
      };
      bool next = p.block == s.block && p.chain == s.chain;
      for (int i = 0; next && i < w; ++i) next = next_of(p.eq[i], s.eq[i]);
      next = next && next_range(p.zero_lo, p.zero_hi, s.zero_lo, s.zero_hi) &&
             next_range(p.done_lo, p.done_hi, s.done_lo, s.done_hi);
      if (next) {
        ++p.count;
        continue;
      }
    }
    spans_.push_back(s);
  }
  return true;
}

const std::vector<std::array<int, 2>> InternalForce::kNone;

int InternalForce::set_parts(int parts) {
  parts_.clear();
  boundary_.clear();
  if (!use_blocks_ || parts < 2) return 1;
  const Eigen::VectorXd x = spread_vector(model_.size());
  Eigen::VectorXd whole(x.size());
  apply_streamed(x, whole, [](int, int) {});
  return split(parts, x, whole);
}

int InternalForce::split(int parts, const Eigen::VectorXd& x, const Eigen::VectorXd& whole) {
  if (!build_parts(parts)) {
    parts_.clear();
    boundary_.clear();
    return 1;
  }
  // Kept only when the parts, run one after the other, give apply_streamed()'s bits on a vector
  // with no special structure and finish every equation exactly once.
  const int n = model_.size();
  Eigen::VectorXd parted(n);
  std::vector<int> finished(n, 0);
  auto count = [&](int lo, int hi) {
    for (int i = lo; i < hi; ++i) ++finished[i];
  };
  for (int t = 0; t < parts; ++t) apply_part(t, x, parted, count);
  finish_parts(parted, count);
  bool same = std::all_of(finished.begin(), finished.end(), [](int c) { return c == 1; });
  for (int i = 0; same && i < n; ++i)
    same = std::bit_cast<std::uint64_t>(whole[i]) == std::bit_cast<std::uint64_t>(parted[i]);
  if (!same) {
    parts_.clear();
    boundary_.clear();
    return 1;
  }
  return parts;
}

bool InternalForce::build_parts(int parts) {
  const int per = model_.dofs_per_node(), w = 2 * per, n = model_.size();
  int ne = 0;
  for (const Span& sp : spans_) ne += sp.count;
  if (ne < 2 * parts) return false;
  auto eq_of = [per](const Span& sp, int k, int i) { return sp.eq[i] >= 0 ? sp.eq[i] + k * per : -1; };
  // The first and the last element touching each equation.
  std::vector<int> first(n, -1), last(n, -1);
  int g = 0;
  for (const Span& sp : spans_)
    for (int k = 0; k < sp.count; ++k, ++g)
      for (int i = 0; i < w; ++i)
        if (const int q = eq_of(sp, k, i); q >= 0) {
          if (first[q] < 0) first[q] = g;
          last[q] = g;
        }
  // Part t: elements [start[t], start[t + 1]).
  std::vector<int> start(parts + 1);
  for (int t = 0; t <= parts; ++t) start[t] = static_cast<int>(static_cast<long>(t) * ne / parts);
  // Equation q is touched by two parts when a part starts after its first element and at or
  // before its last.
  auto crosses = [&](int q) {
    for (int t = 1; t < parts; ++t)
      if (first[q] < start[t] && start[t] <= last[q]) return true;
    return false;
  };
  parts_.assign(parts, Part{});
  g = 0;
  int t = 0;  // the part of element g, stepped with g (the parts' starts increase: ne >= 2 parts)
  for (const Span& sp : spans_)
    for (int k = 0; k < sp.count; ++k, ++g) {
      while (g >= start[t + 1]) ++t;
      const int k0 = start[t];
      Part& p = parts_[t];
      unsigned apart = 0;  // rows of equations an earlier part touches first
      for (int i = 0; i < w; ++i)
        if (const int q = eq_of(sp, k, i); q >= 0 && first[q] < k0) apart |= 1u << i;
      if (apart == 0 && g > k0 && k > 0 && p.pieces.back().apart == 0) {
        ++p.pieces.back().count;  // the same span's next element
        continue;
      }
      Span piece = sp;
      const int o = k * per;
      piece.count = 1;
      for (int i = 0; i < w; ++i) piece.eq[i] = eq_of(sp, k, i);
      if (piece.zero_lo < piece.zero_hi) piece.zero_lo += o, piece.zero_hi += o;
      if (piece.done_lo < piece.done_hi) piece.done_lo += o, piece.done_hi += o;
      if (apart != 0) {
        piece.chain = false;
        piece.apart = apart;
        piece.side_at = static_cast<int>(p.side_eq.size());
        for (int i = 0; i < w; ++i)
          if (apart >> i & 1u) p.side_eq.push_back(piece.eq[i]);
        // It finishes only the equations its own part started (the rest are boundary ones).
        int lo = n, hi = -1, members = 0;
        for (int q = piece.done_lo; q < piece.done_hi; ++q)
          if (first[q] >= k0) lo = std::min(lo, q), hi = std::max(hi, q), ++members;
        if (members > 0 && hi + 1 - lo != members) return false;
        piece.done_lo = members > 0 ? lo : 0;
        piece.done_hi = members > 0 ? hi + 1 : 0;
      }
      p.pieces.push_back(piece);
    }
  for (Part& p : parts_) p.side.assign(p.side_eq.size(), 0.0);
  for (int q = 0; q < n; ++q)
    if (first[q] >= 0 && crosses(q)) {
      if (!boundary_.empty() && boundary_.back()[1] == q)
        ++boundary_.back()[1];
      else
        boundary_.push_back({q, q + 1});
    }
  return true;
}

InternalForce::Local InternalForce::local(int e, const Eigen::VectorXd& U, Eigen::Matrix<int, 6, 1>& eq,
                                          double x[6]) const {
  const Model::Element& el = model_.elements()[e];
  eq = model_.element_equations(e);
  for (int i = 0; i < 6; ++i) x[i] = eq(i) >= 0 ? U(eq(i)) : 0.0;
  const Vec2 p1 = model_.node_position(el.n1), p2 = model_.node_position(el.n2);
  const double dx = p2[0] + x[3] - p1[0] - x[0], dy = p2[1] + x[4] - p1[1] - x[1];
  Local l;
  l.ln = std::hypot(dx, dy);
  l.c = dx / l.ln;
  l.s = dy / l.ln;
  // Rigid rotation of the chord from the reference direction: atan2 gives it in (-pi, pi], but the
  // nodal rotations accumulate past pi on a spinning body, so take the branch nearest to them.
  double alpha = std::atan2(el.c * l.s - el.s * l.c, el.c * l.c + el.s * l.s);
  alpha += 2 * M_PI * std::round((0.5 * (x[2] + x[5]) - alpha) / (2 * M_PI));
  l.u = l.ln - el.length;
  l.th1 = x[2] - alpha;
  l.th2 = x[5] - alpha;
  return l;
}

Vec2 InternalForce::chord_direction(int e, const Eigen::VectorXd& U) const {
  Eigen::Matrix<int, 6, 1> eq;
  double x[6];
  const Local l = local(e, U, eq, x);
  return {l.c, l.s};
}

void InternalForce::apply(const Eigen::VectorXd& U, Eigen::VectorXd& f) const {
  if (use_blocks_) {
    apply_streamed(U, f, [](int, int) {});
    return;
  }
  f.noalias() = (*K_) * U;
  Eigen::Matrix<int, 6, 1> eq;
  double x[6];
  for (int e : corot_elements_) {
    const Model::Element& el = model_.elements()[e];
    const Local l = local(e, U, eq, x);
    const auto [N, M1, M2] = section(el, l.u, l.th1, l.th2);
    // f = B^T [N, M1, M2] with B = [r; e3 - z/ln; e6 - z/ln] (theta_local = theta - chord rotation,
    // d(chord angle) = z . dp / ln), r = [-c,-s,0,c,s,0], z = [s,-c,0,-s,c,0]:
    // f = r N - z (M1 + M2)/ln + e3 M1 + e6 M2.
    const double q = -(M1 + M2) / l.ln;
    const double fe[6] = {-l.c * N + l.s * q, -l.s * N - l.c * q, M1,
                          l.c * N - l.s * q,  l.s * N + l.c * q,  M2};
    for (int i = 0; i < 6; ++i)
      if (eq(i) >= 0) f(eq(i)) += fe[i];
  }
}

void InternalForce::end_forces(const Eigen::VectorXd& U, std::vector<std::array<double, 3>>& out,
                               ThreadTeam* team) const {
  const int n = static_cast<int>(model_.elements().size());
  out.resize(static_cast<std::size_t>(n));
  run_ranges(team, n, [&](long long first, long long last) {
    for (long long e = first; e < last; ++e)
      out[static_cast<std::size_t>(e)] = end_forces(static_cast<int>(e), U);
  });
}

std::array<double, 3> InternalForce::end_forces(int e, const Eigen::VectorXd& U) const {
  const Model::Element& el = model_.elements()[e];
  if (el.rigid) return {0.0, 0.0, 0.0};
  if (std::binary_search(corot_elements_.begin(), corot_elements_.end(), e)) {
    Eigen::Matrix<int, 6, 1> eq;
    double x[6];
    const Local l = local(e, U, eq, x);
    return section(el, l.u, l.th1, l.th2);
  }
  // The linear element: stretch along and chord rotation across the reference axis.
  if (model_.dofs_per_node() == 3 && !model_.rotated(el.n1) && !model_.rotated(el.n2)) {
    // Both nodes' DOFs in global axes (what node_vector() and equation() give, read in one go).
    const std::span<const int> eq = model_.element_dofs(e);
    double x[6];
    for (int i = 0; i < 6; ++i) x[i] = eq[i] >= 0 ? U(eq[i]) : 0.0;
    const double du = x[3] - x[0], dv = x[4] - x[1];
    const double turn = (-el.s * du + el.c * dv) / el.length;
    return section(el, el.c * du + el.s * dv, x[2] - turn, x[5] - turn);
  }
  const Vec2 u1 = model_.node_vector(U, el.n1), u2 = model_.node_vector(U, el.n2);
  const double du = u2[0] - u1[0], dv = u2[1] - u1[1];
  double th1 = 0.0, th2 = 0.0;
  if (model_.dofs_per_node() == 3) {
    const double turn = (-el.s * du + el.c * dv) / el.length;
    auto rotation = [&](int node) {
      const int q = model_.equation(node, 2);
      return q >= 0 ? U(q) : 0.0;
    };
    th1 = rotation(el.n1) - turn;
    th2 = rotation(el.n2) - turn;
  }
  return section(el, el.c * du + el.s * dv, th1, th2);
}

double InternalForce::strain_energy(const Eigen::VectorXd& U) const {
  // U^T K U = sum_j U_j (column j of K) . U, for any K: the columns read U where they are stored.
  const SparseMatrix& K = *K_;
  const double* u = U.data();
  double e = 0.5 * ordered_sum(nullptr, K.outerSize(), energy_chunks_, [&](long long first, long long last) {
               double s = 0.0;
               for (long long j = first; j < last; ++j) {
                 double column = 0.0;
                 for (SparseMatrix::InnerIterator it(K, static_cast<Eigen::Index>(j)); it; ++it)
                   column += it.value() * u[it.index()];
                 s += u[j] * column;
               }
               return s;
             });
  Eigen::Matrix<int, 6, 1> eq;
  double x[6];
  for (int i : corot_elements_) {
    const Model::Element& el = model_.elements()[i];
    const Local l = local(i, U, eq, x);
    const double k = el.E * el.inertia / el.length;
    e += 0.5 * el.E * el.area / el.length * l.u * l.u +
         0.5 * k * (4 * l.th1 * l.th1 + 4 * l.th1 * l.th2 + 4 * l.th2 * l.th2);
  }
  return e;
}

}  // namespace beamimpact::paper
