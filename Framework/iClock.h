// iClock.h - where the Engine's `now` comes from: real time, or a stepped clock for deterministic headless
// runs.
#pragma once

class iClock {
public:
    // Called by the Engine once at the start of every frame.
    virtual void tick() = 0;
    // Engine time in milliseconds since the clock was created.
    virtual int now() const = 0;
    virtual void Delete() const = 0;
};

// Milliseconds of the monotonic system clock; tick() does nothing.
extern "C" iClock* CreateRealClock();
// Starts at startMs and advances by msPerFrame on every tick(): the same run every time.
extern "C" iClock* CreateSteppedClock(int msPerFrame, int startMs = 0);
