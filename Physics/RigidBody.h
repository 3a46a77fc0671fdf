// RigidBody.h - the simulator's iRigidBody: an RBDynamics, the frame it drives, its listeners, and the
// per-body bookkeeping the scene needs between steps (last valid state, interpolation poses, what the scene
// last wrote, so that a game's edits can be told from the simulator's).
//
// Ownership: made by CreateRigidBody (or a PhysicsFrame), gone with Delete(). Delete() during a scene update
// only marks the body dying and unbinds its frame; the scene deletes it at the end of the step.
#pragma once

#include "MathBridge.h"
#include "Prefetch.h"
#include "RBDynamics.h"
#include "iLifetime.h"
#include "iRigidBody.h"
#include "iRigidBodyMotion.h"
#include "iRigidBodySwitches.h"
#include "iUserPointer.h"

#include <vector>

class iFrame;
class iForceGenerator;
class iPhysicsFrame;

namespace physics {

class PhysicsScene;
class Joint;

class RigidBody final : public iRigidBody,
                        public iRigidBodyMotion,
                        public iRigidBodySwitches,
                        public iLifetime,
                        public iUserPointer {
public:
    explicit RigidBody(iFrame* frame);
    RigidBody(const RigidBody&) = delete;
    RigidBody& operator=(const RigidBody&) = delete;

    // --- iRigidBody ---
    iRigidBody* clone() const override;
    void attach(iFrame* o) override;
    void attachListener(iCollisionListener* l) override;
    void detachListener(const iCollisionListener* l) override;
    void restore(int) override {}
    std::vector<iCollisionListener*>& getListeners() override { return m_listeners; }
    iFrame* getFrame() override { return m_frame; }
    RBDynamics& getDynamics() override { return m_dyn; }
    const RBDynamics& getDynamics() const override { return m_dyn; }
    void setDynamics(const RBDynamics& d) override;
    void reset(int) override {}
    void suspend() const override {}
    void release() const override {}
    void Delete() const override;

    // --- iRigidBodyMotion (BodyMotion.cpp) ---
    bool teleport(const Vector& position, const Matrix& orientation) override;
    bool moveTo(const Vector& position, const Matrix& orientation, float seconds) override;
    void wake() override;

    // --- iLifetime (the scene's deferred removal), iUserPointer ---
    void kill() override;
    bool isAlive() const override { return m_alive; }
    void resetAlive() override { m_alive = true; }
    void setUserPointer(void* p) override { m_userPointer = p; }
    void* getUserPointer() const override { return m_userPointer; }

    // --- iRigidBodySwitches (RigidBody.cpp) ---
    void setRotationLocked(bool locked) override { m_switches.rotationLocked = locked; }
    bool isRotationLocked() const override { return m_switches.rotationLocked; }
    bool setGravityScale(float scale) override;
    float getGravityScale() const override { return m_switches.gravityScale; }
    void setContinuousCollisionEnabled(bool on) override { m_switches.continuous = on; }
    bool getContinuousCollisionEnabled() const override { return m_switches.continuous; }
    void setSleepAllowed(bool allowed) override { m_switches.sleepAllowed = allowed; }
    bool getSleepAllowed() const override { return m_switches.sleepAllowed; }
    void copySwitches(const RigidBody& from) { m_switches = from.m_switches; } // a clone's

    // --- the scene's side ---
    PhysicsScene* scene() const { return m_scene; }
    void setScene(PhysicsScene* s) { m_scene = s; }
    iPhysicsFrame* owner() const { return m_owner; }
    void setOwner(iPhysicsFrame* f) { m_owner = f; }
    bool dying() const { return m_dying; }
    // Queued for deletion (by Delete() or its scene's): skipped by the steps, and its frame let go at once
    // (the game may delete the frame right after the call that queued the body).
    void markDying() {
        m_dying = true;
        bindFrame(nullptr);
    }
    // A PhysicsFrame is being deleted: every body bound to it lets go of it (a course framework's Frame
    // cannot say so; see iRigidBody::attach).
    static void frameDeleted(const iFrame* f);
    // Deletes now (the scene calls it when flushing deferred deletions, or Delete() outside a step).
    void destroy();
    std::vector<iForceGenerator*>& generators() { return m_generators; }

    // Takes the pose of the bound frame if the game moved the frame since the scene last wrote it (a
    // teleport: velocities are kept, no interpolation across it). Unattached bodies only.
    void adoptFrameEdits();
    // Checks the state (cleaning float drift in the orientation); an invalid body is reported with error()
    // and restored to its last valid state. Returns false when it had to restore. motionOnly: the settings
    // are, bit for bit, the last accepted ones (acceptState): only the motion is checked (checkMotion).
    bool validate(const char* when, bool motionOnly);
    void snapshotValid() {
        m_lastValid = m_dyn;
        m_lastValidChecked = false;
    }
    // A clone's: what a failed check puts back is what `from` last accepted, not the state copied (a NaN the
    // game wrote into `from` just before would otherwise be put back every step).
    void inheritLastValid(const RigidBody& from) {
        m_lastValid = from.m_lastValid;
        m_lastValidChecked = from.m_lastValidChecked;
    }
    // validate, and on success snapshotValid, as a step does at its start and end; a state that is, bit for
    // bit, the last one this accepted (a body nothing touched since the last step) is accepted as it is,
    // without the checks or the copy, and one that differs only in its motion (a step moved it) has only the
    // motion checked and copied.
    bool acceptState(const char* when);
    // Interpolation: the pose at the start of the step, and the frame write after the steps.
    void recordPreviousPose();
    void recordStepPose(); // the pose a step ended with (an edit after it is a teleport)
    void writeFrame(float alpha);
    // writeFrame once per round, after the frame of the nearest ancestor body (in the attachment chain) that
    // has one in the same scene (a frame's T is relative to its parent, so the parent must be where it is
    // drawn now).
    void writeFrameAfterParent(float alpha, unsigned long long round);
    static unsigned long long newFrameRound();
    // The step's closing of joints (JointClosing.h): held where it was put; its joints listed; queued.
    bool closingHeld = false, closingWalked = false, closingQueued = false;
    bool pendingRemoval = false; // remove() during a step, or kill(): skipped now, removed when the step ends

private:
    // Beside pendingRemoval: every pass of a step over the bodies reads both first (one cache line a body).
    bool m_dying = false;

public:
    int sceneSlot = -1; // its place in its scene's list of bodies (PhysicsScene::bodies)
    // The world pose (COM, rotation) at the start of the current step.
    const Vector& previousPosition() const { return m_prevPosition; }
    const Quat& previousRotation() const { return m_prevRotation; }
    // How far the contact solve projected the body out of a deep overlap this step (a correction, not a
    // path: the continuous stage sweeps from the start pose moved by it).
    Vector projectedBy;

private:
    // The start pose (recordPreviousPose), on the body's second cache line: the contact solver's entry of a
    // body reads it with the first, in contact order, which at 10,000 bodies is random in memory (fetched
    // ahead of it with the first: ContactManifolds.cpp).
    Quat m_prevRotation = Quat::Identity();
    Vec3 m_startPosition = Vec3::Zero();

public:
    // The world pose of this body's COM and its world orientation. While a PoseCache is alive each body's is
    // computed once, from its parent's (O(1) a body, where RBDynamics::getWorldPosition is O(depth)): the
    // scene opens one around the loops that read every body's pose and run no game code (WorldPoseCache.cpp).
    Vector worldPosition() const;
    Matrix worldOrientation() const;
    struct PoseCache {
        PoseCache();
        ~PoseCache();
        PoseCache(const PoseCache&) = delete;
        PoseCache& operator=(const PoseCache&) = delete;
    };
    static void invalidatePoses(); // a body's pose changed: cached poses are recomputed

    // Sleeping: a body (island) at rest for a while stops being integrated until something wakes it. The
    // state is RBDynamics::sleeping itself, so the collision space sees it without any copying.
    bool asleep() const { return m_dyn.sleeping; }
    void setAsleep(bool on) { m_dyn.sleeping = on; }
    float restTime = 0; // seconds spent below the sleep speeds
    // The island it fell asleep with (0: none, or awake): one member woken wakes them all (Islands).
    unsigned sleepIsland = 0;
    long long checkedStep = -1; // the step whose start last took its state in (validated; PhysicsScene::step)
    // True when the game touched a sleeping body's state since its last step: a velocity, a force or
    // torque, or a new pose. Such a body wakes.
    bool editedWhileAsleep() const;
    // True when the world pose differs from the one the last step ended with: the game put the body
    // somewhere (a teleport, RBDynamics::teleports).
    bool movedByGame() const;

    // Angular bookkeeping of a root, written after each step: a differing field is a game edit.
    Vector writtenOmega, writtenMomentum;
    // The engine's own state of a root between steps, in Real (MathBridge.h): COM position and velocity,
    // angular velocity and momentum, authoritative while RBDynamics still holds what the scene last wrote of
    // them (writtenPosition, writtenVelocity, writtenOmega, writtenMomentum); a field that differs is a game
    // edit and is taken instead. In a float build each value is its field's own: nothing changes.
    struct OwnState {
        Vec3 position = Vec3::Zero(), velocity = Vec3::Zero(), omega = Vec3::Zero(), momentum = Vec3::Zero();
        Vector writtenPosition, writtenVelocity;
    };
    OwnState own;
    Vec3 statePosition() const { return ownOr(m_dyn.position, own.writtenPosition, own.position); }
    Vec3 stateVelocity() const { return ownOr(m_dyn.velocity, own.writtenVelocity, own.velocity); }
    Vec3 stateOmega() const { return ownOr(m_dyn.angularVelocity, writtenOmega, own.omega); }
    Vec3 stateMomentum() const { return ownOr(m_dyn.angularMomentum, writtenMomentum, own.momentum); }
    // Sets the state and writes it (rounded to float) into RBDynamics.
    void writePosition(const Vec3& p) {
        own.position = p;
        m_dyn.position = own.writtenPosition = toVector(p);
    }
    void writeVelocity(const Vec3& v) {
        own.velocity = v;
        m_dyn.velocity = own.writtenVelocity = toVector(v);
    }
    // The start of this step: the root's own position (the world position of an attached body).
    const Vec3& startPosition() const { return m_startPosition; }
    Matrix writtenOrientation = Matrix(1);
    Quat rotation = Quat::Identity(); // the exact quaternion behind writtenOrientation
    // The body's own orientation as a quaternion: the exact cached one while the matrix is still the one it
    // made, else the game's matrix converted.
    Quat ownRotation() const {
        return m_dyn.orientation == writtenOrientation ? rotation : toQuat(m_dyn.orientation);
    }
    // What the integrator's forces did to the composite's velocities (about its centre of mass) this step:
    // the contact solver re-applies it a share per sub-step.
    Vec3 forceDv = Vec3::Zero(), forceDw = Vec3::Zero();
    // Composite mass properties of the last step (a change means attach/detach or new inertia: keep w).
    bool hasComposite = false;
    // Its index among the contact solver's bodies while the solver moves it through this step (-1: not).
    int solverSlot = -1;
    // Asks for the dynamics (what the step's edit pass reads) and, when validation runs, the last valid copy
    // acceptState compares them with and copies them into.
    void prefetchDynamics(bool lastValidToo) const {
        prefetchLines(&m_dyn, sizeof(m_dyn));
        if (lastValidToo) prefetchLines(&m_lastValid, sizeof(m_lastValid));
    }
    // Asks for the lines the solver's write-back and the scene's acceptance of it touch here: the fields
    // from projectedBy to solverSlot, declared together for that (ContactResolution.cpp).
    void prefetchSolverState() const {
        const char* from = reinterpret_cast<const char*>(&projectedBy);
        prefetchLines(from, size_t(reinterpret_cast<const char*>(&solverSlot + 1) - from));
    }
    // The joints that hold this body (Joint.h keeps the list): they let go when it is killed or deleted.
    std::vector<Joint*> joints;
    Real compositeMass = 0;
    Mat3 compositeInertia = Mat3::Zero();

    // Everything of the body a step reads, for snapshots (SceneSnapshot.cpp): saved and put back whole.
    struct Saved {
        RBDynamics dyn, lastValid;
        bool sleeping;
        unsigned teleports;
        Vector prevPosition, stepPosition, projectedBy, writtenOmega, writtenMomentum;
        Quat prevRotation, rotation;
        Matrix stepOrientation, writtenOrientation;
        Vec3 forceDv, forceDw;
        OwnState own;
        Vec3 startPosition;
        float restTime;
        Real compositeMass;
        unsigned sleepIsland;
        bool hasComposite;
        Mat3 compositeInertia;
    };
    Saved save() const;
    // Puts s back; the frame is then to be written again (the scene's writeFrames), as after a step.
    void load(const Saved& s);

private:
    ~RigidBody();
    void bindFrame(iFrame* o); // sets m_frame, keeping the index of bindings frameDeleted reads

    RBDynamics m_dyn;
    RBDynamics m_lastValid;
    bool m_lastValidChecked = false;         // m_lastValid is a state acceptState checked (not just a copy)
    Matrix m_checkedOrientation = Matrix(1); // the last orientation validate() accepted: a clean rotation
    struct Switches {
        bool rotationLocked = false, continuous = true, sleepAllowed = true;
        float gravityScale = 1.0f;
    } m_switches;
    iFrame* m_frame = nullptr;
    Matrix
        m_writtenWorld; // the frame's world() as this body last wrote or adopted it: a change is a game edit
    std::vector<iCollisionListener*> m_listeners;
    std::vector<iForceGenerator*> m_generators;
    PhysicsScene* m_scene = nullptr;
    iPhysicsFrame* m_owner = nullptr;
    bool m_alive = true;
    void* m_userPointer = nullptr;
    unsigned long long m_frameRound = 0;
    void cacheWorldPose() const;
    mutable unsigned long long m_poseRound = 0; // the cache round m_worldPos and m_worldRot belong to
    mutable Vector m_worldPos;
    mutable Matrix m_worldRot = Matrix(1);
    Vector m_prevPosition, m_stepPosition;
    static Vec3 ownOr(const Vector& field, const Vector& written, const Vec3& value) {
        return field == written ? value : toEigen(field);
    }
    Matrix m_stepOrientation = Matrix(1);
};

} // namespace physics
