#pragma once
/// @file Table.hpp
/// @brief The one table model behind every table the verification writes: report.md's gate,
/// order and Richardson tables, sweep.md and sweep.csv, study.md, study.csv and timing.csv. A
/// writer formats each cell (its number format, its units in the header) and the table renders
/// it as Markdown or CSV.

#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace beamimpact::jobs {

/// @brief Rows of text cells under a header.
class Table {
 public:
  /// @brief header: the column names (with units, "dt (s)").
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}

  /// @brief Appends a row; throws std::logic_error when it has not one cell per column.
  Table& add(std::vector<std::string> cells);

  /// @brief CSV: every cell of this column quoted (free text such as a message), not only the
  /// cells that need it.
  Table& quote_column(std::size_t column) {
    quoted_.insert(column);
    return *this;
  }

  /// @brief The number of rows.
  std::size_t rows() const { return rows_.size(); }

  /// @brief Markdown: "| a | b |", the rule "|---|---|", one line per row; a '|' in a cell is
  /// escaped ("\|") so that it cannot split the cell.
  std::string markdown() const;

  /// @brief CSV: the header line, one line per row; a cell holding ',', '"' or a line break (or
  /// in a quoted column) is quoted with '"' doubled, a line break read as a space.
  std::string csv() const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::set<std::size_t> quoted_;
};

}  // namespace beamimpact::jobs
