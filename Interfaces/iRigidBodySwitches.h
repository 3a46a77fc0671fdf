// iRigidBodySwitches.h - per-body switches for what one body can leave out: rotation, gravity, continuous
// collision, sleeping.
//
// Not part of the seed's iRigidBody (games implement that one); the simulator's bodies provide it, reached
// with switchesOf(body) (nullptr for a game's own body class). Switches are configuration, not state: a
// snapshot neither saves nor restores them; a clone() copies them.
#pragma once

#include "iRigidBody.h"

class iRigidBodySwitches {
public:
    // Locked (default off): the body never turns, as if its inertia were infinite. Contacts, torques, force
    // generators and off-centre impulses only push it (an impulse J still gives it J / m); an angular
    // velocity the game writes is dropped at the next step. Its inertia tensor is left as it is (still
    // derived from shape and mass, or the game's), so unlocking gives back the body it was. A composite with
    // a locked part does not turn. The same as a zero inverse inertia tensor
    // (RBDynamics::setInverseInertiaTensor), minus the loss of the tensor.
    virtual void setRotationLocked(bool locked) = 0;
    virtual bool isRotationLocked() const = 0;
    // Gravity on this body, times the scene's (default 1; 0: none, -1: falls up). Non-finite refused with
    // error() and false. Only the root of an attachment chain counts (its physicsType governs the chain).
    virtual bool setGravityScale(float scale) = 0;
    virtual float getGravityScale() const = 0;
    // Continuous collision for this body (default on; the scene's switch, when off, wins): off, a fast body
    // may pass through thin things, and the step sweeps nothing for it.
    virtual void setContinuousCollisionEnabled(bool on) = 0;
    virtual bool getContinuousCollisionEnabled() const = 0;
    // Whether the body may fall asleep (default true). False keeps it, and any island it touches, awake.
    virtual void setSleepAllowed(bool allowed) = 0;
    virtual bool getSleepAllowed() const = 0;

protected:
    ~iRigidBodySwitches() = default; // part of a body: Delete() the body
};

inline iRigidBodySwitches* switchesOf(iRigidBody* body) { return dynamic_cast<iRigidBodySwitches*>(body); }
inline const iRigidBodySwitches* switchesOf(const iRigidBody* body) {
    return dynamic_cast<const iRigidBodySwitches*>(body);
}
