// iUserPointer.h - one pointer of the game's own on an engine object, so that a callback handed a body or a
// geometry finds the game's object (seed 000's post mortem: an "owner" on every physics object).
//
// The engine never reads, frees or copies it (a clone starts with none). Bodies made by CreateRigidBody and
// CreatePhysicsFrame and geometries made by the Create* geometry factories implement it, reached with
// userPointerOf(object); nullptr for an object of the game's own making.
#pragma once

class iUserPointer {
public:
    virtual void setUserPointer(void* p) = 0;
    virtual void* getUserPointer() const = 0;

protected:
    ~iUserPointer() = default; // part of an engine object: Delete() the object
};

// A cross-cast from any of the engine's polymorphic interfaces (iRigidBody, iCollisionGeometry, ...).
template <class Object> iUserPointer* userPointerOf(Object* object) {
    return dynamic_cast<iUserPointer*>(object);
}
template <class Object> const iUserPointer* userPointerOf(const Object* object) {
    return dynamic_cast<const iUserPointer*>(object);
}
