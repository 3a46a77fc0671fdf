// Frame.cpp - the test host's reference frame: world pose by walking the parent chain.
#include "Frame.h"
#include "MathDefinitions.h"

Frame::Frame() : T(1), parent(0) {}

Vector Frame::position() const {
    return parent ? T.position() * parent->rotation() + parent->position() : T.position();
}

Matrix Frame::rotation() const { return parent ? T.rotation() * parent->rotation() : T.rotation(); }

Vector Frame::orientation(char axis) const {
    Vector v(axis == 'x' ? 1.0f : 0.0f, axis == 'y' ? 1.0f : 0.0f, axis == 'z' ? 1.0f : 0.0f);
    return v * rotation();
}

Matrix Frame::world() const {
    Matrix w = parent ? T * parent->world() : T;
    w.m43 *= MODEL_Z_AXIS;
    return w;
}

// Keeps the world pose: the transform is re-expressed relative to the new parent.
void Frame::attachTo(iFrame* newParent) {
    if (parent) T = world();
    parent = newParent;
    if (parent) {
        Matrix inv = parent->rotation().transpose();
        Vector p = (T.position() - parent->position()) * inv;
        T = T.rotation() * inv;
        T.m41 = p.x, T.m42 = p.y, T.m43 = p.z;
    }
}
