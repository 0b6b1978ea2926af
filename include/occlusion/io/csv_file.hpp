#pragma once
// Comma-separated tables (RFC 4180): a header line, then rows of the same
// width. Fields holding a comma, quote or line break are quoted, quotes
// doubled. The study keeps its runs in one (a spreadsheet, pandas and a second
// run of the study all read it back), and the jobs' per-element CSV outputs
// quote their names with csv_field.

#include <string>
#include <vector>

namespace occlusion {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;  // each as wide as `columns`

  // The index of a column, or columns.size() when there is none.
  std::size_t column(const std::string& name) const;
};

// A field as written: quoted only when it must be.
std::string csv_field(const std::string& text);

// InputError naming the 1-based line for an unterminated quote, text after a
// closing quote, or a row whose width differs from the header's; and for a
// file without a header. CRLF line ends and a UTF-8 byte-order mark are accepted.
CsvTable read_csv(const std::string& path);

// Written atomically (atomic_file.hpp): a reader never sees half a table.
// std::invalid_argument for a row whose width differs from the header's.
void write_csv(const std::string& path, const CsvTable& table);

}  // namespace occlusion
