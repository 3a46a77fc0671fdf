// iUtilities.h - how every module reports a refused input: error(L"...").
//
// The course framework reports problems through error(const wchar_t*). Here the message goes to a
// replaceable handler (default: one line on stderr) and is counted, so a game can route it to its log and a
// test can assert that bad input was reported. Reporting never throws and never aborts: the caller has
// already refused the input and left its state as it was.
#pragma once

#include <cstdio>

using ErrorHandler = void (*)(const wchar_t* message);

namespace guardian_detail {
inline ErrorHandler& errorHandlerSlot() {
    static ErrorHandler handler = nullptr;
    return handler;
}
inline unsigned long& errorCountSlot() {
    static unsigned long count = 0;
    return count;
}
} // namespace guardian_detail

// Installs h (nullptr restores the default stderr handler); returns the previous handler.
inline ErrorHandler setErrorHandler(ErrorHandler h) {
    ErrorHandler old = guardian_detail::errorHandlerSlot();
    guardian_detail::errorHandlerSlot() = h;
    return old;
}
// Number of errors reported since the program started.
inline unsigned long errorCount() { return guardian_detail::errorCountSlot(); }

inline void error(const wchar_t* message) {
    ++guardian_detail::errorCountSlot();
    if (ErrorHandler h = guardian_detail::errorHandlerSlot())
        h(message ? message : L"(null)");
    else
        std::fprintf(stderr, "guardian error: %ls\n", message ? message : L"(null)");
}
