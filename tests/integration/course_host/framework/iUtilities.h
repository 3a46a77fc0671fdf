#ifndef _I_UTILITIES_H_
#define _I_UTILITIES_H_
// iUtilities.h - the test host's utilities, shaped like the course framework's.

void error(const wchar_t* msg, const wchar_t* more = 0);
int errorsReported(); // the host's own addition: how many errors were reported

#endif
