#include "core/io/CsvWriter.hpp"

#include "core/io/AtomicFile.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace contactlab {
namespace {

// Quotes only when needed so that plain numeric tables stay trivially parsable.
std::string quoted(const std::string& cell) {
  if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
  std::string out = "\"";
  for (const char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

void appendLine(std::string& out, const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i)
    out += (i ? "," : "") + quoted(cells[i]);
  out += '\n';
}

}  // namespace

CsvWriter::CsvWriter(std::vector<std::string> columns) : columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("a CSV table needs at least one column");
}

std::string CsvWriter::format(double value) {
  if (std::isnan(value)) return "";  // not defined (e.g. an unpaired point's gap): an empty cell
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

void CsvWriter::addRow(const std::vector<double>& values) {
  std::vector<std::string> cells;
  cells.reserve(values.size());
  for (const double v : values)
    cells.push_back(format(v));
  addFormattedRow(std::move(cells));
}

void CsvWriter::addFormattedRow(std::vector<std::string> cells) {
  if (cells.size() != columns_.size())
    throw std::invalid_argument("CSV row has " + std::to_string(cells.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns (first column '" +
                                columns_.front() + "')");
  rows_.push_back(std::move(cells));
}

std::string CsvWriter::str() const {
  std::string out;
  appendLine(out, columns_);
  for (const auto& row : rows_)
    appendLine(out, row);
  return out;
}

void CsvWriter::write(const std::string& path) const {
  writeFileAtomically(path, [&](std::ostream& out) { out << str(); });
}

}  // namespace contactlab
