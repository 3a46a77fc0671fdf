// CountingNew.h - how many times the global operator new has run in this test program. CountingNew.cpp
// replaces operator new (and the matching deletes) with a malloc that counts; a test program that links it
// can check that warm code does not allocate.
#pragma once

namespace guardian_test {

long allocationCount();

} // namespace guardian_test
