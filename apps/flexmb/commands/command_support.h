#pragma once
/// \file command_support.h
/// Internal helpers shared by the command groups fe_commands.cc and
/// reduce_commands.cc: wall times, short number formatting for the text
/// reports, the frequency table, error context naming the model file, and
/// node-list options. Not a public header.

#include <Eigen/Core>
#include <chrono>
#include <ostream>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::io::command {

/// Clock of the wall times the commands report.
using Clock = std::chrono::steady_clock;

/// Seconds from `a` to `b`.
double Seconds(Clock::time_point a, Clock::time_point b);

/// `x` with 6 significant digits ("%.6g"): numbers of the text reports and
/// wall times.
std::string Short(double x);

/// "(x, y, z)" with Short numbers.
std::string ShortVector(const Eigen::Vector3d& v);

/// The name of a model shown in reports: the file name of `path`, or the
/// directory name for a path ending in '/' (an exchange-set directory).
std::string ModelName(const std::string& path);

/// Writes the table "mode  frequency [Hz]" with one line per entry of
/// `frequencies_hz` (mode numbers from 1, 9 significant digits).
void WriteFrequencyTable(std::ostream& out, const Eigen::VectorXd& frequencies_hz);

/// Writes the lines "mass: M kg", "centre of mass: (x, y, z) m" and
/// "inertia about the centre of mass (AXES axes): [rows] kg m^2" (Short
/// numbers); `axes` names the frame ("basic", "body").
void WriteMassText(std::ostream& out, double mass, const Eigen::Vector3d& center, const Eigen::Matrix3d& inertia,
                   const char* axes);

/// Runs `f` and returns its result; an InputError or NumericalError whose
/// context names no file is rethrown with `path` as its file.
template <class F>
auto InFile(const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    ErrorContext c = e.context();
    if (c.file.empty()) c.file = path;
    throw InputError(e.message(), c);
  } catch (const NumericalError& e) {
    ErrorContext c = e.context();
    if (c.file.empty()) c.file = path;
    throw NumericalError(e.message(), c);
  }
}

/// The comma-separated finite numbers of an option's value ("0.1,2e-4");
/// InputError naming the option, the value and the item that is not a number.
std::vector<double> NumberList(const std::string& text, const std::string& option);

/// Node indices of a node-list option (comma-separated node ids or a node
/// set name, io::ResolveNodeList); none if `list` is empty. Errors name the
/// model file `path`.
std::vector<int> NodeListOption(const fe::Mesh& mesh, const std::string& list, const std::string& path);

}  // namespace flexmb::io::command
