#pragma once
// A small CSV table (steps.csv, contact.csv): a header, rows kept in memory, the whole file
// rewritten atomically by write(). Numbers keep full double precision so that scripts can
// compare results bit for bit; NaN (a value not defined, e.g. an unpaired point's gap) is
// written as an empty cell, infinities as "inf"/"-inf".
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace contactlab {

class CsvWriter {
 public:
  explicit CsvWriter(std::vector<std::string> columns);

  // One row of numbers and/or strings, one per column: addRow(1, 0.5, "slip", nan).
  // Throws std::invalid_argument if the number of values differs from the number of columns.
  template <class... Values>
  void addRow(const Values&... values) {
    addFormattedRow({format(values)...});
  }
  void addRow(const std::vector<double>& values);
  // Cells already formatted (and not yet quoted), e.g. built in a loop.
  void addFormattedRow(std::vector<std::string> cells);

  // Cell text for a value: integers exactly, doubles with 17 significant digits ("%.17g").
  static std::string format(double value);
  static std::string format(const std::string& text) { return text; }
  static std::string format(const char* text) { return text; }
  template <class Int, class = std::enable_if_t<std::is_integral_v<Int>>>
  static std::string format(Int value) {
    if constexpr (std::is_same_v<Int, bool>)
      return value ? "1" : "0";
    else
      return std::to_string(value);
  }

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t numRows() const { return rows_.size(); }
  std::string str() const;  // the whole table, RFC 4180 quoting where needed
  // Rewrites `path` with the header and every row so far (atomically, parents created).
  void write(const std::string& path) const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace contactlab
