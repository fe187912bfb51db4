#pragma once
// The exceptions momenta throws. Every message names the offending quantity and its value, and
// where it came from (file, line, column) when it came from a file.

#include <optional>
#include <stdexcept>
#include <string>

namespace momenta {

/// Which item of a model an error is about, as data (not only as text), so that a file reader
/// can point at the line that declares it.
struct ModelItemRef {
  enum class Kind { body, joint, force_element, signal, constraint };
  Kind kind;
  std::string name;
};

/// Base of every exception momenta throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;

  /// The model item the error is about, when one is known.
  const std::optional<ModelItemRef>& item() const { return item_; }
  /// Records the item the error is about, unless one is already recorded (the innermost, most
  /// specific item wins). Used as `catch (Error& e) { e.about(...); throw; }`, which keeps the
  /// exception's type.
  void about(ModelItemRef::Kind kind, std::string name) {
    if (!item_) item_ = ModelItemRef{kind, std::move(name)};
  }

 private:
  std::optional<ModelItemRef> item_;
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

/// A run stopped because it was asked to (an interrupt from the user), not because it failed.
class Interrupted : public Error {
 public:
  using Error::Error;
};

/// A computation produced a non-finite value or failed to converge at run time.
class NumericalError : public Error {
 public:
  using Error::Error;
};

}  // namespace momenta
