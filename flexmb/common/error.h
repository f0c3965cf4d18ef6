#pragma once
/// \file error.h
/// One exception hierarchy for flexmb. Every error carries the context a user
/// needs to find the fault: the input file, the line, and the named entity.

#include <stdexcept>
#include <string>

namespace flexmb {

/// Where an error comes from: the input file and line (1-based, 0 = unknown)
/// and the name of the entity (body, joint, marker, ...) at fault.
struct ErrorContext {
  std::string file;    ///< input file path, empty if not from a file
  int line = 0;        ///< 1-based line in `file`, 0 if unknown
  std::string entity;  ///< e.g. "joint 'crank_pin'"; empty if none
};

/// Base of all flexmb errors. what() is the full message with context, in the
/// form "FILE:LINE: ENTITY: message".
class Error : public std::runtime_error {
 public:
  Error(const std::string& message, ErrorContext context = {});
  /// The message without context.
  const std::string& message() const { return message_; }
  /// The context given at construction.
  const ErrorContext& context() const { return context_; }

 private:
  std::string message_;
  ErrorContext context_;
};

/// Invalid user input: model file, command-line value, foreign format.
class InputError : public Error {
 public:
  using Error::Error;
};

/// Numerical trouble during a solve: Newton divergence, singular matrix,
/// inconsistent constraints. The context names the body or joint at fault.
class NumericalError : public Error {
 public:
  using Error::Error;
};

/// Formats "FILE:LINE: ENTITY: message" from its parts, skipping empty ones.
std::string FormatWithContext(const std::string& message, const ErrorContext& context);

}  // namespace flexmb
