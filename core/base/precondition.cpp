#include "base/precondition.h"

namespace qt {

namespace {

PreconditionHandler g_handler = nullptr;

}  // namespace

void set_precondition_handler(PreconditionHandler handler) { g_handler = handler; }

void precondition_failed(const char* file, int line, const char* condition) {
    if (g_handler != nullptr) g_handler(file, line, condition);
    __builtin_trap();  // a handler that returns, or none: stop here
}

}  // namespace qt
