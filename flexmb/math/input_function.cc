#include "flexmb/math/input_function.h"

#include "flexmb/common/error.h"

namespace flexmb {
namespace {

// the table of the innermost InputScope of this thread (nullptr: none)
thread_local InputTable* input_function_current_table = nullptr;

}  // namespace

InputFunction::InputFunction(std::shared_ptr<InputSignal> signal) : signal_(std::move(signal)) {
  if (!signal_) throw InputError("input function without a signal");
}

InputScope::InputScope(InputTable& table) : previous_(input_function_current_table) {
  input_function_current_table = &table;
}

InputScope::~InputScope() { input_function_current_table = previous_; }

std::shared_ptr<InputSignal> RegisterInput(const std::string& name, double initial) {
  InputTable* table = input_function_current_table;
  if (table) {
    auto it = table->find(name);
    if (it != table->end()) return it->second;
  }
  auto signal = std::make_shared<InputSignal>();
  signal->value = initial;
  if (table) (*table)[name] = signal;
  return signal;
}

}  // namespace flexmb
