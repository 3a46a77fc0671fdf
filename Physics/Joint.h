// Joint.h - the simulator's side of every joint: its two bodies and its frame on each, letting go of a body
// killed or deleted, breaking, and the calls the contact solver makes (enter a step, warm start, solve,
// save and restore around the push out, reaction). Each kind (BallJoint.cpp, HingeJoint.cpp, ...) says which
// rows it is made of (JointRows.h) and solves them; the rest is here.
#pragma once

#include "JointRows.h"
#include "iJoint.h"
#include "iUserPointer.h"

#include <limits>
#include <vector>

namespace physics {

class RigidBody;

// Which pass of a sub-step is solving: the velocities, the push out (position errors corrected, then the
// velocity forgotten), or the relax (the velocities again at the moved poses).
enum class JointPass { Velocity, PushOut, Relax };

class Joint {
public:
    static constexpr int kMaxRows = 5;
    Joint(JointType type, RigidBody* a, RigidBody* b, const JointFrame& localA, const JointFrame& localB);
    virtual ~Joint(); // leaves its bodies' joint lists
    Joint(const Joint&) = delete;
    Joint& operator=(const Joint&) = delete;

    JointType type() const { return m_type; }
    RigidBody* bodyA() const { return m_a; }
    RigidBody* bodyB() const { return m_b; }
    bool acting() const { return !m_broken && !m_letGo && !m_deleted; }
    bool deleted() const { return m_deleted; }
    bool collideConnected = false;
    // body (one of the two) is killed or deleted: the joint stops acting and forgets it.
    void letGo(const RigidBody* body);
    // The public object, for listeners.
    virtual iJoint* object() = 0;
    // Delete(): now, or at the end of the current scene update (the step may still hold it).
    void destroy();
    static void deleteDeferred(); // the scene's update ended

    // --- the solver's side ---
    int slotA = -1, slotB = -1; // the two bodies among the solver's (the world's slot for none)
    // At the step's start (the bodies at their starting poses): the frames in the solver bodies' root frames.
    void enter(int a, int b);
    // The rows at the bodies' poses now: directions, arms, effective masses and errors (each kind's). Once at
    // the step's start and after each sub-step's move: the relax, the next warm start, velocity pass and push
    // out all see the same poses.
    virtual void prepare(const SolverBody& a, const SolverBody& b, Real h) = 0;
    // The accumulated impulses again, along the prepared rows (none for a kind that does not warm-start).
    void warmStart(SolverBody& a, SolverBody& b);
    // One sweep: the orientation block, the rows in order, the point block (what matters most ends exact: a
    // slider's rows across its axis after its orientation, whose lever arms reach its far anchor);
    // the push out corrects the errors at soft.biasRate (JointRows.h).
    virtual void solve(SolverBody& a, SolverBody& b, Real h, JointPass pass, const JointSoftness& soft);
    void save();
    void restore();
    // The most the two anchors can be apart while the joint holds: 0 when it keeps them together (ball,
    // hinge, fixed), a distance joint's maximum, infinite when they may slide or stretch apart (slider,
    // spring). What a tether adds up along a chain (JointTethers.cpp).
    virtual Real reach() const;
    // This step's frames, in the solver bodies' root frames.
    const JointFrame& frameA() const { return m_frameA; }
    const JointFrame& frameB() const { return m_frameB; }
    // The current poses of the two frames, world, from RBDynamics (the getters: angle, length, ...; the
    // continuous stage's closing of joints).
    void worldFrames(JointFrame& a, JointFrame& b) const;
    // An impulse on its bodies that a tether took over from it this sub-step (+ on b, - on a): its reaction,
    // and what breaks it, include it.
    void carry(const Vec3& impulse) { m_carried += impulse; }
    // After the step: the reaction of the last sub-step of length h; true when it broke now.
    bool finish(Real h);
    // What the next step reads of the last (snapshots): the impulses it warm-starts from, whether it broke.
    struct State {
        PointBlock point;
        OrientationBlock orientation;
        JointRow rows[kMaxRows];
        bool broken;
        Vec3 force, torque;
    };
    State state() const;
    void setState(const State& s);
    void resetImpulses(); // as a new joint: nothing to warm-start from

    // --- iJoint, shared by every kind (JointObject forwards) ---
    iRigidBody* publicBodyA() const;
    iRigidBody* publicBodyB() const;
    Vector localAnchorA() const { return toVector(m_localA.point); }
    Vector localAnchorB() const { return toVector(m_localB.point); }
    bool setBreakForce(float newtons);
    bool setBreakTorque(float newtonMetres);
    bool broken() const { return m_broken; }
    iJointListener* listener = nullptr;
    Vector reactionForce() const { return toVector(m_force); }
    Vector reactionTorque() const { return toVector(m_torque); }

protected:
    void wakeBodies(); // its going, and its setters' changes, wake both bodies
    // A setter's write: a value that differs wakes both bodies (asleep, they would never feel a motor turned
    // on, a spring shortened, a limit moved); the same value again wakes nothing, so a game may set it every
    // frame and the bodies still sleep.
    template <class Field, class Value> void change(Field& field, Value value) {
        if (field == Field(value)) return;
        field = Field(value);
        wakeBodies();
    }
    // The rows a kind uses: warm started, saved, restored and summed into the reaction generically.
    bool m_usesPoint = false, m_usesOrientation = false;
    bool m_warmStarts = true; // a spring is a force: its impulse is worked out afresh each sub-step
    PointBlock m_point;
    OrientationBlock m_orientation;
    Vec3 m_pointError = Vec3::Zero(), m_rotationError = Vec3::Zero(); // C of the blocks, as prepared
    // Where the linear rows (the point block's, a slider's) act, from the anchors (zero: at them). The
    // reaction torque is reported about the anchors all the same: finish() moves it there.
    Vec3 m_pointShift = Vec3::Zero();
    // The point block's arms and mass at the frames' world points now.
    void preparePoint(const SolverBody& a, const SolverBody& b);
    JointRow m_rows[kMaxRows];
    int m_rowCount = 0;
    // Frames in each body's own frame (relative to its frame's origin; the world's in world coordinates),
    // and this step's, in the solver bodies' root frames (JointRows.h).
    JointFrame m_localA, m_localB, m_frameA, m_frameB;
    Real anchorDistance() const; // between the two anchors now (distance joints, springs)

private:
    JointFrame rootFrame(const RigidBody* body, const JointFrame& local) const;
    JointType m_type;
    RigidBody *m_a, *m_b;
    bool m_broken = false, m_letGo = false, m_deleted = false;
    float m_breakForce = std::numeric_limits<float>::infinity();
    float m_breakTorque = std::numeric_limits<float>::infinity();
    Vec3 m_force = Vec3::Zero(), m_torque = Vec3::Zero();
    Vec3 m_carried = Vec3::Zero();
};

// The iJoint methods every kind shares, forwarded to Joint.
template <class Interface> class JointObject : public Interface, public Joint, public iUserPointer {
public:
    using Joint::Joint;
    iJoint* object() override { return this; }
    JointType getType() const override { return type(); }
    iRigidBody* getBodyA() const override { return publicBodyA(); }
    iRigidBody* getBodyB() const override { return publicBodyB(); }
    Vector getLocalAnchorA() const override { return localAnchorA(); }
    Vector getLocalAnchorB() const override { return localAnchorB(); }
    bool isActive() const override { return acting(); }
    void setCollideConnected(bool collide) override { change(collideConnected, collide); }
    bool getCollideConnected() const override { return collideConnected; }
    bool setBreakForce(float newtons) override { return Joint::setBreakForce(newtons); }
    bool setBreakTorque(float newtonMetres) override { return Joint::setBreakTorque(newtonMetres); }
    bool isBroken() const override { return broken(); }
    void setListener(iJointListener* l) override { listener = l; }
    Vector getReactionForce() const override { return reactionForce(); }
    Vector getReactionTorque() const override { return reactionTorque(); }
    void Delete() const override { const_cast<JointObject*>(this)->destroy(); }
    void setUserPointer(void* p) override { m_user = p; }
    void* getUserPointer() const override { return m_user; }

private:
    void* m_user = nullptr;
};

// What every factory checks and works out: a (a simulator body), b (nullptr or another), the anchor and axis
// finite. Returns false (with error(), naming the factory) on bad input; else the frames in each body's frame
// of a joint frame at the world point anchor whose x axis is axis.
bool jointFrames(const wchar_t* factory, iRigidBody* a, iRigidBody* b, const Vector& anchorA,
                 const Vector& anchorB, const Vector& axis, RigidBody*& bodyA, RigidBody*& bodyB,
                 JointFrame& localA, JointFrame& localB);

} // namespace physics
