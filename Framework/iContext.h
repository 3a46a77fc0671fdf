// iContext.h - the stand-in framework's settings store (the course framework's iContext): typed key/value
// pairs the engine and designs read. The physics scene does not read it: a course project's iContext has
// keys of its own, so the engine takes its knobs through settingsOf(scene) instead.
//
// A typed key/value store in the course framework's style: set(key, value) and get(key). A key that was
// never set reads as 0 (or the zero vector), which every module takes to mean "use your default".
#pragma once

#include "MathDeclarations.h"

enum Integer : int {
    GF_FRAMES,   // headless runs: frames to run
    GF_FRAME_MS, // headless runs: milliseconds a frame
    GF_NO_INTEGERS
};

enum Float : int {
    GF_FRAME_SECONDS, // headless runs: seconds a frame (informational)
    GF_NO_FLOATS
};

enum VectorId : int {
    GF_GRAVITY, // the game's idea of gravity (m/s^2), for designs that read it; the physics scene's gravity
                // is set with settingsOf(scene)->setGravity
    GF_NO_VECTORS
};

class iContext {
public:
    virtual void set(Integer key, int value) = 0;
    virtual void set(Float key, float value) = 0;
    virtual void set(VectorId key, const Vector& value) = 0;
    virtual int get(Integer key) const = 0;
    virtual float get(Float key) const = 0;
    virtual Vector get(VectorId key) const = 0;
    // True once set() was called for the key.
    virtual bool isSet(Integer key) const = 0;
    virtual bool isSet(Float key) const = 0;
    virtual bool isSet(VectorId key) const = 0;
    virtual void Delete() const = 0;
};

// Implemented by the framework (Framework/Context.cpp).
extern "C" iContext* CreateContext();
