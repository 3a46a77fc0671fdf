// FrameDriver.cpp - moving a frame with the course framework's iFrame members only.
#include "FrameDriver.h"

#include "iFrame.h"

namespace physics {

void setFrameWorldPose(iFrame* frame, const Matrix& rotation, const Vector& origin) {
    // With T's rotation set to the identity, the frame's world rotation is its parent's (P).
    const Matrix identity(1);
    frame->orient(identity);
    Matrix parent = frame->rotation();
    if (parent == identity) { // a root frame (most): R_T is the rotation, d the origin's change
        frame->orient(rotation);
        const Vector d = origin - frame->position();
        frame->translate(d.x, d.y, d.z);
        return;
    }
    Matrix parentInverse = parent.transpose(); // a rotation's inverse
    // world rotation = R_T * P, so R_T = rotation * P^T.
    frame->orient(rotation * parentInverse);
    // translate(d) adds d to T's translation, which moves the world origin by d * P.
    Vector d = parentInverse.direction(origin - frame->position());
    frame->translate(d.x, d.y, d.z);
}

Matrix frameWorldRotation(const iFrame* frame) {
    Matrix r = orthoNormalize(frame->world());
    r.m41 = r.m42 = r.m43 = 0.0f;
    return r;
}

} // namespace physics
