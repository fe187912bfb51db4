#pragma once
// The exceptions momenta throws. Every message names the offending quantity and its value, and
// where it came from (file, line, column) when it came from a file.

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace momenta {

/// Which item of a model an error is about, as data (not only as text), so that a file reader
/// can point at the line that declares it.
struct ModelItemRef {
  enum class Kind { body, joint, force_element, signal, constraint, controller };
  Kind kind;
  std::string name;
};

/// Writes a message that names options of a run or a command — the step, the integrator, whether
/// to overwrite — which each front end spells its own way (`--dt` on the command line, `dt=` in
/// Python). In the text an option is ‹name› or ‹name=value› with the library's name
/// (RunOptionNames below); what() reads it plainly (`step`, `integrator dopri5`), and a front end
/// reads it through Error::spelled.
struct OptionMessage {
  std::string text;
};

/// The library's names of the options a message may name: the fields of
/// model::SimulationSettings (step, duration, integrator, relative_tolerance,
/// absolute_tolerance, every), and force (overwrite an existing file), resume, about (the
/// operating point), body, link_density, package_path, mjcf (write MJCF rather than URDF),
/// reactions, code (equations written as generated code), linearize (the numeric
/// linearization).
/// How a front end writes option `name` (with `value`, empty when the message gives none).
using OptionSpelling = std::string (*)(std::string_view name, std::string_view value);

/// Base of every exception momenta throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  /// An error whose message names options (OptionMessage): what() reads them plainly.
  explicit Error(const OptionMessage& message);

  /// The message with its options as `spell` writes them (what() when it names none).
  std::string spelled(OptionSpelling spell) const;
  /// The options the message names, in order, by the library's names.
  std::vector<std::string> options() const;

  /// The model item the error is about, when one is known.
  const std::optional<ModelItemRef>& item() const { return item_; }
  /// Records the item the error is about, unless one is already recorded (the innermost, most
  /// specific item wins). Used as `catch (Error& e) { e.about(...); throw; }`, which keeps the
  /// exception's type.
  void about(ModelItemRef::Kind kind, std::string name) {
    if (!item_) item_ = ModelItemRef{kind, std::move(name)};
  }

  /// The name in the equations of motion an error is about — a parameter's or coordinate's, as a
  /// model file's `symbols:` section gives it — when one is known: the file points at its line.
  const std::optional<std::string>& symbol() const { return symbol_; }
  void about_symbol(std::string name) {
    if (!symbol_) symbol_ = std::move(name);
  }

 private:
  std::optional<ModelItemRef> item_;
  std::optional<std::string> symbol_;
  std::string option_text_;  // the message with its ‹option› marks; empty: it names none
};

/// The message `text` with every ‹name› or ‹name=value› written by `spell`.
std::string spell_options(std::string_view text, OptionSpelling spell);

/// The library's own spelling, what() reads: `step`, `integrator dopri5`.
std::string plain_spelling(std::string_view name, std::string_view value);

/// The marks themselves, ‹name=value›: for a message that wraps another's in a new OptionMessage.
std::string keep_option_marks(std::string_view name, std::string_view value);

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
  /// The same for a message that names options (OptionMessage).
  ParseError(std::string file, int line, int column, const OptionMessage& message);

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
