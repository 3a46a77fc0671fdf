#ifndef _GENERAL_CONSTANTS_H_
#define _GENERAL_CONSTANTS_H_
// GeneralConstants.h - the test host's general constants, shaped like the course framework's.

#define WND_CAPTION L"course host"
#define MAX_DESC 255

// z-axis directions
#define NEAR_TO_FAR (1)
#define FAR_TO_NEAR (-1)
#define MODEL_Z_AXIS NEAR_TO_FAR

#endif
