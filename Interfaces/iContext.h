// iContext.h - the interface to the engine's settings store, which modules read when they are created.
//
// A typed key/value store in the course framework's style: set(key, value) and get(key). A key that was
// never set reads as 0 (or the zero vector), which every module takes to mean "use your default".
#pragma once

#include "MathDeclarations.h"

enum Integer {
    GF_PHYS_STEP_RATE,         // fixed physics steps per second (default 60)
    GF_PHYS_MAX_STEPS,         // most steps one update(now) may take to catch up (default 8)
    GF_PHYS_INTEGRATOR,        // an Integrator value (iPhysicsSettings.h); 0 = the default
    GF_PHYS_SOLVER_ITERATIONS, // contact solver iterations (sub-steps) per step (default 4)
    GF_FRAMES,                 // headless runs: frames to run
    GF_FRAME_MS,               // headless runs: milliseconds a frame
    GF_NO_INTEGERS
};

enum Float {
    GF_PHYS_DUMMY_FLOAT, // reserved
    GF_NO_FLOATS
};

enum VectorId {
    GF_PHYS_GRAVITY, // gravity (m/s^2); unset means (0, -9.81, 0)
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
