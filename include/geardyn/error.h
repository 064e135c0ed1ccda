#pragma once
/// \file
/// The error types of geardyn's public API (STYLE.md, "three tiers of errors"):
/// `InputError` for bad input, `IoError` for files that cannot be read or written. Numerical
/// failure is never an exception: solvers return a status.

#include <stdexcept>
#include <string>

namespace geardyn {

/// Bad input to a public function or in a configuration: names the offending key (dotted path,
/// e.g. "pinion.teeth", or a function argument name), the value that was given and what is
/// allowed. pybind11 maps it to Python's ValueError; the CLI exits with code 2.
class InputError : public std::invalid_argument {
 public:
  /// \param key     dotted configuration key or argument name ("" when none applies)
  /// \param value   the offending value as the user wrote it ("" when none applies)
  /// \param allowed what would have been accepted, or why the value cannot be used
  InputError(std::string key, std::string value, std::string allowed);

  const std::string& key() const noexcept { return key_; }
  const std::string& value() const noexcept { return value_; }
  const std::string& allowed() const noexcept { return allowed_; }

 private:
  std::string key_;
  std::string value_;
  std::string allowed_;
};

/// A file that cannot be read or written (permissions, full disk, missing folder). The CLI exits
/// with code 3. A configuration file that does not exist is an InputError, not an IoError.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace geardyn
