#include "occlusion/io/csv_file.hpp"

#include <algorithm>
#include <stdexcept>

#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {

namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// Reads records field by field; a quoted field may span lines, so records and
// lines are counted apart (errors name the line where the record starts).
class CsvParser {
 public:
  CsvParser(const std::string& path, std::string_view text) : path_(path), text_(text) {
    if (text_.substr(0, kByteOrderMark.size()) == kByteOrderMark) {
      text_.remove_prefix(kByteOrderMark.size());
    }
  }

  bool next(std::vector<std::string>& record) {
    record.clear();
    // A trailing line end, or blank lines, end no record.
    while (position_ < text_.size() && (text_[position_] == '\n' || text_[position_] == '\r')) {
      if (text_[position_] == '\n') ++line_;
      ++position_;
    }
    if (position_ >= text_.size()) return false;
    record_line_ = line_;
    for (;;) {
      record.push_back(field());
      if (position_ >= text_.size()) return true;
      const char c = text_[position_++];
      if (c == ',') continue;
      if (c == '\r' && position_ < text_.size() && text_[position_] == '\n') ++position_;
      ++line_;
      return true;
    }
  }

  std::size_t record_line() const { return record_line_; }

 private:
  std::string field() {
    if (position_ >= text_.size() || text_[position_] != '"') {
      const std::size_t end = std::min(text_.find_first_of(",\r\n", position_), text_.size());
      std::string plain(text_.substr(position_, end - position_));
      position_ = end;
      return plain;
    }
    ++position_;
    std::string quoted;
    for (;;) {
      if (position_ >= text_.size()) {
        throw InputError(path_, record_line_, "a quoted field is not closed");
      }
      const char c = text_[position_++];
      if (c == '\n') ++line_;
      if (c != '"') {
        quoted += c;
        continue;
      }
      if (position_ < text_.size() && text_[position_] == '"') {
        quoted += '"';
        ++position_;
        continue;
      }
      if (position_ < text_.size() && text_.find_first_of(",\r\n", position_) != position_) {
        throw InputError(path_, line_, "text after a closing quote");
      }
      return quoted;
    }
  }

  std::string path_;
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t line_ = 1;
  std::size_t record_line_ = 1;
};

}  // namespace

std::size_t CsvTable::column(const std::string& name) const {
  return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) -
                                  columns.begin());
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

CsvTable read_csv(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  CsvParser parser(path, bytes);
  CsvTable table;
  if (!parser.next(table.columns)) throw InputError(path, 0, "no header line");
  std::vector<std::string> record;
  while (parser.next(record)) {
    if (record.size() != table.columns.size()) {
      throw InputError(path, parser.record_line(),
                       "has " + std::to_string(record.size()) + " fields, the header " +
                           std::to_string(table.columns.size()));
    }
    table.rows.push_back(record);
  }
  return table;
}

void write_csv(const std::string& path, const CsvTable& table) {
  for (const auto& row : table.rows) {
    if (row.size() != table.columns.size()) {
      throw std::invalid_argument("write_csv: a row has " + std::to_string(row.size()) +
                                  " fields, the header " + std::to_string(table.columns.size()));
    }
  }
  const auto write_record = [](std::ostream& out, const std::vector<std::string>& record) {
    for (std::size_t i = 0; i < record.size(); ++i) {
      out << (i == 0 ? "" : ",") << csv_field(record[i]);
    }
    out << '\n';
  };
  write_file_atomically(path, [&](std::ostream& out) {
    write_record(out, table.columns);
    for (const auto& row : table.rows) write_record(out, row);
  });
}

}  // namespace occlusion
