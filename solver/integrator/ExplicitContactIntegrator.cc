#include <solver/integrator/ExplicitContactIntegrator.hpp>

#include <algorithm>
#include <thread>

#include <solver/model/load_vector.hpp>
#include <solver/util/available_cores.hpp>

namespace beamimpact::paper {
namespace {

/// Per pair: the Coulomb coefficient of its scene contact.
std::vector<double> frictions(const Scene& scene, const std::vector<int>& contact_of_pair) {
  std::vector<double> mu;
  for (int c : contact_of_pair) mu.push_back(scene.contacts[c].friction);
  return mu;
}

/// Per contact: 1e-10 of the larger element length of the two bodies in contact. Above the
/// roundoff of positions (~1e-15 relative), far below any physical penetration per step, and
/// blind to bodies that take no part in the contact.
std::vector<double> gap_tolerances(const Scene& scene, const std::vector<int>& contact_of_pair) {
  std::vector<double> tol;
  for (int k : contact_of_pair) {
    const Contact& c = scene.contacts[k];
    const Body& a = scene.bodies[c.striker];
    const Body& b = scene.bodies[c.target];
    tol.push_back(1e-10 * std::max(a.length() / a.elements, b.length() / b.elements));
  }
  return tol;
}

/// The search boxes of a scene with node = "all" contacts (nullptr without): the bodies of those
/// contacts, each inflated by its element length.
std::unique_ptr<SearchBoxes> search_boxes(const Model& model, const Scene& scene) {
  std::vector<char> boxed(scene.bodies.size(), 0);
  std::vector<double> margin(scene.bodies.size(), 0.0);
  bool any = false;
  for (const Contact& c : scene.contacts)
    if (c.search) {
      any = true;
      for (int b : {c.striker, c.target}) {
        boxed[b] = 1;
        margin[b] = scene.bodies[b].length() / scene.bodies[b].elements;
      }
    }
  return any ? std::make_unique<SearchBoxes>(model, boxed, margin) : nullptr;
}

/// One equation of the fused update: Vbar^{p+1} = vb_old + inv w2 (w2 the force sum of the
/// velocity line times dt), then the next prediction ub = (un + dt Vbar^{p+1}) + dt^2/2 inv (-fn).
inline void fused_entry(int i, double vb_old, double w2, double dt, const double* un, const double* fn,
                        const double* inv, double* vb, double* ub) {
  const double vbar = vb_old + inv[i] * w2;
  vb[i] = vbar;
  ub[i] = (un[i] + dt * vbar) + (0.5 * dt * dt) * (inv[i] * -fn[i]);
}

/// The fused update on equations [lo, hi) without contact force (the vectors do not overlap).
void velocity_sweep(int lo, int hi, double dt, const double* __restrict un, const double* __restrict fn,
                    const double* __restrict fu, const double* __restrict inv, double* __restrict vb,
                    double* __restrict ub) {
  for (int i = lo; i < hi; ++i) fused_entry(i, vb[i], (-0.5 * dt) * (fn[i] + fu[i]), dt, un, fn, inv, vb, ub);
}

/// The fused step (advance_fused) serves a lumped, undamped run: a fixed diagonal mass (a
/// consistent mass, rotating or not, is never lumped) and no damper force in the update. Only that
/// step is split over threads.
bool fused_step(const Model& model, bool damped) { return model.lumped() && !damped; }

}  // namespace

int default_threads(int dofs) {
  if (dofs < kThreadsMinDofs) return 1;
  return available_cores().count;
}

ExplicitContactIntegrator::ExplicitContactIntegrator(const Model& model, const Scene& scene,
                                                     const Effects& effects, double dt,
                                                     SurfaceInterpolation surface, int threads)
    : model_(model),
      dt_(dt),
      damped_(effects.damping && model.damped()),
      friction_(effects.friction),
      minv_(model),
      fint_(model, effects.corotational ? effects.rotating : std::vector<bool>(scene.bodies.size(), false),
            fused_step(model, damped_) ? threads : 1),
      search_(make_contact_pairs(model, scene, surface)),
      boxes_(search_boxes(model, scene)),
      solver_(search_.pairs, frictions(scene, search_.contact), effects.friction, model.size(),
              gap_tolerances(scene, search_.contact),
              [this](const Eigen::VectorXd& f, Eigen::VectorXd& out) { apply_H(f, out); }),
      load_(effects.loads ? load_vector(model, scene) : Eigen::VectorXd()) {
  solver_.set_search_boxes(boxes_.get());
  if (std::any_of(scene.contacts.begin(), scene.contacts.end(),
                  [](const Contact& c) { return c.law == ContactLaw::kHertz; })) {
    std::vector<double> k;
    for (int c : search_.contact) k.push_back(scene.contacts[c].hertz_stiffness);
    solver_.set_hertz(std::move(k));
    hertz_ = true;
  }
  if (!model.lumped() && fint_.nonlinear()) {
    cmass_ = std::make_unique<CorotationalMass>(model, fint_);
    minv_.factorize_pattern(cmass_->M());  // M_A(t) may hold entries the model's M never stored
  }
  const int n = model.size();
  for (Eigen::VectorXd* v : {&U_, &U_next_, &Ubar_, &fc_, &work_, &work2_, &vwork_, &fint_U_, &fint_next_})
    v->setZero(n);
  if (damped_)  // the damper's work vectors (an undamped run never reads them)
    for (Eigen::VectorXd* v : {&du_, &scratch_, &hwork_, &c_du_, &c_z_}) v->setZero(n);
  Vbar_ = model.initial_velocity();  // no contact force at t = 0: Vbar^0 = V^0
  V_ = Vbar_;
  net_force(U_, fint_U_);
  fused_ = fused_step(model, damped_);
  // Lumped and undamped, and no consistent mass that follows the rotation: dt^2 H is diagonal.
  if (fused_ && !cmass_) solver_.set_diagonal_response(&minv_.inverse_diagonal(), dt_ * dt_);
  start_team(threads);
  // Each momentum covector's support: its dot product reads only the equations of its body.
  for (int b = 0; b < model.num_bodies(); ++b)
    for (int c = 0; c < 2; ++c) {
      const Eigen::VectorXd& p = model.momentum_covector(b, c);
      long long lo = 0, hi = p.size();
      while (lo < hi && p[lo] == 0.0) ++lo;
      while (hi > lo && p[hi - 1] == 0.0) --hi;
      momentum_support_.push_back({lo, hi});
    }
  // Room for every equation a contact force can touch (a surface contact's rows move with the
  // struck point, so their size now is no bound): no allocation while stepping.
  fc_dofs_.reserve(solver_.max_touched());
  vbar_saved_.reserve(solver_.max_touched());
  initial_energy_ = kinetic_energy() + strain_energy();  // no contact force solved yet: V = Vbar^0
  // The step before the first, U^{-1} = U^0 - dt Vbar^0 (exact for central differences from rest,
  // K U^0 = 0): a contact closing in the first step books its work from there, as every later
  // closure does from U^{p-1} (with U^{-1} = U^0 it booked 0.0045 J of S1's 0.05 J closure loss).
  U_prev_ = U_ - dt_ * Vbar_;
  solve_contacts();  // step 0 complete
}

void ExplicitContactIntegrator::subtract_damping_force(const Eigen::VectorXd& v, Eigen::VectorXd& f) {
  // f -= C v with C = a0 M + a1 K, through a scratch vector (no allocation).
  scratch_.noalias() = mass() * v;
  f -= model_.rayleigh_mass() * scratch_;
  scratch_.noalias() = fint_.linear_stiffness() * v;
  f -= model_.rayleigh_stiffness() * scratch_;
}

void ExplicitContactIntegrator::apply_H(const Eigen::VectorXd& f, Eigen::VectorXd& out) {
  // out = dt^2 H f = dt^2 M^-1 (f - dt/4 C M^-1 f), C = a0 M + a1 K.
  apply_Minv(f, out);
  if (damped_) {
    // C M^-1 f = a0 f + a1 K M^-1 f
    scratch_.noalias() = fint_.linear_stiffness() * out;
    hwork_.noalias() = model_.rayleigh_mass() * f + model_.rayleigh_stiffness() * scratch_;
    apply_Minv(hwork_, scratch_);
    out -= 0.25 * dt_ * scratch_;
  }
  out *= dt_ * dt_;
}

void ExplicitContactIntegrator::solve_contacts() {
  if (cmass_) {  // Eq. 22: the rotating body's consistent mass follows its element frames
    cmass_->update(U_);
    minv_.refactor(cmass_->M());
    solver_.invalidate();
  }
  // Contact-free prediction of U^{p+1}.
  work2_ = -fint_U_;
  if (damped_) subtract_damping_force(Vbar_, work2_);
  apply_Minv(work2_, work_);
  Ubar_.noalias() = U_ + dt_ * Vbar_ + (0.5 * dt_ * dt_) * work_;

  resolve_contacts();
}

void ExplicitContactIntegrator::resolve_contacts() {
  solver_.solve(Ubar_, U_, &U_prev_);
  if (hertz_) {
    // The contact work below counts what the bodies put into the Hertz springs: the change of
    // their energy is taken back out of the dissipated energy. The secant force's work is that
    // change exactly (hertz_law.hpp): a frictionless Hertz contact leaves dissipated unchanged.
    const double e = solver_.hertz_energy();
    dissipated_ -= e - hertz_energy_;
    hertz_energy_ = e;
  }
  v_stale_ = solver_.any_force();  // V^p = Vbar^p unless a contact force acts; formed on demand
  if (solver_.any_force()) {
    if (fused_) {
      gather_contact_force();
    } else {
      fc_.setZero();
      solver_.add_forces(fc_);
    }
    if (damped_) {
      book_damper_contact_share();  // the last step's damper at V^p's contact part
      // and the contact's work on the damper's part of the last step's displacement,
      // dt/4 f_c^p . M^-1 C z^{p-1} (damper_strain_share; hwork_ = M^-1 f_c^p from the call above)
      dissipated_ -= 0.25 * dt_ * hwork_.dot(c_z_);
    }
    // Contact work of step p: f_c . (U^{p+1} - U^{p-1}) / 2 with this step's rows, i.e.
    // R (g_{p+1} - g_{p-1})/2 + tau (s_{p+1} - s_{p-1})/2. It is the exact change of the discrete
    // energy 1/2 v_{p+1/2} M v_{p+1/2} + 1/2 u_p K u_{p+1} (linear kinematics).
    for (std::size_t c = 0; c < search_.pairs.size(); ++c) {
      const ContactForce& f = solver_.forces()[c];
      if (f.state == ContactState::kOpen) continue;
      const ContactPair& pc = search_.pairs[c];
      const double g_prev = pc.g0() + ContactPair::eval(pc.normal_row(), U_prev_);
      dissipated_ -= 0.5 * f.R * (f.gap_next - g_prev);
      if (friction_) {
        const double s_now = ContactPair::eval(pc.tangent_row(), U_),
                     s_prev = ContactPair::eval(pc.tangent_row(), U_prev_);
        dissipated_ -= 0.5 * f.tau * (f.slip_next + s_now - s_prev);
      }
    }
  }
}

void ExplicitContactIntegrator::advance() {
  // U^{p+1} = Ubar + dt^2 H f_c
  U_next_ = Ubar_;
  if (solver_.any_force()) {
    apply_H(fc_, work_);
    U_next_ += work_;
  }
  net_force(U_next_, fint_next_);
  // Vbar^{p+1} = Vbar^p + M^-1 (-dt/2 (f(U^{p+1}) + f(U^p)) - C (U^{p+1} - U^p) + dt f_c)
  work2_.noalias() = (-0.5 * dt_) * (fint_next_ + fint_U_);
  if (solver_.any_force()) work2_.noalias() += dt_ * fc_;
  double damper_work = 0.0;
  if (damped_) {
    // The paper's velocity line replaces C (V^p + V^{p+1}) dt/2 by C (U^{p+1} - U^p). The damper's
    // share of the kinetic energy 1/2 Vbar M Vbar is then exactly (Vbar^p + Vbar^{p+1})/2 . C du:
    // booked below (du^T C du / dt, at the half-step velocity, under-counted it by 7.7 % at
    // a0 dt = 0.5). The reported kinetic energy is the physical velocity's: the damper takes
    // (V^p + V^{p+1})/2 . C du from it, V = Vbar + dt/2 M^-1 f_c. The f_c^p part is booked here,
    // the f_c^{p+1} part once it is solved (book_damper_contact_share).
    du_.noalias() = U_next_ - U_;
    c_du_.setZero();
    subtract_damping_force(du_, c_du_);  // c_du_ = -C du
    work2_ += c_du_;
    damper_work = -0.5 * Vbar_.dot(c_du_) + damper_strain_share();
    if (solver_.any_force()) book_damper_contact_share();
  }
  apply_Minv(work2_, work_);
  Vbar_ += work_;
  if (damped_) dissipated_ += damper_work - 0.5 * Vbar_.dot(c_du_);
  std::swap(U_prev_, U_);
  std::swap(U_, U_next_);
  std::swap(fint_U_, fint_next_);
  ++p_;
}

void ExplicitContactIntegrator::advance_fused() {
  const double* inv = minv_.inverse_diagonal().data();
  const double dt = dt_, dt2 = dt_ * dt_, m_half_dt = -0.5 * dt_;
  const bool force = solver_.any_force();
  // U^{p+1} = Ubar + dt^2 M^-1 f_c (apply_H undamped: (inv fc) dt^2). f_c is zero outside
  // fc_dofs_, where U^{p+1} is Ubar itself, whose buffer the prediction below overwrites: swap
  // instead of copying, then add the force at its equations.
  U_next_.swap(Ubar_);
  if (force)
    for (int i : fc_dofs_) U_next_[i] = U_next_[i] + (inv[i] * fc_[i]) * dt2;
  // One sweep: f(U^{p+1}) and, on each range of equations as soon as f is final there,
  // Vbar^{p+1} = Vbar^p + inv (-dt/2 (f(U^{p+1}) + f(U^p)) + dt f_c), then the next step's
  // prediction Ubar = U^{p+1} + dt Vbar^{p+1} + dt^2/2 inv (-f(U^{p+1})).
  const double* un = U_next_.data();
  const double* fn = fint_next_.data();
  const double* fu = fint_U_.data();
  double* vb = Vbar_.data();
  double* ub = Ubar_.data();
  if (force) {  // the sweep below leaves out f_c; the contact equations are redone after it
    vbar_saved_.resize(fc_dofs_.size());
    for (std::size_t k = 0; k < fc_dofs_.size(); ++k) vbar_saved_[k] = vb[fc_dofs_[k]];
  }
  if (load_.size()) {  // f_int - F^P on each range before the sweep reads it
    double* fnet = fint_next_.data();
    const double* F = load_.data();
    sweep_f_int([=](int lo, int hi) {
      for (int i = lo; i < hi; ++i) fnet[i] -= F[i];
      velocity_sweep(lo, hi, dt, un, fn, fu, inv, vb, ub);
    });
  } else {
    sweep_f_int([=](int lo, int hi) { velocity_sweep(lo, hi, dt, un, fn, fu, inv, vb, ub); });
  }
  if (force)
    for (std::size_t k = 0; k < fc_dofs_.size(); ++k) {
      const int i = fc_dofs_[k];
      double w2 = m_half_dt * (fn[i] + fu[i]);
      w2 += dt * fc_[i];
      fused_entry(i, vbar_saved_[k], w2, dt, un, fn, inv, vb, ub);
    }
  std::swap(U_prev_, U_);
  std::swap(U_, U_next_);
  std::swap(fint_U_, fint_next_);
  ++p_;
}

int ExplicitContactIntegrator::set_threads(int threads) {
  if (threads > 1 && fused_) fint_.set_parts(threads);
  return start_team(threads);
}

int ExplicitContactIntegrator::start_team(int threads) {
  team_.reset();
  threads_note_.clear();
  if (threads <= 1) return 1;
  if (!fused_) {
    threads_note_ =
        "one thread: only the lumped, undamped, linear step is split over threads (this run has " +
        std::string(damped_  ? "damping"
                    : cmass_ ? "a consistent mass that rotates"
                             : "a consistent mass") +
        ")";
    return 1;
  }
  const int used = fint_.parts();
  if (used < threads) {
    threads_note_ = used == 1 ? "one thread: the element product is not split here (corotational bodies, a "
                                "sparse product, or fewer than two elements per thread)"
                              : "fewer threads: two elements per thread at least";
    if (used == 1) return 1;
  }
  team_ = std::make_unique<ThreadTeam>(used);
  return used;
}

double ExplicitContactIntegrator::damper_strain_share() {
  // The step's strain change is (f(U^p) + f(U^{p+1}))/2 . du, the velocity line moves U by
  // dt (V^p + V^{p+1})/2; of their difference the damper's part is dt/2 M^-1 C z, z = du - dt V^p
  // (z = dt^2/2 a^p). Its strain work dt/4 (f(U^p) + f(U^{p+1})) . M^-1 C z is energy the damper
  // took too (0 for mass damping on free bodies; the rest of the difference telescopes).
  hwork_ = du_ - dt_ * Vbar_;
  if (solver_.any_force()) {
    apply_Minv(fc_, scratch_);
    hwork_ -= (0.5 * dt_ * dt_) * scratch_;
  }
  work_.setZero();
  subtract_damping_force(hwork_, work_);  // -C z
  c_z_ = work_;                           // for the next step's contact force (resolve_contacts)
  apply_Minv(work_, hwork_);
  double share = 0.25 * dt_ * (fint_U_ + fint_next_).dot(hwork_);
  // The contact force's work is booked on (U^{p+1} - U^{p-1})/2, whose damper part differs from
  // the contact's power at the physical velocity by dt/4 f_c^p . M^-1 C (z^p + z^{p-1}): energy the
  // damper took, first order in dt at a closure (f_c ~ impulse / dt, z^p ~ dt^2/2 M^-1 f_c) and
  // 0.21 % of E0 on s2_damped (a1 = 0.1 s) when left out. The z^p half here, z^{p-1} once
  // f_c^p is solved.
  if (solver_.any_force()) share -= 0.25 * dt_ * fc_.dot(hwork_);
  return share;
}

void ExplicitContactIntegrator::book_damper_contact_share() {
  // dt/4 (M^-1 f_c) . C du with c_du_ = -C du of the last step (zero before the first step).
  apply_Minv(fc_, hwork_);
  dissipated_ -= 0.25 * dt_ * hwork_.dot(c_du_);
}

void ExplicitContactIntegrator::form_velocity() const {
  if (fused_ && !cmass_) {  // M^-1 diagonal: entry by entry on the team
    run_ranges(team_.get(), static_cast<int>(V_.size()),
               [&](long long first, long long last) { form_velocity_range(first, last); });
  } else {
    apply_Minv(fc_, vwork_);
    V_.noalias() = Vbar_ + (0.5 * dt_) * vwork_;
  }
  v_stale_ = false;
}

void ExplicitContactIntegrator::form_velocity_range(long long first, long long last) const {
  // V_i = Vbar_i + dt/2 (M^-1 f_c)_i, as velocity_along() forms one entry.
  const long long n = last - first;
  V_.segment(first, n) =
      Vbar_.segment(first, n) +
      (0.5 * dt_) * minv_.inverse_diagonal().segment(first, n).cwiseProduct(fc_.segment(first, n));
}

void ExplicitContactIntegrator::gather_contact_force() {
  for (int i : fc_dofs_) fc_[i] = 0.0;
  fc_dofs_.clear();
  solver_.add_forces(fc_, &fc_dofs_);
  std::sort(fc_dofs_.begin(), fc_dofs_.end());  // each equation once (add_forces summed them)
  fc_dofs_.erase(std::unique(fc_dofs_.begin(), fc_dofs_.end()), fc_dofs_.end());
}

double ExplicitContactIntegrator::kinetic_terms(const Eigen::VectorXd& v, long long first,
                                                long long last) const {
  const auto vs = v.segment(first, last - first);
  return vs.dot(model_.lumped_mass().segment(first, last - first).cwiseProduct(vs));
}

double ExplicitContactIntegrator::strain_terms(long long first, long long last) const {
  const auto u = U_.segment(first, last - first);
  double s = u.dot(fint_U_.segment(first, last - first));
  if (load_.size()) s += u.dot(load_.segment(first, last - first));
  return s;
}

double ExplicitContactIntegrator::momentum_terms(const Eigen::VectorXd& v, int b, int c, long long first,
                                                 long long last) const {
  const long long lo = std::max(first, momentum_support_[2 * b + c][0]);
  const long long hi = std::min(last, momentum_support_[2 * b + c][1]);
  if (hi <= lo) return 0.0;
  return model_.momentum_covector(b, c).segment(lo, hi - lo).dot(v.segment(lo, hi - lo));
}

double ExplicitContactIntegrator::kinetic_energy() const {
  const Eigen::VectorXd& v = V();
  if (!model_.lumped()) return 0.5 * v.dot(mass() * v);
  return 0.5 * ordered_sum(team_.get(), v.size(), sum_chunks_,
                           [&](long long first, long long last) { return kinetic_terms(v, first, last); });
}

double ExplicitContactIntegrator::velocity_along(const std::vector<DofTerm>& row) const {
  if (!fused_ || !v_stale_) return ContactPair::eval(row, V());
  // V_i = Vbar_i + dt/2 (M^-1 f_c)_i, each entry as form_velocity() forms it (M^-1 diagonal).
  const Eigen::VectorXd& inv = minv_.inverse_diagonal();
  const double h = 0.5 * dt_;
  double s = 0.0;
  for (const DofTerm& t : row) s += t.coeff * (Vbar_[t.eq] + h * (inv[t.eq] * fc_[t.eq]));
  return s;
}

double ExplicitContactIntegrator::strain_energy() const {
  // Not fused, or corotational: one thread (start_team: no team, or fint_ not split).
  if (!fused_ || fint_.nonlinear()) return fint_.strain_energy(U_);
  // Linear elements: the step has formed f_int(U^p) - F^P already (fint_U_), so 1/2 U^T K U is a
  // dot product with it, not a second product with K.
  return 0.5 * ordered_sum(team_.get(), U_.size(), sum_chunks_,
                           [&](long long first, long long last) { return strain_terms(first, last); });
}

double ExplicitContactIntegrator::momentum(int b, int c) const {
  const Eigen::VectorXd& v = V();
  if (cmass_) return cmass_->momentum(b, c, v);
  // The chunks of every sum over the equations (not of the support alone): row_sums() gives the
  // same bits.
  return ordered_sum(team_.get(), v.size(), sum_chunks_,
                     [&](long long first, long long last) { return momentum_terms(v, b, c, first, last); });
}

ExplicitContactIntegrator::RowSums ExplicitContactIntegrator::row_sums() const {
  RowSums r;
  const int bodies = model_.num_bodies();
  if (!fused_ || cmass_ || fint_.nonlinear()) {
    r.kinetic = kinetic_energy();
    r.strain = strain_energy();
    for (int b = 0; b < bodies; ++b)
      for (int c = 0; c < 2; ++c) r.momentum[c] += momentum(b, c);
    return r;
  }
  // V^p, when a contact force acts and it is still to be formed, is formed chunk by chunk in the
  // same pass: each chunk writes its entries, then sums them while they are in cache.
  const bool form = solver_.any_force() && v_stale_;
  const Eigen::VectorXd& v = solver_.any_force() ? V_ : Vbar_;
  const int width = 2 + 2 * bodies;
  row_totals_.resize(static_cast<std::size_t>(width));
  ordered_sums(team_.get(), U_.size(), width, sum_chunks_, row_totals_.data(),
               [&](long long first, long long last, double* out) {
                 if (form) form_velocity_range(first, last);
                 out[0] = kinetic_terms(v, first, last);
                 out[1] = strain_terms(first, last);
                 for (int b = 0; b < bodies; ++b)
                   for (int c = 0; c < 2; ++c) out[2 + 2 * b + c] = momentum_terms(v, b, c, first, last);
               });
  if (form) v_stale_ = false;
  r.kinetic = 0.5 * row_totals_[0];
  r.strain = 0.5 * row_totals_[1];
  for (int b = 0; b < bodies; ++b)
    for (int c = 0; c < 2; ++c) r.momentum[c] += row_totals_[2 + 2 * b + c];
  return r;
}

}  // namespace beamimpact::paper
