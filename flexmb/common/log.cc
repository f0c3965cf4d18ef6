#include "flexmb/common/log.h"

#include <iostream>

namespace flexmb {
namespace {

LogSink& Sink() {
  static LogSink sink;
  return sink;
}

}  // namespace

void LogWarning(const std::string& message) {
  if (Sink()) {
    Sink()(message);
  } else {
    std::cerr << "warning: " << message << "\n";
  }
}

LogSink SetWarningSink(LogSink sink) {
  LogSink old = std::move(Sink());
  Sink() = std::move(sink);
  return old;
}

}  // namespace flexmb
