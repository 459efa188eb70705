// Preconditions that the code states: QT_PRECONDITION(condition) checks one in the builds that
// define QT_CHECK_PRECONDITIONS (the host, sanitizer and aarch64 test builds, CMake option
// QT_CHECK_PRECONDITIONS) and compiles to nothing elsewhere (the firmware). A violated one calls
// the handler: by default a trap (no I/O in core/); tests install one that prints where.
#pragma once

namespace qt {

using PreconditionHandler = void (*)(const char* file, int line, const char* condition);

// The handler called on a violated precondition; it must not return (the default traps).
void set_precondition_handler(PreconditionHandler handler);

[[noreturn]] void precondition_failed(const char* file, int line, const char* condition);

}  // namespace qt

#if defined(QT_CHECK_PRECONDITIONS)
#define QT_PRECONDITION(condition) \
    ((condition) ? static_cast<void>(0) : ::qt::precondition_failed(__FILE__, __LINE__, #condition))
#else
#define QT_PRECONDITION(condition) static_cast<void>(0)
#endif
