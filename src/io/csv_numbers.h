// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: a CSV file of numbers (a header line naming the columns, then one row of
// finite numbers per non-empty line), with errors that name the file and the line.
// Shared by the planar (x,y,r) and surface (x,y,z,r) sample readers and writers;
// implemented in points_csv.cpp.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

namespace disktune::detail {

struct CsvNumbers {
  std::string header;              // the accepted header that matched
  std::size_t columns = 0;         // numbers per row (the header's names)
  std::vector<double> values;      // row after row
  std::vector<std::size_t> lines;  // each row's line number in the file (the header is 1)
  std::size_t rows() const { return lines.size(); }
  double at(std::size_t row, std::size_t column) const { return values[row * columns + column]; }
};

/// Reads `path`, whose first line must be one of `headers` (comma-separated column
/// names, e.g. {"x,y,z,r", "x,y,z"}); every other non-empty line must hold exactly as
/// many finite numbers as that header names. Throws IoError when the file cannot be
/// read and InvalidInput "PATH:LINE: ..." when its content is wrong.
CsvNumbers read_csv_numbers(const std::string& path, const std::vector<std::string>& headers);

/// Writes one row: the numbers comma-separated (each in the shortest form that reads
/// back the same), then a line end.
void put_csv_row(std::ostream& out, std::initializer_list<double> values);

}  // namespace disktune::detail
