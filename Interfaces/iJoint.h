// iJoint.h - what every joint has: the two bodies it joins, whether they still collide, breaking, the
// reaction it exerts, and Delete(). The kinds are iBallJoint, iHingeJoint, iSliderJoint, iFixedJoint,
// iDistanceJoint and iSpring, each made by its own Create* factory.
//
// A joint joins body A (never nullptr) to body B, or to the world when B is nullptr. Anchors and axes are
// given in world coordinates at creation, at the bodies' poses then, and kept in each body's own frame (the
// world's: world coordinates); getLocalAnchorA/B read them back. Only bodies made by CreateRigidBody or
// CreatePhysicsFrame can be joined.
//
// The scene that simulates body A solves the joint, in the same solver and sub-steps as the contacts
// (warm-started), while B is the world or a body of the same scene; otherwise the joint waits. Bodies a
// joint joins do not collide with each other unless setCollideConnected(true); they sleep and wake together.
// When either body is killed (iLifetime) or deleted, the joint lets go of it (seed 000's spring): it stops
// acting for good, getBodyA/B return nullptr for that body, and the game makes a new joint to join again.
// A joint's Delete() during a scene update (from a listener, updater or generator) takes effect at once for
// the simulation; the object is freed when the update ends.
#pragma once

#include "iRigidBody.h"

enum JointType { JOINT_Ball, JOINT_Hinge, JOINT_Slider, JOINT_Fixed, JOINT_Distance, JOINT_Spring };

class iJoint;

// Told when a joint breaks (setBreakForce), at the end of the step that broke it; it may Delete() the joint.
class iJointListener {
public:
    virtual void jointBroken(iJoint* joint) = 0;

protected:
    ~iJointListener() = default; // the game's object: the engine never deletes it
};

class iJoint {
public:
    virtual JointType getType() const = 0;
    virtual iRigidBody* getBodyA() const = 0;
    virtual iRigidBody* getBodyB() const = 0;   // nullptr: the world, or a body the joint let go of
    virtual Vector getLocalAnchorA() const = 0; // in A's frame
    virtual Vector getLocalAnchorB() const = 0; // in B's frame (world coordinates for the world)
    // Acting: not broken, and neither body let go of.
    virtual bool isActive() const = 0;
    // Whether the two bodies still collide with each other (default false).
    virtual void setCollideConnected(bool collide) = 0;
    virtual bool getCollideConnected() const = 0;
    // The joint breaks when its reaction force exceeds newtons, or its reaction torque newton-metres (both
    // default infinite: never). Not positive, or NaN: refused with error() and false.
    virtual bool setBreakForce(float newtons) = 0;
    virtual bool setBreakTorque(float newtonMetres) = 0;
    virtual bool isBroken() const = 0;
    virtual void setListener(iJointListener* listener) = 0; // nullptr: none
    // What the joint did to body B in the last step's last sub-step, world axes: the force at B's anchor (N)
    // and the torque of its angular rows (N m); A received the opposite.
    virtual Vector getReactionForce() const = 0;
    virtual Vector getReactionTorque() const = 0;
    virtual void Delete() const = 0;

protected:
    virtual ~iJoint() = default; // Delete() it
};
