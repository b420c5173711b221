#include <solver/contact/ContactSolver.hpp>

#include <cmath>
#include <limits>

#include <solver/contact/hertz_law.hpp>

namespace beamimpact::paper {
namespace {

/// The sign of a slipping tau: opposing the sliding the stick force Ts would have prevented
/// (when the stick solve gave Rs > 0), else opposing the predicted slide s.
double slip_direction(double Rs, double Ts, double s) {
  return Rs > 0.0 ? (Ts >= 0 ? 1.0 : -1.0) : (s > 0 ? -1.0 : 1.0);
}

}  // namespace

ContactSolver::ContactSolver(std::vector<ContactPair>& pairs, std::vector<double> mu, bool friction, int n,
                             std::vector<double> gap_tol, ApplyH apply_H)
    : pairs_(pairs),
      mu_(std::move(mu)),
      friction_(friction),
      tol_(std::move(gap_tol)),
      apply_H_(std::move(apply_H)),
      out_(pairs.size()),
      hn_(pairs.size()),
      ht_(friction ? pairs.size() : 0),
      fresh_(pairs.size(), 0),
      scratch_(Eigen::VectorXd::Zero(n)),
      gbar_(pairs.size()),
      sbar_(pairs.size()),
      active_(pairs.size()),
      candidate_(pairs.size()) {
  // Response columns of declared pairs are sized now (no allocation in the step loop); a
  // search's pairs get theirs when they first close (memory grows with the pairs that touch).
  for (std::size_t c = 0; c < pairs.size(); ++c)
    if (!pairs[c].searched()) {
      hn_[c].setZero(n);
      if (friction_) ht_[c].setZero(n);
    }
  engaged_.reserve(pairs.size());
}

void ContactSolver::set_diagonal_response(const Eigen::VectorXd* inv, double dt2) {
  h_inv_ = inv;
  h_dt2_ = dt2;
  hn_eqs_.assign(pairs_.size(), {});
  ht_eqs_.assign(friction_ ? pairs_.size() : 0, {});
  for (auto* eqs : {&hn_eqs_, &ht_eqs_})
    for (std::vector<int>& e : *eqs) e.reserve(32);  // a row's equations: no allocation while stepping
  scratch_.setZero();
  std::fill(fresh_.begin(), fresh_.end(), 0);
}

void ContactSolver::refresh_response(int c) {
  if (fresh_[c]) return;
  auto column = [&](const std::vector<DofTerm>& row, Eigen::VectorXd& out) {
    scratch_.setZero();
    for (const DofTerm& t : row) scratch_(t.eq) += t.coeff;
    if (out.size() != scratch_.size()) out.setZero(scratch_.size());
    apply_H_(scratch_, out);
  };
  // Diagonal H: only the row's equations are non-zero; the column's earlier ones are cleared.
  // Each entry is (inv_i f_i) dt^2 with f_i summed in row order, as apply_H forms it.
  auto sparse_column = [&](const std::vector<DofTerm>& row, Eigen::VectorXd& out, std::vector<int>& eqs) {
    if (out.size() != scratch_.size()) out.setZero(scratch_.size());
    for (int i : eqs) out[i] = 0.0;
    eqs.clear();
    for (const DofTerm& t : row) {
      scratch_(t.eq) += t.coeff;
      eqs.push_back(t.eq);
    }
    for (int i : eqs) out[i] = ((*h_inv_)[i] * scratch_(i)) * h_dt2_;
    for (int i : eqs) scratch_(i) = 0.0;  // scratch_ stays zero between columns
  };
  if (h_inv_) {
    sparse_column(pairs_[c].normal_row(), hn_[c], hn_eqs_[c]);
    if (friction_) sparse_column(pairs_[c].tangent_row(), ht_[c], ht_eqs_[c]);
  } else {
    column(pairs_[c].normal_row(), hn_[c]);
    if (friction_) column(pairs_[c].tangent_row(), ht_[c]);
  }
  fresh_[c] = 1;
}

const std::vector<ContactForce>& ContactSolver::solve(const Eigen::VectorXd& Ubar, const Eigen::VectorXd& U,
                                                      const Eigen::VectorXd* U_prev) {
  const int m = static_cast<int>(pairs_.size());
  any_ = false;
  engaged_.clear();
  if (boxes_) boxes_->update(Ubar);
  if (!hertz_.empty()) {  // the springs' energies at U^p; those at U^{p+1} are set by this solve
    energy_now_.swap(energy_next_);
    std::fill(energy_next_.begin(), energy_next_.end(), 0.0);
    U_prev_ = U_prev ? U_prev : &U;
  }
  for (int c = 0; c < m; ++c) predict(c, Ubar, U);
  // Gauss-Seidel over contacts: each local solve sees the others' current forces. A contact that
  // was open before the others' forces were applied joins as soon as they push it into
  // penetration (with one contact there is nothing to push: the first pass decides).
  for (int sweep = 0; sweep < (m > 1 ? 100 : 1); ++sweep) {
    double change = 0.0;
    for (int c = 0; c < m; ++c) {
      if (!active_[c] && (m == 1 || !candidate_[c])) continue;
      double g = gbar_[c], s = sbar_[c];
      add_others(c, g, s);
      if (!active_[c]) {
        if (g >= -tol_[c]) continue;  // still open with the others' forces
        active_[c] = 1;
        refresh_response(c);
        engaged_.insert(std::upper_bound(engaged_.begin(), engaged_.end(), c), c);  // keep index order
      }
      const double Ann = ContactPair::eval(pairs_[c].normal_row(), hn_[c]);
      ContactForce f;
      if (!hertz_pair(c))
        f = hard_local(c, g, s, Ann);
      else if (g < -tol_[c] || gap_prev_[c] < 0.0)
        f = hertz_local(c, g, s, Ann);
      else
        f = ContactForce{0.0, 0.0, g, s, ContactState::kOpen};
      change = std::max(change, std::abs(f.R - out_[c].R) + std::abs(f.tau - out_[c].tau));
      out_[c] = f;
    }
    if (change <= 1e-13 * (1.0 + std::abs(out_[0].R))) break;
  }
  finish_open_gaps();
  return out_;
}

void ContactSolver::predict(int c, const Eigen::VectorXd& Ubar, const Eigen::VectorXd& U) {
  // Contact search: an open searched pair whose node is outside the other body's box cannot
  // touch it within this step; it is skipped (gap reported as +inf: far).
  if (boxes_ && pairs_[c].searched() && out_[c].state == ContactState::kOpen &&
      !boxes_->near(Ubar, pairs_[c].striker_node(), pairs_[c].target_body())) {
    out_[c] = ContactForce{0.0, 0.0, std::numeric_limits<double>::infinity(), 0.0, ContactState::kOpen};
    active_[c] = candidate_[c] = 0;
    return;
  }
  // A sliding (or newly closing) striker is re-located from the predicted configuration; a
  // sticking one stays on the material point it holds.
  if (out_[c].state != ContactState::kStick && pairs_[c].relocate(Ubar)) fresh_[c] = 0;
  const ContactPair& p = pairs_[c];
  gbar_[c] = p.g0() + ContactPair::eval(p.normal_row(), Ubar);
  sbar_[c] =
      friction_ ? ContactPair::eval(p.tangent_row(), Ubar) - ContactPair::eval(p.tangent_row(), U) : 0.0;
  if (closure_slip_ == ClosureSlip::kFromClosure && friction_ && out_[c].state == ContactState::kOpen &&
      gbar_[c] < -tol_[c]) {
    // A closure step: only the slide after the closure instant (linear in time) is to be stopped.
    const double g_now = std::max(0.0, p.g0() + ContactPair::eval(p.normal_row(), U));
    sbar_[c] *= -gbar_[c] / (g_now - gbar_[c]);  // 1 - phi, phi = g_now / (g_now - gbar)
  }
  out_[c] = ContactForce{0.0, 0.0, gbar_[c], sbar_[c], ContactState::kOpen};
  active_[c] = gbar_[c] < -tol_[c] && p.on_surface();
  // A Hertz pair indenting at U^{p-1} still carries the secant force of its release (hertz_local).
  if (hertz_pair(c)) {
    gap_prev_[c] = p.g0() + ContactPair::eval(p.normal_row(), *U_prev_);
    if (gap_prev_[c] < 0.0) active_[c] = p.on_surface();
  }
  candidate_[c] = p.on_surface();
  if (active_[c]) {
    refresh_response(c);
    engaged_.push_back(c);
  }
}

void ContactSolver::add_others(int c, double& g, double& s) const {
  // The effect of the other contacts' forces on this one.
  const ContactPair& p = pairs_[c];
  for (int d : engaged_) {
    if (d == c || out_[d].state == ContactState::kOpen) continue;
    g += out_[d].R * ContactPair::eval(p.normal_row(), hn_[d]);
    if (friction_) {
      g += out_[d].tau * ContactPair::eval(p.normal_row(), ht_[d]);
      s += out_[d].R * ContactPair::eval(p.tangent_row(), hn_[d]) +
           out_[d].tau * ContactPair::eval(p.tangent_row(), ht_[d]);
    }
  }
}

ContactForce ContactSolver::hard_local(int c, double g, double s, double Ann) const {
  const ContactPair& p = pairs_[c];
  ContactForce f{0.0, 0.0, g, s, ContactState::kOpen};
  if (g >= -tol_[c]) return f;
  if (!friction_ || mu_[c] == 0.0) {
    f.R = -g / Ann;  // Eq. 20 in general form: the gap closes exactly
    f.state = friction_ ? ContactState::kSlip : ContactState::kClosed;
  } else {
    const double Ant = ContactPair::eval(p.normal_row(), ht_[c]);
    const double Atn = ContactPair::eval(p.tangent_row(), hn_[c]);
    const double Att = ContactPair::eval(p.tangent_row(), ht_[c]);
    // Stick: no relative tangential increment (Eq. 2 second line / Eq. 31).
    const double det = Ann * Att - Ant * Atn;
    const double Rs = (-g * Att + s * Ant) / det, Ts = (-s * Ann + g * Atn) / det;
    if (Rs > 0.0 && std::abs(Ts) <= mu_[c] * Rs) {
      f.R = Rs;
      f.tau = Ts;
      f.state = ContactState::kStick;
    } else {
      // Slip: tau opposes the sliding the stick force would have prevented.
      const double sigma = slip_direction(Rs, Ts, s);
      const double R = -g / (Ann + sigma * mu_[c] * Ant);
      if (R > 0.0) {
        f.R = R;
        f.tau = sigma * mu_[c] * R;
        f.state = ContactState::kSlip;
      }
    }
  }
  if (f.state != ContactState::kOpen) {
    f.gap_next = g + f.R * Ann + (friction_ ? f.tau * ContactPair::eval(p.normal_row(), ht_[c]) : 0.0);
    if (friction_)
      f.slip_next = s + f.R * ContactPair::eval(p.tangent_row(), hn_[c]) +
                    f.tau * ContactPair::eval(p.tangent_row(), ht_[c]);
  }
  return f;
}

void ContactSolver::finish_open_gaps() {
  // Gaps of contacts left open include the others' forces (for the history's gap column).
  const int m = static_cast<int>(pairs_.size());
  for (int c = 0; c < m; ++c) {
    any_ |= out_[c].state != ContactState::kOpen;
    if (out_[c].state == ContactState::kOpen && m > 1) {
      double g = gbar_[c];
      for (int d : engaged_)
        if (out_[d].state != ContactState::kOpen) {
          refresh_response(d);
          g += out_[d].R * ContactPair::eval(pairs_[c].normal_row(), hn_[d]);
          if (friction_) g += out_[d].tau * ContactPair::eval(pairs_[c].normal_row(), ht_[d]);
        }
      out_[c].gap_next = g;
    }
  }
}

ContactForce ContactSolver::hertz_local(int c, double g, double s, double Ann) {
  // The applied force is the secant of the spring's energy from the gap at U^{p-1} to the
  // corrected gap a + b R (hertz_law.hpp). Stick: tau from the tangential row
  // (s + R Atn + tau Att = 0) leaves a scalar equation; slip: tau = sigma mu R.
  const ContactPair& p = pairs_[c];
  const double k = hertz_[c], gp = gap_prev_[c];
  auto force = [&](double a, double b) { return hertz_step_force(a, b, gp, k); };
  ContactForce f{0.0, 0.0, g, s, ContactState::kOpen};
  if (!friction_ || mu_[c] == 0.0) {
    f.R = force(g, Ann);
    f.state = friction_ ? ContactState::kSlip : ContactState::kClosed;
  } else {
    const double Ant = ContactPair::eval(p.normal_row(), ht_[c]);
    const double Atn = ContactPair::eval(p.tangent_row(), hn_[c]);
    const double Att = ContactPair::eval(p.tangent_row(), ht_[c]);
    const double Rs = force(g - s * Ant / Att, Ann - Ant * Atn / Att), Ts = -(s + Rs * Atn) / Att;
    f.R = Rs;
    f.tau = Ts;
    f.state = ContactState::kStick;
    if (!(Rs > 0.0 && std::abs(Ts) <= mu_[c] * Rs)) {
      const double sigma = slip_direction(Rs, Ts, s);
      f.R = force(g, Ann + sigma * mu_[c] * Ant);
      f.tau = sigma * mu_[c] * f.R;
      f.state = ContactState::kSlip;
    }
  }
  if (!(f.R > 0.0)) {
    energy_next_[c] = 0.0;
    return ContactForce{0.0, 0.0, g, s, ContactState::kOpen};
  }
  f.gap_next = g + f.R * Ann + (friction_ ? f.tau * ContactPair::eval(p.normal_row(), ht_[c]) : 0.0);
  if (friction_)
    f.slip_next = s + f.R * ContactPair::eval(p.tangent_row(), hn_[c]) +
                  f.tau * ContactPair::eval(p.tangent_row(), ht_[c]);
  energy_next_[c] = hertz_potential(f.gap_next, k);
  return f;
}

void ContactSolver::set_hertz(std::vector<double> k) {
  hertz_ = std::move(k);
  gap_prev_.assign(hertz_.size(), 0.0);
  energy_now_.assign(hertz_.size(), 0.0);
  energy_next_.assign(hertz_.size(), 0.0);
}

double ContactSolver::hertz_energy() const {
  // The springs' energy at the mean of U^p and U^{p+1}: the work R (g^{p+1} - g^{p-1}) / 2 of
  // the secant force telescopes into it.
  double e = 0.0;
  for (std::size_t c = 0; c < hertz_.size(); ++c) e += 0.5 * (energy_now_[c] + energy_next_[c]);
  return e;
}

void ContactSolver::add_forces(Eigen::VectorXd& f, std::vector<int>* touched) const {
  auto add = [&](const std::vector<DofTerm>& row, double force) {
    for (const DofTerm& t : row) {
      f(t.eq) += t.coeff * force;
      if (touched) touched->push_back(t.eq);
    }
  };
  for (std::size_t c = 0; c < pairs_.size(); ++c) {
    if (out_[c].state == ContactState::kOpen) continue;
    add(pairs_[c].normal_row(), out_[c].R);
    if (friction_) add(pairs_[c].tangent_row(), out_[c].tau);
  }
}

}  // namespace beamimpact::paper
