#pragma once
// The exceptions momenta throws. Every message names the offending quantity and its value, and
// where it came from (file, line, column) when it came from a file.

#include <stdexcept>
#include <string>

namespace momenta {

/// Base of every exception momenta throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A function argument is outside its documented domain (a negative length, a non-unit axis).
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

/// Mass properties that no physical body can have (negative mass, an inertia tensor that is not
/// positive definite or breaks the triangle inequality A + B >= C).
class InvalidInertia : public InvalidArgument {
 public:
  using InvalidArgument::InvalidArgument;
};

/// A triangle mesh that does not bound a solid: open, non-manifold, inconsistently oriented.
class MeshError : public Error {
 public:
  using Error::Error;
};

/// A file that cannot be read, or does not exist.
class FileError : public Error {
 public:
  using Error::Error;
};

/// A malformed input file. what() reads `file:line:column: message`, the form editors jump to.
class ParseError : public Error {
 public:
  /// `line` and `column` are 1-based; 0 means unknown and is left out of the message.
  ParseError(std::string file, int line, int column, const std::string& message);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  std::string file_;
  int line_;
  int column_;
};

/// A computation produced a non-finite value or failed to converge at run time.
class NumericalError : public Error {
 public:
  using Error::Error;
};

}  // namespace momenta
