// iFixedJoint.h - a weld: B keeps the pose relative to A it had at creation (a breakable wall's bricks, a
// part knocked off when the joint breaks).
#pragma once

#include "iJoint.h"

class iFixedJoint : public iJoint {
protected:
    ~iFixedJoint() override = default;
};

// a welded to b (nullptr: the world) at their poses now; anchor (world) is where the reaction acts.
// nullptr on bad input, with error().
extern "C" iFixedJoint* CreateFixedJoint(iRigidBody* a, iRigidBody* b, const Vector& anchor);
