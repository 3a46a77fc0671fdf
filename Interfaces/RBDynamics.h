// RBDynamics.h - the physical state of one rigid body, as the seed documents it, and PhysicsType.
//
// A plain struct whose public properties a game edits directly (body->getDynamics().velocity += ...). The
// simulator reads and writes it every step; a collision space only reads it. Both packages need it, so it
// lives here; its functions are in RBDynamics.cpp.
//
// Frames: an unattached body's position, orientation, velocities and momentum are in world space. A body
// attached to another (attachTo) stores position and orientation relative to its parent's centre of mass
// and orientation, and moves rigidly with the root of its chain; use getWorldPosition/getWorldOrientation.
// A chain is one composite body: the root's velocity is that of the root's own centre of mass, its
// angularVelocity is the composite's, and its angularMomentum is the composite's about the composite centre
// of mass (L = I_composite w). An attached body's own velocity and angular fields are not used while it is
// attached; its force, torque, temporal force/torque, acceleration (times its mass) and drag act on the
// composite at its own centre of mass. The root's physicsType governs the whole composite.
//
// Validation: the simulator checks every body at the start of a step and after integrating it. A body whose
// state has become invalid (NaN or Inf anywhere, mass <= 0 or NaN, negative drag, a scaled, sheared or
// reflected orientation, a non-positive-definite inertia tensor, restitution outside [0, 1], negative
// friction) is reported with error() and restored to its last valid state; the scene goes on. An orientation
// within 1e-2 of a rotation (the drift of composing many float rotations) is not an error: it is cleaned with
// orthoNormalize. Anything further from a rotation (a scale of 2, say) is refused: the simulator never
// guesses which part of a scaled matrix you meant.
#pragma once

#include "MathDeclarations.h"
#include "PhysicsConstants.h"

#include <cstddef>
#include <vector>

enum PhysicsType : int { // a fixed type: any int is a value, so a bad one is refused, not undefined
    PHYS_Falling,        // moves under forces and gravity (the default)
    PHYS_Floating,       // moves under forces, feels no gravity
    PHYS_FixedInSpace,   // never moves; collisions between two fixed bodies are never tested
};

// True when the 3x3 block of i is finite, symmetric and positive definite: a valid inertia tensor (or
// inverse tensor).
bool isValidInertiaTensor(const Matrix& i);
// True when the 3x3 block of an inverse tensor is zero: infinite inertia, rotation locked (allowed).
bool isRotationLock(const Matrix& inverse);

// The mass distribution of a uniform solid, per kilogram: its volume (m^3), its centroid and its inertia per
// kilogram about that centroid (3x3 in the upper-left), both in body-local axes relative to the body frame's
// origin. A collision geometry describes itself with one to RBDynamics::setShapeMass.
struct ShapeMass {
    float volume = 0.0f;
    Vector centroid;
    Matrix unitInertia; // kg m^2 per kg
};
// A solid sphere of radius r (unitInertia 2/5 r^2) and a solid box of half extents h turned by rotation
// (row-vector, box local -> body local), centred on centre.
ShapeMass sphereShapeMass(float r, const Vector& centre = Vector());
ShapeMass boxShapeMass(const Vector& h, const Vector& centre = Vector(), const Matrix& rotation = Matrix(1));
// Several solids as one of uniform density: volumes add, the centroid is the volume-weighted mean, and each
// part's inertia is weighted by its volume share and moved to that centroid by the parallel-axis theorem.
// Parts with no volume are skipped; overlapping parts count twice. No part: a zero ShapeMass.
ShapeMass combineShapeMass(const ShapeMass* parts, size_t n);

struct RBDynamics {
    // --- properties (seed names and meanings) ---
    // The pose first, with what a collision space and every pass of a step read of each body (mass, type,
    // sleeping, teleports, the attachment links): 128 bytes, two or three cache lines, where the seed's
    // order of declaration spread them over five.
    Vector position;                // current position of the centre of mass (m)
    Vector com;                     // centre-of-mass offset from the body frame's origin, in body-local axes
    Matrix orientation = Matrix(1); // rotation (body local -> world), orthonormal, never scaled
    // mass: kg, > 0. INFINITE_MASS makes the body kinematic: forces, torques, gravity, drag and impulses do
    // not change its motion, but it still moves and turns with the velocity and angular velocity you give it
    // (a composite with an infinite part turns about its root's centre of mass).
    float mass = 1.0f;
    PhysicsType physicsType = PHYS_Falling;
    // Set by the simulator while the body sleeps (at rest, neither integrated nor solved); a game reads it.
    // Give the body a velocity, a force or a torque, or move it, and it wakes. A collision space skips pairs
    // of bodies that are each sleeping or fixed, so a resting pile costs next to nothing. Not copied by
    // operator= (it is the simulator's state, not a property).
    bool sleeping = false;
    // Teleports: how many times the body was put somewhere rather than moved there (a respawn). A collision
    // space never sweeps a body across a teleport, so nothing between the old and the new place is hit or
    // hears HitWall. The simulator counts every write of position or orientation (or a moved frame) itself;
    // a game's own iRigidBody (the collision-only route) calls markTeleported() when it jumps. Not copied by
    // operator= (it is the body's history, not a property).
    unsigned teleports = 0;
    void markTeleported() { ++teleports; }

private:
    // The attachment links beside the pose: every pass of a step and every space call asks each body for its
    // root (attachmentRoot, attachedTo).
    RBDynamics* m_parent = nullptr;
    RBDynamics* m_firstChild = nullptr;
    RBDynamics* m_nextSibling = nullptr;

public:
    // The motion, then what drives it.
    Vector velocity;        // current velocity of the centre of mass (m/s)
    Vector angularVelocity; // rad/s, world axes
    Vector angularMomentum; // about the COM, world axes (kg m^2/s)
    Vector lastVelocity;    // velocity before the last step: helps detect velocity spikes
    Vector acceleration;    // additive acceleration of the COM (m/s^2), on top of gravity
    Vector force;           // constant force on the COM (N), applied every step
    Vector temporalForce;   // force applied for the next step only, then reset to zero
    // Linear acceleration = gravity (PHYS_Falling only) + acceleration + (force + temporalForce) / mass +
    // drag / mass.
    // Quadratic drag F = -1/2 rho Cd A |v| v through the COM, with air density rho = 1.2 kg/m^3 and the
    // reference area A = pi r^2 of the sphere with the body's volume (its collision geometry's solid; a body
    // with none is the sphere of radius 1 its inertia assumes: A = pi), so drag follows the body's size and
    // this is a true Cd (a sphere's 0.47). Terminal speed: sqrt(2 m g / (rho Cd A)). >= 0.
    float dragCoefficient = 0.0f;
    // Angular drag (1/s): the spin's angular momentum decays as e^(-angularDrag t), a torque -angularDrag L
    // taken exactly over each step (stable at any value). 0: none; >= 0. On an attachment chain the root's
    // value acts on the whole composite.
    float angularDrag = 0.0f;
    float restitution = 0.5f; // 1 superball (keeps all energy), 0 clay (keeps none); outside [0, 1]: refused
    float friction = 0.25f;   // a contact's coefficient is the sum of both bodies' values (seed rule); >= 0
    Vector torque;            // constant torque about the COM (N m), world axes, applied every step
    Vector temporalTorque;    // torque for the next step only, then reset to zero
    // dL/dt = torque + temporalTorque; w = I_world^-1 L with I_world^-1 = R^T I^-1 R (row vectors), so the
    // gyroscopic term w x (I w) comes with it.
    // Angular velocity and momentum are two views of one state (L = I_world w). Write either: before each
    // step the simulator takes whichever one you changed since its last step (angular velocity wins if both
    // changed) and recomputes the other.

    RBDynamics();
    // Copies the physical state. Attachment links are not copied: a copy starts unattached, and assigning
    // to a body keeps that body's own place in its attachment chain.
    RBDynamics(const RBDynamics& src);
    RBDynamics& operator=(const RBDynamics& src);
    // Detaches from the parent and releases any attached children (they keep their world pose).
    ~RBDynamics();

    // --- functions ---
    // REMOVED IN NEXT UPDATE in the seed; kept for ported code: the same as getWorldPosition().
    Vector getWorldCOM() const;
    // Velocity of a world point moving with this body (or with the composite it belongs to): v + w x (p - c).
    Vector getVelocityAtWorldPoint(const Vector& p) const;
    // Set either tensor (3x3 in the upper-left, body-local axes about the COM); the other is kept consistent.
    // A tensor that is not finite, symmetric and positive definite, or whose inverse is not as a float, is
    // refused with error() and nothing changes (1e30 kg m^2 has the inverse 1e-30 and is accepted; 1e-39, a
    // denormal, has an inverse of 1e39 beyond the float range). Inverses are taken in double, so a 1 km rock
    // (2.5e17 kg m^2) is accepted. A zero inverse tensor locks rotation (infinite inertia; the inertia tensor
    // then reads zero): the body, and any composite it is part of, never turns, and an impulse or contact
    // only pushes it. A tensor set here (or written through the getInertiaTensor() references) is the
    // game's: it is kept as set whatever mass or geometry the body is given later, until useShapeInertia().
    //
    // Until then the tensor follows shape and mass: mass times the inertia per kilogram of the body's shape
    // about its centre of mass. The shape is every collision geometry bound to the body together (spheres,
    // boxes, compounds; a plane adds nothing), as one solid of uniform density (combineShapeMass); a body
    // with no geometry is a solid sphere of radius 1 m centred on its COM (2/5 mass kg m^2). When the
    // shape's centroid is not at com, the tensor is about com all the same: the parallel-axis term
    // mass (|d|^2 1 - d d^T), d = centroid - com, is added. A geometry updates it at once when it is bound,
    // resized or given children; the simulator brings it up to date with mass and com at the start of each
    // step (call updateInertia() to see it sooner). The simulator keeps the angular velocity when a tensor
    // changes (the momentum follows). With INFINITE_MASS (or an invalid mass) the tensor is left as it was:
    // such a body is immovable, its inverse inertia counts as zero in every solve. A copy carries its
    // source's shape until a geometry is bound to it.
    void setInverseInertiaTensor(const Matrix& i);
    void setInertiaTensor(const Matrix& i);
    Matrix& getInertiaTensor();
    Matrix& getInverseInertiaTensor();
    const Matrix& getInertiaTensor() const;
    const Matrix& getInverseInertiaTensor() const;
    // Brings a derived tensor up to date with mass, com and shape; true if it changed. Does nothing to a
    // tensor the game set (and notices one written through the references).
    bool updateInertia();
    bool isInertiaSetByGame() const { return m_inertiaFromGame; }
    // Hands the tensor back to the engine: derived from shape and mass again, from now on.
    void useShapeInertia();
    // For collision geometries: owner (any unique address) contributes shape s to this body, replacing its
    // previous contribution; a shape with no volume (or removeShapeMass) withdraws it.
    void setShapeMass(const void* owner, const ShapeMass& s);
    void removeShapeMass(const void* owner);
    // The body's shape as it stands (volume 0: none, the 1 m sphere is used).
    const ShapeMass& getShapeMass() const { return m_shape; }
    // Instantly changes linear and angular velocity (and momentum) by an impulse (N s) applied at a world
    // point. On an attached body it acts on the whole composite. Non-finite input is refused with error().
    void ApplyImpulse(const Vector& impulse, const Vector& pointOfApplication);
    // A force (N) at a world point, for the next step only: adds it to temporalForce and its moment about
    // this body's centre of mass, (point - getWorldPosition()) x force, to temporalTorque. On an attached
    // body the composite feels the moment about its own centre of mass, as a force through that point would
    // give. Call it before each step it should act in (a fixed updater), or set force/torque for a lasting
    // one. Non-finite input is refused with error().
    void ApplyForce(const Vector& force, const Vector& pointOfApplication);

    // --- attachment chains ("coming in next update" in the seed) ---
    // Attaches this body to p, keeping its world pose; nullptr detaches (the body keeps the world velocity it
    // had as part of the composite). Attaching to itself or a descendant is refused with error().
    void attachTo(RBDynamics* p);
    RBDynamics* attachedTo() const { return m_parent; }
    RBDynamics* attachmentRoot() const { // (inline: spaces and the scene ask it of every body every step)
        const RBDynamics* r = this;
        while (r->m_parent) r = r->m_parent;
        return const_cast<RBDynamics*>(r);
    }
    // A count of the attachments and detachments of every body so far (in any thread): while it stays the
    // same, every body's attachmentRoot() is what it was, so a cache of them holds (the collision space
    // knows a body's root without reading its links).
    static unsigned long long attachmentEpoch();
    // The seed: the mass of the body at the root of the attachment chain (its own mass when unattached).
    float getMass() const;
    // Mass of the whole composite rooted at attachmentRoot() (INFINITE_MASS if any part is infinite).
    float getCompositeMass() const;
    // Mass, centre of mass and inertia (world axes, about that centre) of the composite rooted at
    // attachmentRoot(), by the parallel-axis theorem. For an unattached body: its own mass, position and
    // world tensor. inverseInertia is zero when the mass is infinite (nothing can turn it).
    struct MassProperties {
        float mass;
        Vector centre;
        Matrix inertia;
        Matrix inverseInertia;
    };
    MassProperties getCompositeMassProperties() const;
    Vector getWorldPosition() const;    // world position of this body's COM
    Matrix getWorldOrientation() const; // world orientation of this body
    // The body frame's origin in world space: getWorldPosition() - com * getWorldOrientation().
    Vector getWorldOrigin() const;
    // The inverse inertia tensor in world axes, R^T I^-1 R in row-vector form (this body alone).
    Matrix getWorldInverseInertiaTensor() const;

    // The first child and the next sibling in the attachment tree (for walking a composite).
    RBDynamics* firstAttached() const { return m_firstChild; }
    RBDynamics* nextAttached() const { return m_nextSibling; }

private:
    Matrix m_inertia;        // body-local, about the COM
    Matrix m_inverseInertia; // its inverse
    // Inertia from shape and mass. Not copied by operator=: the geometries bound to this body (m_shapeParts).
    // Copied: the combined shape (unless the target has geometries of its own), the flag and the tensors.
    struct ShapePart {
        const void* owner;
        ShapeMass shape;
    };
    std::vector<ShapePart> m_shapeParts;
    ShapeMass m_shape;                         // their combination (volume 0: none)
    bool m_inertiaFromGame = false;            // set by setInertiaTensor & co: never derived again
    bool m_shapeDirty = true;                  // shape changed since the last derivation
    float m_derivedMass = 0.0f;                // mass and com of the last derivation
    Vector m_derivedCom;                       //
    Matrix m_derivedInertia, m_derivedInverse; // what it wrote (a difference is a write through a reference)

    void unlinkFromParent();
    void combineShapeParts();
};
