// iDesign.h - the interface a game implements: it builds its world and updates it once a frame.
//
// The Engine calls initialize(now) once, then update(now) every frame after the physics scene has moved.
#pragma once

class iDesign {
public:
    virtual void initialize(int now) = 0;
    virtual void update(int now) = 0;
    virtual void reset(int now) = 0;
    virtual void restore(int now) = 0;
    virtual void suspend() = 0;
    virtual void release() = 0;
    // A headless run stops early once this returns true.
    virtual bool finished() const = 0;
    virtual void Delete() const = 0;
};
