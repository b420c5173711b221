#pragma once
/// @file step_mean_rows.hpp
/// @brief IDA's history rows with the contact forces of the protocol: the row at t_k carries,
/// for each contact, the mean normal and tangential force over the output step it begins,
/// (J(t_k+1) - J(t_k)) / (t_k+1 - t_k), J the impulse IDA integrates under its own error control:
/// the convention of the paper integrator's rows (docs/protocol.md, "The time R belongs to"). The
/// rows' integral is then the run's impulse, and the penalty dashpot's jump at a first touch
/// (cn times the closing speed, a force far above any the bodies carry) shows only through the
/// impulse it transmits. Every other column is the state at t_k; the last row, which begins no
/// step, keeps the forces at its own time. The same rows give the summary's peaks.

#include <array>
#include <optional>
#include <vector>

#include <solver/record/ResultRecorder.hpp>

namespace beamimpact::ida {

/// @brief One contact's force peaks over the finished rows (N).
struct RowPeaks {
  double all = 0.0;              ///< the largest row force: summary peak_R
  double outside_closure = 0.0;  ///< the largest force of a row whose step meets no closure window
  double first_closure = 0.0;    ///< the force of the first row in contact: summary first_step_R
};

/// @brief Holds each output row until the next output time is reached, then writes its step
/// means and hands it to the recorder.
class StepMeanRows {
 public:
  /// @param rec the run's recorder (add_row)
  /// @param closure_windows per contact, the time after each onset that a closure's transient
  ///        lasts (s): a row whose step meets one is left out of RowPeaks::outside_closure
  StepMeanRows(ResultRecorder& rec, std::vector<double> closure_windows);

  /// @brief Contact i was closed at some instant of the current output step (an accepted step or
  /// an event of IDA): only then does its mean come from the impulses (else it is 0 exactly, not
  /// the quadrature's roundoff).
  void touch(int i) { touched_[i] = 1; }

  /// @brief The row at the next output time, with each contact's impulses (normal, tangential:
  /// N s, IDA's running quadratures at row.t) and each contact's onsets so far (s). Finishes the
  /// row before it.
  void add(HistoryRow row, const std::vector<std::array<double, 2>>& impulses,
           const std::vector<std::vector<double>>& onsets);

  /// @brief Hands the last row over with its forces at its own time. Call once, after the last add.
  void finish(const std::vector<std::vector<double>>& onsets);

  /// @brief Each contact's peaks over the rows handed over.
  const std::vector<RowPeaks>& peaks() const { return peaks_; }

 private:
  void hand_over(double t_next, const std::vector<std::vector<double>>& onsets);

  ResultRecorder& rec_;
  std::vector<double> windows_;
  std::optional<HistoryRow> pending_;
  std::vector<std::array<double, 2>> impulses_;  ///< at the pending row's time
  std::vector<char> touched_;
  std::vector<RowPeaks> peaks_;
};

}  // namespace beamimpact::ida
