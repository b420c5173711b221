#include <verification/jobs/Table.hpp>

#include <stdexcept>

namespace beamimpact::jobs {
namespace {

std::string markdown_line(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const auto& c : cells) {
    line += ' ';
    for (char ch : c) line += ch == '|' ? std::string("\\|") : std::string(1, ch);
    line += " |";
  }
  return line + "\n";
}

std::string csv_cell(const std::string& c, bool quoted) {
  if (!quoted && c.find_first_of(",\"\n\r") == std::string::npos) return c;
  std::string q = "\"";
  for (char ch : c)
    q += ch == '"' ? std::string("\"\"") : std::string(1, ch == '\n' || ch == '\r' ? ' ' : ch);
  return q + "\"";
}

}  // namespace

Table& Table::add(std::vector<std::string> cells) {
  if (cells.size() != header_.size())
    throw std::logic_error("Table: a row of " + std::to_string(cells.size()) + " cells under " +
                           std::to_string(header_.size()) + " columns");
  rows_.push_back(std::move(cells));
  return *this;
}

std::string Table::markdown() const {
  std::string m = markdown_line(header_) + "|";
  for (std::size_t i = 0; i < header_.size(); ++i) m += "---|";
  m += "\n";
  for (const auto& r : rows_) m += markdown_line(r);
  return m;
}

std::string Table::csv() const {
  std::string out;
  auto line = [&](const std::vector<std::string>& cells, bool header) {
    for (std::size_t i = 0; i < cells.size(); ++i)
      out += (i ? "," : "") + csv_cell(cells[i], !header && quoted_.count(i) > 0);
    out += "\n";
  };
  line(header_, true);
  for (const auto& r : rows_) line(r, false);
  return out;
}

}  // namespace beamimpact::jobs
