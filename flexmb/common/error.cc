#include "flexmb/common/error.h"

namespace flexmb {

std::string FormatWithContext(const std::string& message, const ErrorContext& context) {
  std::string out;
  if (!context.file.empty()) {
    out += context.file;
    if (context.line > 0) out += ":" + std::to_string(context.line);
    out += ": ";
  }
  if (!context.entity.empty()) out += context.entity + ": ";
  out += message;
  return out;
}

Error::Error(const std::string& message, ErrorContext context)
    : std::runtime_error(FormatWithContext(message, context)),
      message_(message),
      context_(std::move(context)) {}

}  // namespace flexmb
