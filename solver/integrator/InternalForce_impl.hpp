#pragma once
/// @file InternalForce_impl.hpp
/// @brief The element-block product of InternalForce, templated on the caller's per-equation
/// work (InternalForce::apply_streamed). Included by InternalForce.hpp; not for direct use.

#include <solver/integrator/InternalForce.hpp>

namespace beamimpact::paper {

template <int W, class Done>
void InternalForce::sweep_pieces(const Span* begin, const Span* end,
                                 const std::vector<std::array<int, 2>>& untouched, const double* u,
                                 double* out, double* side, Done&& done) const {
  constexpr int per = W / 2;  // DOFs per node: the stride of a span
  // Finished ranges that follow each other are handed on together, kBatch equations or more at
  // a time (a few kB: still in L1), so that the caller's loop is long enough to vectorise.
  constexpr int kBatch = 128;
  int pending_lo = 0, pending_hi = 0;
  auto finish = [&](int lo, int hi) {
    if (lo != pending_hi || pending_hi - pending_lo >= kBatch) {
      if (pending_lo < pending_hi) done(pending_lo, pending_hi);
      pending_lo = lo;
    }
    pending_hi = hi;
  };
  for (const std::array<int, 2>& r : untouched) {
    for (int i = r[0]; i < r[1]; ++i) out[i] = 0.0;
    finish(r[0], r[1]);
  }
  // Every entry of f gets exactly the operations of a zeroed f followed by "out[eq] += row . x"
  // element by element in model order: 0.0 at its first element, then each element's row sum
  // (accumulated from 0.0 in column order).
  for (const Span* sp = begin; sp != end; ++sp) {
    const double* k = blocks_.data() + sp->block * W * W;
    if (sp->chain) {  // the hand kernel's loop: no index arrays, no tests
      // Each element adds to its first node (finished after it) and starts its second: 0.0 + y
      // there, what zeroing and then adding gives, without a store and a reload per entry.
      for (int e = 0; e < sp->count; ++e) {
        const int b = sp->eq[0] + e * per;
        double x[W];
        for (int i = 0; i < W; ++i) x[i] = u[b + i];
        for (int i = 0; i < W; ++i) {
          double y = 0.0;
          for (int j = 0; j < W; ++j) y += k[i * W + j] * x[j];
          out[b + i] = (i < per ? out[b + i] : 0.0) + y;
        }
        finish(b, b + per);
      }
      continue;
    }
    for (int e = 0; e < sp->count; ++e) {
      const int o = e * per;
      int eq[W];
      for (int i = 0; i < W; ++i) eq[i] = sp->eq[i] >= 0 ? sp->eq[i] + o : -1;
      for (int i = sp->zero_lo + o; i < sp->zero_hi + o; ++i) out[i] = 0.0;
      double x[W];
      for (int i = 0; i < W; ++i) x[i] = eq[i] >= 0 ? u[eq[i]] : 0.0;
      int s = sp->side_at;
      for (int i = 0; i < W; ++i) {
        if (eq[i] < 0) continue;
        double y = 0.0;
        for (int j = 0; j < W; ++j) y += k[i * W + j] * x[j];
        if (sp->apart >> i & 1u)
          side[s++] = y;  // a later part's term of a boundary equation: added by finish_parts
        else
          out[eq[i]] += y;
      }
      if (sp->done_lo < sp->done_hi) finish(sp->done_lo + o, sp->done_hi + o);
    }
  }
  if (pending_lo < pending_hi) done(pending_lo, pending_hi);
}

template <int W, class Done>
void InternalForce::apply_spans(const Eigen::VectorXd& U, Eigen::VectorXd& f, Done&& done) const {
  sweep_pieces<W>(spans_.data(), spans_.data() + spans_.size(), untouched_, U.data(), f.data(), nullptr,
                  done);
}

template <class Done>
void InternalForce::apply_part(int t, const Eigen::VectorXd& U, Eigen::VectorXd& f, Done&& done) const {
  if (parts_.empty()) {
    apply_streamed(U, f, done);
    return;
  }
  const Part& p = parts_[t];
  const Span* b = p.pieces.data();
  const Span* e = b + p.pieces.size();
  const std::vector<std::array<int, 2>>& untouched = t == 0 ? untouched_ : kNone;
  if (model_.dofs_per_node() == 3)
    sweep_pieces<6>(b, e, untouched, U.data(), f.data(), p.side.data(), done);
  else
    sweep_pieces<2>(b, e, untouched, U.data(), f.data(), p.side.data(), done);
}

template <class Done>
void InternalForce::finish_parts(Eigen::VectorXd& f, Done&& done) const {
  if (parts_.empty()) return;
  double* out = f.data();
  // The first part touching a boundary equation summed its own terms into f; the later parts'
  // follow in part order, each part's in element order: the order of apply_streamed().
  for (std::size_t t = 1; t < parts_.size(); ++t) {
    const Part& p = parts_[t];
    for (std::size_t j = 0; j < p.side_eq.size(); ++j) out[p.side_eq[j]] += p.side[j];
  }
  for (const std::array<int, 2>& r : boundary_) done(r[0], r[1]);
}

template <class Done>
void InternalForce::apply_streamed(const Eigen::VectorXd& U, Eigen::VectorXd& f, Done&& done) const {
  if (!use_blocks_) {
    apply(U, f);
    if (f.size() > 0) done(0, static_cast<int>(f.size()));
    return;
  }
  if (model_.dofs_per_node() == 3)
    apply_spans<6>(U, f, done);
  else
    apply_spans<2>(U, f, done);
}

}  // namespace beamimpact::paper
