// Exceptions that carry their context to main(), which turns them into
// one-line messages and exit codes (2: bad input, 1: failure during computation).
#pragma once
#include <stdexcept>
#include <string>

namespace isosid::format {

/// Bad user input: a file, a field in it, and what is wrong. Exit status 2.
class InputError : public std::runtime_error {
public:
  InputError(const std::string& file, const std::string& field, const std::string& problem)
      : std::runtime_error(compose(file, field, problem)), file_(file), field_(field), problem_(problem) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

private:
  static std::string compose(const std::string& file, const std::string& field, const std::string& problem) {
    std::string s = file;
    if (!field.empty()) s += (s.empty() ? "" : ": ") + field;
    return s + ": " + problem;
  }
  std::string file_, field_, problem_;
};

/// A failure while computing on valid input. Exit status 1.
class ComputationError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace isosid::format
