// Utilities.cpp - the test host's error reporting: one line on stderr per error, counted.
#include "iUtilities.h"

#include <cstdio>

static int errors = 0;

void error(const wchar_t* msg, const wchar_t* more) {
    ++errors;
    std::fprintf(stderr, "host error: %ls%ls\n", msg ? msg : L"", more ? more : L"");
}

int errorsReported() { return errors; }
