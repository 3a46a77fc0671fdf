// iEngine.h - the headless course-framework engine: owns the design, the physics scene and the clock, and
// runs the frame loop in the course order (input, physicsScene->update(now), design->update(now)).
#pragma once

class iContext;
class iDesign;
class iPhysicsScene;
class iClock;

class iEngine {
public:
    // Calls design->initialize(now). Returns false when there is no design.
    virtual bool setup() = 0;
    // One frame: tick the clock; if at least MIN_ELAPSED_TIME ms passed and the engine is active, update the
    // physics scene then the design with the same `now`. Returns false once the design has finished.
    virtual bool step() = 0;
    // Runs up to `frames` frames (stops early when the design finishes); returns the frames run.
    virtual int run(int frames) = 0;
    // Lifecycle, forwarded to the scene and the design as the course Engine does.
    virtual void suspend() = 0;
    virtual void restore() = 0;
    virtual void reset() = 0;
    virtual void release() = 0;
    virtual bool active() const = 0;
    virtual int now() const = 0; // the `now` of the last frame
    virtual iContext* context() const = 0;
    virtual iPhysicsScene* physicsScene() const = 0;
    // Deletes the design, the physics scene and the clock (in that order); never the context.
    virtual void Delete() const = 0;
};

// scene may be nullptr (collision-only games); clock nullptr means a real-time clock.
extern "C" iEngine* CreateEngine(iContext* context, iDesign* design, iPhysicsScene* scene, iClock* clock);
