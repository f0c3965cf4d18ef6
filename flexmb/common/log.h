#pragma once
/// \file log.h
/// Warnings and notes for the user. The default sink prints to stderr; a
/// program or test may install its own.

#include <functional>
#include <string>

namespace flexmb {

/// Receives each warning message.
using LogSink = std::function<void(const std::string&)>;

/// Issues a warning (e.g. "joint 'j4': equation z_i . x_j = 0 is redundant ...").
void LogWarning(const std::string& message);

/// Replaces the warning sink; returns the previous one. An empty sink restores
/// the default (stderr).
LogSink SetWarningSink(LogSink sink);

}  // namespace flexmb
