#pragma once
// The two kinds of failure every module reports: bad model input (exit code 2 on the CLI) and
// files that cannot be read or written (exit code 1).
#include <stdexcept>
#include <string>

namespace gridifs {

/// A problem with the model or its input; `path` is a JSON path such as
/// `functions[2].ops[0].k` when the problem belongs to one field.
class ModelError : public std::runtime_error {
 public:
  ModelError(std::string path, const std::string& message)
      : std::runtime_error(path.empty() ? message : path + ": " + message), path_(std::move(path)), message_(message) {}
  const std::string& path() const { return path_; }
  /// The message without the path.
  const std::string& message() const { return message_; }
  /// The same error located under `prefix` (e.g. "functions[1]" + "ops[0].k").
  ModelError under(const std::string& prefix) const {
    return ModelError(path_.empty() ? prefix : prefix.empty() ? path_ : prefix + "." + path_, message_);
  }

 private:
  std::string path_, message_;
};

/// A failure to read or write a file (exit code 1 on the CLI, unlike ModelError's 2).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace gridifs
