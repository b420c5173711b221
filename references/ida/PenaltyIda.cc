#include <references/ida/PenaltyIda.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <ida/ida.h>
#include <ida/ida_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>

namespace beamimpact::ida {
namespace {

using Vec = Eigen::VectorXd;
using CMap = Eigen::Map<const Vec>;
using MMap = Eigen::Map<Vec>;
using Triplet = Eigen::Triplet<double>;

/// Contact state. "Receding" is open after a release while the bodies still separate (the gap's
/// rate positive; with a dashpot the gap is then still negative). It re-closes when the trial
/// force rises above the spring force of a penetration of the integration's absolute tolerance
/// (kn atol: what IDA's error control resolves of the spring force), or when the bodies approach
/// again (the gap's rate falls through zero); it turns plain open once the gap has cleared the
/// surface by atol (a plain g-root would miss a re-approach that starts below zero). Both margins
/// keep the roots off roundoff: with a stiff penalty on a receding contact the trial force creeps
/// along zero (the overdamped spring-dashpot relaxing while the bodies part) within its roundoff
/// of about kn 1e-18 m, and a root on zero itself flips the contact by events of roundoff size
/// without end; g = g0 + n.U cancels to a few 1e-18 m near zero, which the root finder reads as a
/// fall while the gap rises.
enum class Phase { kOpen, kClosed, kReceding };

/// IDA's messages: errors are kept for the exception text, warnings counted (not printed).
struct Messages {
  std::string last_error;
  long warnings = 0;
};

void error_handler(int code, const char* module, const char* function, char* msg, void* user) {
  auto* m = static_cast<Messages*>(user);
  if (code > 0) {  // IDA_WARNING
    ++m->warnings;
    return;
  }
  m->last_error = std::string(module) + "/" + function + ": " + msg;
}

void check(int flag, const char* call, const Messages* m = nullptr) {
  if (flag < 0)
    throw std::runtime_error(std::string("IDA reference: ") + call +
                             " failed: " + IDAGetReturnFlagName(flag) +
                             (m && !m->last_error.empty() ? " (" + m->last_error + ")" : ""));
}

bool is_diagonal(const SparseMatrix& A) {
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      if (it.row() != it.col() && it.value() != 0.0) return false;
  return true;
}

}  // namespace

struct PenaltyIda::Impl {
  const SparseMatrix& M;
  const SparseMatrix& K;
  SparseMatrix C;
  std::vector<const ContactKinematics*> contacts;
  std::vector<PenaltyLaw> laws;
  IdaSettings settings;
  int n = 0, nc = 0, nq = 0;

  Vec m_diag;  // when M is diagonal
  Eigen::SimplicialLDLT<SparseMatrix> m_ldlt;
  bool diagonal_mass = true;

  std::vector<Phase> phase;
  std::vector<ContactEvent> events;
  IdaCounters done;  // counters of finished segments (IDAReInit zeroes IDA's own)
  Messages messages;
  double released_energy = 0.0;           // J, spring energy (kn g^2/2) left in the penalty at releases
  Vec load;                               // constant external load F, empty for none
  const ElasticForce* elastic = nullptr;  // f_int(U) and its tangent; null: K U

  SUNContext ctx = nullptr;
  N_Vector yy = nullptr, yp = nullptr;
  SUNMatrix J = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  double t_now = 0.0;

  // Sparse Jacobian work: base triplets ([0 -I; K C]), the cj-scaled ones ([I 0; 0 M]); with an
  // elastic force, K's place takes its tangent at the current U (between id_trip and c_trip).
  std::vector<Triplet> base_trip, id_trip, c_trip, cj_trip;
  std::vector<sunindextype> last_ptr, last_idx;

  Impl(const SparseMatrix& M_, const SparseMatrix& K_, const SparseMatrix& C_,
       std::vector<const ContactKinematics*> c, std::vector<PenaltyLaw> l, IdaSettings s)
      : M(M_), K(K_), C(C_), contacts(std::move(c)), laws(std::move(l)), settings(s) {
    n = static_cast<int>(M.rows());
    nc = static_cast<int>(contacts.size());
    nq = 3 * nc + 1;
    if (C.rows() == 0) C.resize(n, n);
    diagonal_mass = is_diagonal(M);
    if (diagonal_mass) {
      m_diag = M.diagonal();
    } else {
      m_ldlt.compute(M);
      if (m_ldlt.info() != Eigen::Success)
        throw std::runtime_error("IDA reference: the mass matrix is not positive definite");
    }
    phase.assign(nc, Phase::kOpen);
    for (int i = 0; i < n; ++i) {
      base_trip.emplace_back(i, n + i, -1.0);
      id_trip.emplace_back(i, n + i, -1.0);
      cj_trip.emplace_back(i, i, 1.0);
    }
    // Quadrature rows F_q = Q' - q(U, V): their coupling to U, V is left out of the Jacobian
    // (Q does not feed back, so Newton still converges; Q merely lags one iteration).
    for (int k = 0; k < nq; ++k) cj_trip.emplace_back(2 * n + k, 2 * n + k, 1.0);
    for (int k = 0; k < K.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(K, k); it; ++it)
        base_trip.emplace_back(n + it.row(), it.col(), it.value());
    for (int k = 0; k < C.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(C, k); it; ++it) {
        base_trip.emplace_back(n + it.row(), n + it.col(), it.value());
        c_trip.emplace_back(n + it.row(), n + it.col(), it.value());
      }
    for (int k = 0; k < M.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(M, k); it; ++it)
        cj_trip.emplace_back(n + it.row(), n + it.col(), it.value());
  }

  ~Impl() {
    if (mem) IDAFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (J) SUNMatDestroy(J);
    if (yp) N_VDestroy(yp);
    if (yy) N_VDestroy(yy);
    if (ctx) SUNContext_Free(&ctx);
  }

  /// The internal force f_int(U): K U, or the elastic force's.
  Vec internal(const CMap& U) const {
    if (!elastic) return K * U;
    Vec f;
    elastic->apply(U, f);
    return f;
  }

  /// Contact reading for displacement U and velocity V.
  ContactReading read(int i, const double* y) const {
    const CMap U(y, n), V(y + n, n);
    ContactReading r;
    r.frame = contacts[i]->evaluate(U);
    r.gap = r.frame.gap(U);
    r.gap_rate = r.frame.normal_rate(V);
    r.slip_rate = r.frame.tangential_rate(V);
    r.force_rate = r.frame.force_rate(V);
    r.closed = phase[i] == Phase::kClosed;
    if (r.closed) {
      r.R = laws[i].normal_force(r.gap, r.gap_rate);
      r.tau = laws[i].friction_force(r.R, r.slip_rate);
      r.penalty_energy = laws[i].spring_energy(r.gap);
    }
    return r;
  }

  /// Generalised contact force f_c = sum (R G_n + tau G_t).
  void contact_force(const double* y, Vec& f) const {
    f.setZero(n);
    for (int i = 0; i < nc; ++i) {
      if (phase[i] != Phase::kClosed) continue;
      const ContactReading r = read(i, y);
      for (const DofTerm& d : r.frame.n_terms) f(d.eq) += r.R * d.coeff;
      for (const DofTerm& d : r.frame.t_terms) f(d.eq) += r.tau * d.coeff;
    }
  }

  Vec solve_mass(const Vec& b) const {
    if (diagonal_mass) return b.cwiseQuotient(m_diag);
    return m_ldlt.solve(b);
  }

  /// y' consistent with y for the current contact phases.
  void consistent_yp() {
    const double* y = N_VGetArrayPointer(yy);
    const CMap U(y, n), V(y + n, n);
    Vec f;
    contact_force(y, f);
    if (load.size()) f += load;
    const Vec acc = elastic ? solve_mass(f - internal(U) - C * V) : solve_mass(f - K * U - C * V);
    double* p = N_VGetArrayPointer(yp);
    MMap(p, n) = V;
    MMap(p + n, n) = acc;
    quad_rhs(y, p + 2 * n);
  }

  void residual(const double* y, const double* ydot, double* res) const {
    const CMap U(y, n), V(y + n, n), Ud(ydot, n), Vd(ydot + n, n);
    Vec f;
    contact_force(y, f);
    if (load.size()) f += load;
    MMap(res, n) = Ud - V;
    if (elastic)
      MMap(res + n, n) = M * Vd + C * V + internal(U) - f;
    else
      MMap(res + n, n) = M * Vd + C * V + K * U - f;
    quad_rhs(y, res + 2 * n);
    for (int k = 0; k < nq; ++k) res[2 * n + k] = ydot[2 * n + k] - res[2 * n + k];
  }

  void roots(const double* y, double* g) const {
    for (int i = 0; i < nc; ++i) {
      const CMap U(y, n), V(y + n, n);
      const ContactFrame f = contacts[i]->evaluate(U);
      const double gap = f.gap(U);
      switch (phase[i]) {
        case Phase::kOpen:
          g[2 * i] = gap;
          g[2 * i + 1] = 1.0;
          break;
        case Phase::kClosed:
          g[2 * i] = laws[i].normal_force(gap, f.normal_rate(V));
          g[2 * i + 1] = 1.0;
          break;
        case Phase::kReceding: {
          const double rate = f.normal_rate(V);
          g[2 * i] =
              std::max(laws[i].normal_force(gap, rate) - laws[i].normal_force(-settings.atol, 0.0), -rate);
          g[2 * i + 1] = gap - settings.atol;
          break;
        }
      }
    }
  }

  void set_root_directions() {
    std::vector<int> dir(2 * nc, 0);
    for (int i = 0; i < nc; ++i) {
      dir[2 * i] = phase[i] == Phase::kReceding ? +1 : -1;
      dir[2 * i + 1] = +1;
    }
    if (nc > 0) check(IDASetRootDirection(mem, dir.data()), "IDASetRootDirection");
  }

  void quad_rhs(const double* y, double* out) const {
    for (int i = 0; i < nc; ++i) {
      const ContactReading r = read(i, y);
      out[3 * i] = r.R;
      out[3 * i + 1] = r.tau;
      // What the contact forces take from the bodies, -(R force_rate + tau v_t), less what the
      // spring stores, d(kn g^2/2)/dt = kn g g': the dashpot's cn g'^2 and friction's -tau v_t
      // (both >= 0), and the reference normal's work on a slide over a deflected target,
      // R rate_coupling v_t (either sign: energy the linear contact creates or removes).
      out[3 * i + 2] =
          r.closed ? -(r.R * r.force_rate + r.tau * r.slip_rate) - laws[i].kn * r.gap * r.gap_rate : 0.0;
    }
    const CMap V(y + n, n);
    out[3 * nc] = V.dot(C * V);
  }

  /// J = dF/dy + cj dF/dy' as a compressed sparse matrix.
  SparseMatrix jacobian(double cj, const double* y) const {
    std::vector<Triplet> trip;
    if (elastic) {
      trip = id_trip;
      elastic->add_tangent(CMap(y, n), 1.0, n, 0, trip);
      trip.insert(trip.end(), c_trip.begin(), c_trip.end());
    } else {
      trip = base_trip;
    }
    trip.reserve(trip.size() + cj_trip.size() + 64);
    for (const Triplet& t : cj_trip) trip.emplace_back(t.row(), t.col(), cj * t.value());
    for (int i = 0; i < nc; ++i) {
      const ContactReading r = read(i, y);
      // dF_v/dU -= G_n dR/dU + G_t dtau/dU, dF_v/dV likewise; dR/dU = -kn G_n (Hertz: the
      // spring's stiffness at the gap), dR/dV = -cn G_n,
      // dtau = -mu s(vt) dR - mu R s'(vt) G_t dV. Entries are written (as zeros) while open
      // too, so the sparsity pattern changes only when the struck point changes element.
      // The weights' own dependence on U (sliding) is left out: it only slows Newton slightly.
      const PenaltyLaw& law = laws[i];
      const double on = r.closed ? 1.0 : 0.0;
      const double s = law.slip_sign(r.slip_rate);
      const double ds = law.slip_sign_derivative(r.slip_rate);
      const auto& Gn = r.frame.n_terms;
      const auto& Gt = r.frame.t_terms;
      const double kn = law.spring_stiffness(r.gap);
      for (const DofTerm& a : Gn)
        for (const DofTerm& b : Gn) {
          trip.emplace_back(n + a.eq, b.eq, on * kn * a.coeff * b.coeff);
          trip.emplace_back(n + a.eq, n + b.eq, on * law.cn * a.coeff * b.coeff);
        }
      for (const DofTerm& a : Gt) {
        for (const DofTerm& b : Gn) {
          trip.emplace_back(n + a.eq, b.eq, -on * law.mu * s * kn * a.coeff * b.coeff);
          trip.emplace_back(n + a.eq, n + b.eq, -on * law.mu * s * law.cn * a.coeff * b.coeff);
        }
        for (const DofTerm& b : Gt)
          trip.emplace_back(n + a.eq, n + b.eq, on * law.mu * r.R * ds * a.coeff * b.coeff);
      }
    }
    SparseMatrix Jm(2 * n + nq, 2 * n + nq);
    Jm.setFromTriplets(trip.begin(), trip.end());
    Jm.makeCompressed();
    return Jm;
  }

  int fill_jacobian(double cj, const double* y, SUNMatrix Jac) {
    const SparseMatrix Jm = jacobian(cj, y);
    if (settings.linear_solver == IdaLinearSolver::kDense) {
      SUNMatZero(Jac);
      for (int k = 0; k < Jm.outerSize(); ++k)
        for (SparseMatrix::InnerIterator it(Jm, k); it; ++it)
          SM_ELEMENT_D(Jac, it.row(), it.col()) = it.value();
      return 0;
    }
    const sunindextype nnz = Jm.nonZeros();
    if (SM_NNZ_S(Jac) < nnz && SUNSparseMatrix_Reallocate(Jac, nnz) != 0) return -1;
    sunindextype* ptr = SM_INDEXPTRS_S(Jac);
    sunindextype* idx = SM_INDEXVALS_S(Jac);
    double* data = SM_DATA_S(Jac);
    const int N = 2 * n + nq;
    for (int k = 0; k <= N; ++k) ptr[k] = Jm.outerIndexPtr()[k];
    for (sunindextype k = 0; k < nnz; ++k) {
      idx[k] = Jm.innerIndexPtr()[k];
      data[k] = Jm.valuePtr()[k];
    }
    // A new pattern (the struck point entered another element) needs a new symbolic
    // factorisation: KLU would otherwise refactor with the old one.
    const bool same = last_ptr.size() == static_cast<std::size_t>(N + 1) &&
                      std::equal(last_ptr.begin(), last_ptr.end(), ptr) &&
                      last_idx.size() == static_cast<std::size_t>(nnz) &&
                      std::equal(last_idx.begin(), last_idx.end(), idx);
    if (!same) {
      if (!last_ptr.empty()) ++done.klu_pattern_changes;
      last_ptr.assign(ptr, ptr + N + 1);
      last_idx.assign(idx, idx + nnz);
      if (SUNLinSol_KLUReInit(LS, Jac, SM_NNZ_S(Jac), SUNKLU_REINIT_PARTIAL) != 0) return -1;
    }
    return 0;
  }

  IdaCounters counters_now() const {
    IdaCounters c = done;
    if (!mem) return c;
    long v = 0;
    IDAGetNumSteps(mem, &v);
    c.steps += v;
    IDAGetNumResEvals(mem, &v);
    c.residual_evals += v;
    IDAGetNumJacEvals(mem, &v);
    c.jacobian_evals += v;
    IDAGetNumNonlinSolvIters(mem, &v);
    c.nonlinear_iters += v;
    IDAGetNumErrTestFails(mem, &v);
    c.error_test_fails += v;
    IDAGetNumNonlinSolvConvFails(mem, &v);
    c.nonlinear_conv_fails += v;
    if (nc > 0) {
      IDAGetNumGEvals(mem, &v);
      c.root_evals += v;
    }
    c.warnings = messages.warnings;
    return c;
  }

  /// The phase change a root of contact i asks for at time t (r0: its first root function, else
  /// its second), if any. A gap root of an open contact closes it only while the gap falls: a
  /// contact closed while the gap rises would start with a tensile trial force (-cn g' < 0) that
  /// the release root (R falling through zero) never sees, and hold the bodies together.
  void switch_phase(int i, double t, bool r0) {
    const double* y = N_VGetArrayPointer(yy);
    switch (phase[i]) {
      case Phase::kOpen:
        if (!(read(i, y).gap_rate < 0.0)) return;
        phase[i] = Phase::kClosed;
        events.push_back({i, t, true});
        return;
      case Phase::kClosed: {
        // The force is zero at release, but with a dashpot the spring is still compressed:
        // its energy leaves the mechanical balance here (counted as dissipated).
        const ContactReading r = read(i, y);
        released_energy += r.penalty_energy;
        phase[i] = r.gap_rate > 0.0 ? Phase::kReceding : Phase::kOpen;
        events.push_back({i, t, false});
        return;
      }
      case Phase::kReceding:
        if (r0 && read(i, y).gap <= 0.0) {
          // Re-closing below zero gap hands the spring kn g^2/2 back (the balance's mirror of
          // the release above).
          phase[i] = Phase::kClosed;
          released_energy -= read(i, y).penalty_energy;
          events.push_back({i, t, true});
        } else {
          phase[i] = Phase::kOpen;  // cleared, or approaching again above the surface
        }
        return;
    }
  }

  void reinit(double t) {
    done = counters_now();
    consistent_yp();
    check(IDAReInit(mem, t, yy, yp), "IDAReInit");
    set_root_directions();
  }
};

namespace {

int residual_fn(sunrealtype, N_Vector yy, N_Vector yp, N_Vector rr, void* user) {
  static_cast<PenaltyIda::Impl*>(user)->residual(N_VGetArrayPointer(yy), N_VGetArrayPointer(yp),
                                                 N_VGetArrayPointer(rr));
  return 0;
}

int root_fn(sunrealtype, N_Vector yy, N_Vector, sunrealtype* g, void* user) {
  static_cast<PenaltyIda::Impl*>(user)->roots(N_VGetArrayPointer(yy), g);
  return 0;
}

int jac_fn(sunrealtype, sunrealtype cj, N_Vector yy, N_Vector, N_Vector, SUNMatrix J, void* user, N_Vector,
           N_Vector, N_Vector) {
  return static_cast<PenaltyIda::Impl*>(user)->fill_jacobian(cj, N_VGetArrayPointer(yy), J);
}

}  // namespace

PenaltyIda::PenaltyIda(const SparseMatrix& M, const SparseMatrix& K, const SparseMatrix& C,
                       std::vector<const ContactKinematics*> contacts, std::vector<PenaltyLaw> laws,
                       IdaSettings settings)
    : impl_(std::make_unique<Impl>(M, K, C, std::move(contacts), std::move(laws), settings)) {
  if (impl_->laws.size() != impl_->contacts.size())
    throw std::invalid_argument("PenaltyIda: one law per contact");
}

PenaltyIda::~PenaltyIda() = default;

void PenaltyIda::start(double t0, const Eigen::VectorXd& U0, const Eigen::VectorXd& V0) {
  Impl& I = *impl_;
  const int N = 2 * I.n + I.nq;
  check(SUNContext_Create(nullptr, &I.ctx), "SUNContext_Create");
  I.yy = N_VNew_Serial(N, I.ctx);
  I.yp = N_VNew_Serial(N, I.ctx);
  MMap(N_VGetArrayPointer(I.yy), I.n) = U0;
  MMap(N_VGetArrayPointer(I.yy) + I.n, I.n) = V0;
  for (int k = 0; k < I.nq; ++k) N_VGetArrayPointer(I.yy)[2 * I.n + k] = 0.0;
  for (int i = 0; i < I.nc; ++i) {
    const double g = I.contacts[i]->evaluate(U0).gap(U0);
    if (!(g > 0.0))
      throw std::runtime_error("IDA reference: contact " + std::to_string(i) +
                               " starts closed (initial gap " + std::to_string(g) + " m)");
  }
  I.consistent_yp();
  I.mem = IDACreate(I.ctx);
  if (!I.mem) throw std::runtime_error("IDA reference: IDACreate failed");
  check(IDASetErrHandlerFn(I.mem, error_handler, &I.messages), "IDASetErrHandlerFn");
  check(IDAInit(I.mem, residual_fn, t0, I.yy, I.yp), "IDAInit");
  check(IDASStolerances(I.mem, I.settings.rtol, I.settings.atol), "IDASStolerances");
  check(IDASetUserData(I.mem, &I), "IDASetUserData");
  check(IDASetMaxNumSteps(I.mem, 1000000), "IDASetMaxNumSteps");
  if (I.settings.max_step > 0.0) check(IDASetMaxStep(I.mem, I.settings.max_step), "IDASetMaxStep");
  if (I.settings.linear_solver == IdaLinearSolver::kDense) {
    I.J = SUNDenseMatrix(N, N, I.ctx);
    I.LS = SUNLinSol_Dense(I.yy, I.J, I.ctx);
  } else {
    const sunindextype nnz = I.jacobian(1.0, N_VGetArrayPointer(I.yy)).nonZeros();
    I.J = SUNSparseMatrix(N, N, nnz, CSC_MAT, I.ctx);
    I.LS = SUNLinSol_KLU(I.yy, I.J, I.ctx);
  }
  if (!I.J || !I.LS) throw std::runtime_error("IDA reference: linear solver creation failed");
  check(IDASetLinearSolver(I.mem, I.LS, I.J), "IDASetLinearSolver");
  check(IDASetJacFn(I.mem, jac_fn), "IDASetJacFn");
  if (I.nc > 0) {
    check(IDARootInit(I.mem, 2 * I.nc, root_fn), "IDARootInit");
    I.set_root_directions();
  }
  I.t_now = t0;
}

void PenaltyIda::set_elastic(const ElasticForce* elastic) { impl_->elastic = elastic; }

void PenaltyIda::set_load(const Eigen::VectorXd& F) {
  if (F.size() != 0 && F.size() != impl_->n) throw std::invalid_argument("PenaltyIda::set_load: wrong size");
  impl_->load = F;
}

void PenaltyIda::advance_to(double t_out, const std::function<void(double)>& on_step) {
  Impl& I = *impl_;
  while (I.t_now < t_out) {
    check(IDASetStopTime(I.mem, t_out), "IDASetStopTime");
    const double t_prev = I.t_now;
    double t = t_prev;
    const int flag = IDASolve(I.mem, t_out, &t, I.yy, I.yp, IDA_ONE_STEP);
    check(flag, "IDASolve", &I.messages);
    I.t_now = t;
    if (flag == IDA_ROOT_RETURN) {
      std::vector<int> found(2 * I.nc, 0);
      check(IDAGetRootInfo(I.mem, found.data()), "IDAGetRootInfo");
      for (int i = 0; i < I.nc; ++i)
        if (found[2 * i] != 0 || found[2 * i + 1] != 0) I.switch_phase(i, t, found[2 * i] != 0);
      ++I.done.events;
      if (I.done.events > I.settings.max_events)
        throw std::runtime_error("IDA reference: more than " + std::to_string(I.settings.max_events) +
                                 " contact events (endless chatter?)");
      // Re-initialised after every root, a switch or not: IDA refuses to go on from a root
      // function that is still zero where it stopped (IDARcheck2).
      I.reinit(t);
    }
    if (on_step) on_step(t_prev);
  }
}

double PenaltyIda::t() const { return impl_->t_now; }
Eigen::Map<const Eigen::VectorXd> PenaltyIda::U() const {
  return CMap(N_VGetArrayPointer(impl_->yy), impl_->n);
}
Eigen::Map<const Eigen::VectorXd> PenaltyIda::V() const {
  return CMap(N_VGetArrayPointer(impl_->yy) + impl_->n, impl_->n);
}
ContactReading PenaltyIda::contact(int i) const { return impl_->read(i, N_VGetArrayPointer(impl_->yy)); }

namespace {
double quad(const PenaltyIda::Impl& I, int k) { return N_VGetArrayPointer(I.yy)[2 * I.n + k]; }
}  // namespace

double PenaltyIda::impulse_normal(int i) const { return quad(*impl_, 3 * i); }
double PenaltyIda::impulse_tangential(int i) const { return quad(*impl_, 3 * i + 1); }
double PenaltyIda::dissipated() const {
  double s = 0.0;
  for (int i = 0; i < impl_->nc; ++i) s += quad(*impl_, 3 * i + 2);
  return s + quad(*impl_, 3 * impl_->nc) + impl_->released_energy;
}
const std::vector<ContactEvent>& PenaltyIda::events() const { return impl_->events; }
IdaCounters PenaltyIda::counters() const { return impl_->counters_now(); }

}  // namespace beamimpact::ida
