// iSoftBody.h - a soft body (seed 000's SoftBody): a grid of small bodies joined by springs, built from a 2D
// mask of which grid places hold a body (the post mortem's "other shapes"): cloth, a jelly blob.
//
// Each pair of neighbours along a row or column gets a structural spring, each diagonal pair a shear
// spring, and each pair two places apart along a row or column a bend spring, all at their distance at
// creation. The bodies have no collision geometry: the game gives them their shapes (a sim-only package has
// no collision module), e.g. a CreateCSphere per body. Tightness and damping apply to every spring.
// Delete() deletes the springs and the bodies it made (in a step, at its end, as Delete() of each does). A
// body deleted by someone else (its scene's Delete(), or the game's) reads as nullptr and is not deleted
// again.
#pragma once

#include "iRigidBody.h"

class iPhysicsScene;
class iSpring;

class iSoftBody {
public:
    virtual int getColumns() const = 0;
    virtual int getRows() const = 0;
    virtual int getBodyCount() const = 0;
    virtual iRigidBody* getBody(int i) const = 0; // 0 <= i < getBodyCount(), row by row; nullptr otherwise
    virtual iRigidBody* getBodyAt(int column, int row) const = 0; // nullptr where the mask is false
    virtual int getSpringCount() const = 0;
    virtual iSpring* getSpring(int i) const = 0;
    // Every spring's stiffness (N per length unit) and damping (N s per length unit); refused like iSpring.
    virtual bool setTightness(float k) = 0;
    virtual bool setDamping(float c) = 0;
    // Adds every body to scene (false if any was refused); kills every body (iLifetime: they leave their
    // scene at the end of its step, and the springs let go).
    virtual bool addToScene(iPhysicsScene* scene) = 0;
    virtual void killAll() = 0;
    virtual void Delete() const = 0;

protected:
    virtual ~iSoftBody() = default; // Delete() it
};

// mask[row * columns + column] says whether that grid place holds a body; the place (column, row) is at
// corner + column * columnStep + row * rowStep (world). Each body has bodyMass kg (the inertia of a solid
// sphere of radius half the smaller step). The bodies are in no scene yet (addToScene). nullptr on bad input
// (no mask, no body, non-finite or degenerate steps, mass <= 0, negative k or c), with error().
extern "C" iSoftBody* CreateSoftBody(const bool* mask, int columns, int rows, const Vector& corner,
                                     const Vector& columnStep, const Vector& rowStep, float bodyMass,
                                     float stiffness, float damping);
