#ifndef _MODEL_SETTINGS_H_
#define _MODEL_SETTINGS_H_
// ModelSettings.h - the test host's model settings, shaped like the course framework's.

#define UNITS_PER_SEC 1000  // engine time units per second
#define MIN_ELAPSED_TIME 10 // the engine skips frames shorter than this
#define SPEED 0.02f         // a design's own tuning constant

#endif
