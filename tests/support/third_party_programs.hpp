#pragma once
// Running the programs users open our outputs with (CloudCompare under
// xvfb-run, Open3D's Python, PCL's tools), as the third-party tests do: each
// under `timeout`, output captured, and CloudCompare's ASCII export read back.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace occlusion::testing {

// A program that hangs must not hang the suite: each gets this long.
inline constexpr const char* kProgramTimeout = "timeout 180 ";

struct ProgramRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

inline ProgramRun run_program(const std::string& command) {
  ProgramRun result;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t got = 0;
  while ((got = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.output.append(buffer.data(), got);
  }
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

inline bool have_program(const std::string& program) {
  return run_program("command -v " + program + " >/dev/null").exit_code == 0;
}

// A path as one shell word (test paths hold no ').
inline std::string shell_word(const std::string& path) {
  return "'" + path + "'";
}

inline std::vector<std::string> words_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

// CloudCompare saves `-O DIR/X.ply` as DIR/X_<time stamp>.<extension>: that
// file for `stem`, or "" when it saved none.
inline std::string saved_by_cloudcompare(const std::filesystem::path& dir, const std::string& stem,
                                         const std::string& extension) {
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(stem + "_", 0) == 0 && entry.path().extension() == extension) {
      return entry.path().string();
    }
  }
  return "";
}

// CloudCompare's ASCII export with -ADD_HEADER: `//X Y Z [R G B] <fields>`,
// then one row of numbers per point. Its columns are what it loaded: a
// property it took for a colour or a normal shows as R G B or Nx Ny Nz, not
// under its own name.
struct CloudCompareTable {
  std::string header;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

inline CloudCompareTable read_cloudcompare_ascii(const std::string& path) {
  CloudCompareTable table;
  std::ifstream in(path);
  std::getline(in, table.header);
  if (table.header.rfind("//", 0) == 0) table.columns = words_of(table.header.substr(2));
  for (std::string line; std::getline(in, line);) {
    std::istringstream values(line);
    std::vector<double> row;
    for (double v = 0; values >> v;) row.push_back(v);
    if (!row.empty()) table.rows.push_back(row);
  }
  return table;
}

}  // namespace occlusion::testing
