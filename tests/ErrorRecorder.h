// ErrorRecorder.h - the tests' one quiet error recorder: while alive it keeps refused input from printing,
// counts the error() calls made since it was created and keeps the last message.
#pragma once

#include "iUtilities.h"

#include <string>

namespace guardian_test {

class ErrorRecorder {
public:
    static std::wstring& last() {
        static std::wstring s;
        return s;
    }
    ErrorRecorder() : m_previous(setErrorHandler(&handler)), m_start(errorCount()) { last().clear(); }
    ~ErrorRecorder() { setErrorHandler(m_previous); }
    ErrorRecorder(const ErrorRecorder&) = delete;
    ErrorRecorder& operator=(const ErrorRecorder&) = delete;
    unsigned long count() const { return errorCount() - m_start; }

private:
    static void handler(const wchar_t* m) { last() = m; }
    ErrorHandler m_previous;
    unsigned long m_start;
};

} // namespace guardian_test
