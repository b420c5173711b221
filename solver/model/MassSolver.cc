#include <solver/model/MassSolver.hpp>

#include <stdexcept>

namespace beamimpact {

MassSolver::MassSolver(const Model& model) {
  if (model.lumped()) {
    if ((model.lumped_mass().array() <= 0.0).any())
      throw std::runtime_error("lumped mass has a zero or negative entry");
    inv_ = model.lumped_mass().cwiseInverse();
  } else {
    ldlt_ = std::make_unique<Eigen::SimplicialLDLT<SparseMatrix>>();
    factorize_pattern(model.M());
  }
}

void MassSolver::factorize_pattern(const SparseMatrix& M) {
  ldlt_->compute(M);
  if (ldlt_->info() != Eigen::Success) throw std::runtime_error("consistent mass matrix is singular");
  pattern_nnz_ = M.nonZeros();
  pattern_rows_ = M.rows();
}

void MassSolver::refactor(const SparseMatrix& M) {
  if (M.rows() != pattern_rows_ || M.nonZeros() != pattern_nnz_)
    throw std::logic_error(
        "MassSolver::refactor: the mass has another sparsity pattern than the one analysed; "
        "call factorize_pattern() first");
  ldlt_->factorize(M);
  if (ldlt_->info() != Eigen::Success) throw std::runtime_error("consistent mass matrix became singular");
}

void MassSolver::apply(const Eigen::VectorXd& in, Eigen::VectorXd& out) const {
  if (ldlt_)
    out = ldlt_->solve(in);
  else
    out.noalias() = inv_.cwiseProduct(in);
}

}  // namespace beamimpact
