#pragma once
// Reading option values from the command line. Every parse error is a
// UsageError that names the option.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion::cli {

class Arguments {
 public:
  explicit Arguments(std::vector<std::string> args) : args_(std::move(args)) {}
  bool done() const { return next_ >= args_.size(); }
  const std::string& peek() const { return args_[next_]; }
  std::string take() { return args_[next_++]; }
  // The value after `option`; UsageError if there is none.
  std::string value_of(const std::string& option);

 private:
  std::vector<std::string> args_;
  std::size_t next_ = 0;
};

double parse_number(const std::string& option, const std::string& text);
std::uint64_t parse_unsigned(const std::string& option, const std::string& text);
bool parse_bool(const std::string& option, const std::string& text);
// "X,Y,Z"
Eigen::Vector3d parse_point(const std::string& option, const std::string& text);

}  // namespace occlusion::cli
